#!/usr/bin/env bash
# `kmr hull --svg`: the picture is well-formed XML; its vertex markers are exactly the printed hull
# vertices and its grey points exactly the other input points (index and coordinates, read back
# against the input file); it draws exactly the printed facets, each classed front or back as an
# outward normal recomputed here from the input says (view direction from the picture's data-view);
# seen from the viewer the front faces are all counter-clockwise, the back faces all clockwise, and
# both cover the same area (the silhouette). Bad uses exit 2. The SVG, the JSON and the input are
# read back with Python's own parsers, sharing no code with kmr.
# Usage: hull_picture_test.sh path/to/kmr
set -u
kmr=$1
source "$(dirname "$0")/lib.sh"  # $tmp, ok, bad, expect_error, finish
python3 -c "
import random; random.seed(12)
for i in range(80): print(*(random.gauss(0, 1) for _ in range(3)))" >"$tmp/ball.xyz"
# a cube with points inside, on faces and edges, and a duplicate corner (coplanar facets)
printf '0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n0.5 0.5 0.5\n0.5 0.5 0\n0.5 0 0\n0.2 0.3 1\n1 1 1\n0.1 0.9 0.4\n0 0.5 0.5\n' >"$tmp/cube.xyz"
printf '0 0 0\n1e-9 0 0\n0 1e-9 0\n0 0 1e-9\n' >"$tmp/tiny.xyz"
check() {  # name, input
  local name=$1
  "$kmr" hull "$2" --svg "$tmp/p.svg" >"$tmp/out" 2>"$tmp/err" || { bad "$name: rc=$? $(cat "$tmp/err")"; return; }
  xmllint --noout "$tmp/p.svg" && ok || bad "$name: not well-formed"
  python3 - "$2" "$tmp/out" "$tmp/p.svg" <<'PY' && ok || bad "$name: picture differs from stdout"
import json, sys, xml.etree.ElementTree as ET
pts = [tuple(map(float, l.split("#")[0].split())) for l in open(sys.argv[1]) if l.split("#")[0].split()]
out = json.load(open(sys.argv[2]))
ns = "{http://www.w3.org/2000/svg}"
root = ET.parse(sys.argv[3]).getroot()
def marks(cls):
    return sorted((int(c.get("data-index")), float(c.get("data-x")), float(c.get("data-y")), float(c.get("data-z")))
                  for c in root.iter(ns + "circle") if c.get("class") == cls)
want_v = [(i,) + pts[i] for i in out["vertices"]]
if marks("vertex") != want_v: sys.exit(f"vertex markers: {len(marks('vertex'))} drawn, {len(want_v)} printed, or not the same")
want_p = [(i,) + pts[i] for i in range(len(pts)) if i not in set(out["vertices"])]
if marks("point") != want_p: sys.exit(f"point markers: {len(marks('point'))} drawn, {len(want_p)} other points")
view = [float(x) for x in next(g for g in root.iter(ns + "g") if g.get("data-view")).get("data-view").split()]
faces = [p for p in root.iter(ns + "polygon") if p.get("class") in ("front", "back")]
if sorted(list(map(int, p.get("data-facet").split())) for p in faces) != out["facets"]:
    sys.exit(f"facets: {len(faces)} drawn, {len(out['facets'])} printed, or not the same")
area = {"front": 0.0, "back": 0.0}
for p in faces:
    a, b, c = (pts[i] for i in map(int, p.get("data-facet").split()))
    u, v = [b[k] - a[k] for k in range(3)], [c[k] - a[k] for k in range(3)]
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    s = sum(n[k] * view[k] for k in range(3)) / sum(x * x for x in n) ** 0.5 / sum(x * x for x in view) ** 0.5
    if abs(s) > 1e-6 and (s > 0) != (p.get("class") == "front"): sys.exit(f"facet {p.get('data-facet')} drawn {p.get('class')}")
    q = [tuple(map(float, t.split(","))) for t in p.get("points").split()]
    sa = sum(q[i][0] * q[(i + 1) % 3][1] - q[(i + 1) % 3][0] * q[i][1] for i in range(3)) / 2  # y down: ccw < 0
    if abs(sa) > 0.5 and (sa < 0) != (p.get("class") == "front"): sys.exit(f"facet {p.get('data-facet')}: screen area {sa}, {p.get('class')}")
    area[p.get("class")] += abs(sa)
if abs(area["front"] - area["back"]) > 1e-3 * max(area.values()) + 1: sys.exit(f"front faces cover {area['front']}, back faces {area['back']}")
PY
}
check ball "$tmp/ball.xyz"
check cube "$tmp/cube.xyz"
check tiny "$tmp/tiny.xyz"
"$kmr" hull "$tmp/cube.xyz" --svg /proc/nonexistent/x.svg >"$tmp/out" 2>"$tmp/err"
[ $? -eq 2 ] && [ ! -s "$tmp/out" ] && grep -q "cannot write --svg file" "$tmp/err" && ok || bad "unwritable --svg: $(cat "$tmp/err")"
finish "hull_picture_test"
