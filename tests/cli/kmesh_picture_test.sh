#!/usr/bin/env bash
# `kmr kmesh --svg`: the picture is well-formed XML; its markers are exactly the vertices printed on
# stdout (index, kind, coordinates); it draws exactly the printed triangles, each at the pixel
# positions of its three vertex markers. Bad uses exit 2. The SVG and the JSON are read back with
# Python's own parsers (xml.etree, json), sharing no code with kmr.
# Usage: kmesh_picture_test.sh path/to/kmr
set -u
kmr=$1
source "$(dirname "$0")/lib.sh"  # $tmp, ok, bad, expect_error, finish
printf '0 0\n1000 0\n0 1000\n1000 1000\n430 570\n432 571\n250 800\n900 120\n' >"$tmp/spread.txt"
awk 'BEGIN { for (i = 0; i < 4; i++) for (j = 0; j < 4; j++) print i * 100, j * 100 }' >"$tmp/grid.txt"  # cocircular
printf '0 0\n10 0\n20 0\n30 0\n' >"$tmp/line.txt"                                                        # collinear
printf '5 -7\n' >"$tmp/one.txt"
printf '0 0\n3 0 1 0\n' >"$tmp/moving.txt"
check() {  # name, then the kmesh arguments
  local name=$1; shift
  "$kmr" kmesh "$@" --svg "$tmp/p.svg" >"$tmp/out" 2>"$tmp/err" || { bad "$name: rc=$? $(cat "$tmp/err")"; return; }
  xmllint --noout "$tmp/p.svg" && ok || bad "$name: not well-formed"
  python3 - "$tmp/out" "$tmp/p.svg" <<'PY' && ok || bad "$name: picture differs from stdout"
import json, sys, xml.etree.ElementTree as ET
out = json.load(open(sys.argv[1]))
ns = "{http://www.w3.org/2000/svg}"
root = ET.parse(sys.argv[2]).getroot()
marks = [c for c in root.iter(ns + "circle") if c.get("class") in ("input", "steiner")]
got = sorted((int(c.get("data-index")), float(c.get("data-x")), float(c.get("data-y")), int(c.get("class") == "steiner")) for c in marks)
want = [(i, float(v[0]), float(v[1]), v[2]) for i, v in enumerate(out["vertices"])]
if got != want: sys.exit(f"markers: {len(got)} drawn, {len(want)} printed; first difference {next((a, b) for a, b in zip(got + [None] * len(want), want) if a != b)}")
at = {int(c.get("data-index")): (float(c.get("cx")), float(c.get("cy"))) for c in marks}
tris = [p for p in root.iter(ns + "polygon") if p.get("class") == "triangle"]
if [list(map(int, p.get("data-vertices").split())) for p in tris] != out["triangles"]:
    sys.exit(f"triangles: {len(tris)} drawn, {len(out['triangles'])} printed, or not the same")
for p in tris:
    pts = [tuple(map(float, q.split(","))) for q in p.get("points").split()]
    for q, v in zip(pts, map(int, p.get("data-vertices").split())):
        if abs(q[0] - at[v][0]) > 1e-3 or abs(q[1] - at[v][1]) > 1e-3: sys.exit(f"triangle corner {q} is not at vertex {v}'s marker {at[v]}")
PY
}
check spread "$tmp/spread.txt"
check grid "$tmp/grid.txt"
check line "$tmp/line.txt"
check one "$tmp/one.txt"
check moving "$tmp/moving.txt" --until 0.25 --lattice-bits 2
"$kmr" kmesh "$tmp/one.txt" --svg /proc/nonexistent/x.svg >"$tmp/out" 2>"$tmp/err"
[ $? -eq 2 ] && [ ! -s "$tmp/out" ] && grep -q "cannot write --svg file" "$tmp/err" && ok || bad "unwritable --svg: $(cat "$tmp/err")"
finish "kmesh_picture_test"
