#!/usr/bin/env bash
# The options the other CLI tests leave out (issue 13 §2, found by coverage/run.sh), each judged by
# something outside the code it runs: every command's --help against the README's synopsis; the
# counts of `simulate hull --check-every K` and `--integrated` against hand-derived formulas, and its
# final hull against `kmr hull` of the positions at T computed here; `wellspaced --dim 3/4 --stats`
# against the input set and the Steiner count of its own output; `bench sac --json` parsed as JSON;
# `--svg` never unlinks what is not a regular file (a FIFO, /dev/full) when the run fails.
# Usage: options_test.sh path/to/kmr path/to/README.md
set -u
kmr=$1 readme=$2
source "$(dirname "$0")/lib.sh"  # $tmp, ok, bad, expect_error, finish
expect_timeout=120

# --- --help of every command lists every option of its README synopsis; exit 0, nothing on stderr --
help_of() {  # help_of NAME SYNOPSIS_PREFIX CMD...
  local name=$1 prefix=$2; shift 2
  "$kmr" "$@" --help >"$tmp/help" 2>"$tmp/err"; local rc=$?
  local opts; opts=$(grep -F "    build/bin/kmr $prefix " "$readme" | grep -oE -- '--[a-z][a-z-]*' | sort -u)
  [ -n "$opts" ] || { bad "help-$name: no synopsis 'build/bin/kmr $prefix' in README"; return; }
  local missing=""
  for o in $opts; do grep -qF -- "$o" "$tmp/help" || missing="$missing $o"; done
  if [ $rc -eq 0 ] && [ ! -s "$tmp/err" ] && grep -q "^usage: kmr $prefix" "$tmp/help" && [ -z "$missing" ]; then ok; else
    bad "help-$name: rc=$rc, missing options:$missing; stderr: $(head -c 200 "$tmp/err")"; fi
}
help_of audit audit audit
help_of roots roots roots
help_of sort "simulate sort" simulate sort
help_of simulate-hull "simulate hull" simulate hull
help_of wellspaced wellspaced wellspaced
help_of bench "bench sac" bench sac
help_of hull hull hull
help_of kmesh kmesh kmesh
# -h is --help; `kmr` alone prints the usage on stderr and exits 2; `kmr --help` lists every command.
"$kmr" roots -h >"$tmp/h1" 2>/dev/null && "$kmr" roots --help >"$tmp/h2" && cmp -s "$tmp/h1" "$tmp/h2" && ok || bad "roots -h differs from --help"
"$kmr" >"$tmp/out" 2>"$tmp/err"; rc=$?
[ $rc -eq 2 ] && [ ! -s "$tmp/out" ] && grep -q '^usage: kmr' "$tmp/err" && ok || bad "kmr without a command: rc=$rc"
"$kmr" --help >"$tmp/out"
missing=""
for c in audit roots simulate wellspaced hull kmesh bench; do grep -qE "^  $c +[a-z]" "$tmp/out" || missing="$missing $c"; done
[ -z "$missing" ] && ok || bad "kmr --help does not list:$missing"
"$kmr" bench --help >"$tmp/out" && grep -q 'sac' "$tmp/out" && ok || bad "bench --help"
"$kmr" bench >"$tmp/out" 2>"$tmp/err"; rc=$?
[ $rc -eq 2 ] && grep -q '^  sac ' "$tmp/out" && ok || bad "bench without a subcommand: rc=$rc"
expect_error bench-unknown "unknown subcommand 'frob'" -- bench frob

# --- bench sac --json: one JSON row per program asked for, output checked against the static twin --
"$kmr" bench sac --n 40 --edits 2 --program sum --json >"$tmp/b.json" 2>"$tmp/err" && python3 - "$tmp/b.json" <<'PY' && ok || bad "bench sac --json: $(head -c 300 "$tmp/b.json") $(head -c 200 "$tmp/err")"
import json, sys
rows = json.load(open(sys.argv[1]))
assert [r["program"] for r in rows] == ["sum"], rows
assert rows[0]["n"] == 40 and rows[0]["edits"] == 2 and rows[0]["output_ok"] is True, rows
PY

# --- simulate hull: --check-every K, --integrated, --stats ------------------------------------------
cat >"$tmp/mh.txt" <<'EOF'
0 0 0 1 0 0
10 0 1 -1 0 0
0 10 2 0 -1 1
0 0 10 0 1 -1
3 3 3 1 1 1
7 2 5 -1 1 0
EOF
# positions at T = 6, computed here, for the static hull
python3 -c "
import sys
for l in open(sys.argv[1]):
    x, y, z, a, b, c = map(int, l.split()); print(x + 6 * a, y + 6 * b, z + 6 * c)" "$tmp/mh.txt" >"$tmp/mh6.xyz"
"$kmr" hull "$tmp/mh6.xyz" >"$tmp/static.json"
for k in 1 2 5; do
  "$kmr" simulate hull "$tmp/mh.txt" --until 6 --check-every $k --stats "$tmp/s$k.json" >"$tmp/k$k.json" 2>"$tmp/err"; rc=$?
  # checks: once at time 0, then after every K-th of the B batches: 1 + floor(B / K); the hull just
  # before T (no four points coplanar at T = 6) is the static hull of the positions at T.
  python3 - "$tmp/k$k.json" "$tmp/s$k.json" "$tmp/static.json" $k <<'PY' && [ $rc -eq 0 ] && ok || bad "simulate hull --check-every $k: rc=$rc $(head -c 300 "$tmp/k$k.json") $(head -c 200 "$tmp/err")"
import json, sys
out, stats, static, k = json.load(open(sys.argv[1])), json.load(open(sys.argv[2])), json.load(open(sys.argv[3])), int(sys.argv[4])
assert out["batches"] > 0 and out["checks"] == 1 + out["batches"] // k, (out["checks"], out["batches"])
assert stats["checks"] == out["checks"], stats
assert out["vertices"] == static["vertices"] and out["facets"] == static["facets"], (out, static)
assert sum(int(s) * c for s, c in out["batch_sizes"].items()) == out["events"], out
PY
done
# --integrated: after each batch, one motion change per event, each point once: min(n, events) changes.
"$kmr" simulate hull "$tmp/mh.txt" --until 6 --integrated --check-every 1 >"$tmp/i.json" 2>"$tmp/err"; rc=$?
python3 - "$tmp/i.json" <<'PY' && [ $rc -eq 0 ] && ok || bad "simulate hull --integrated: rc=$rc $(head -c 300 "$tmp/i.json") $(head -c 200 "$tmp/err")"
import json, sys
out = json.load(open(sys.argv[1]))
assert out["integrated_changes"] == min(out["n"], out["events"]) > 0, out
assert out["checks"] == 1 + out["batches"], out
PY
expect_error hull-stats-unwritable "cannot write --stats file" -- simulate hull "$tmp/mh.txt" --until 1 --stats "$tmp/no/dir/s.json"

# --- wellspaced --dim 3 and 4 with --updates --check --stats --------------------------------------
printf '0.1 0.2 0.3\n0.7 0.6 0.5\n0.4 0.9 0.2\n' >"$tmp/w3"
printf '+ 0.5 0.5 0.5\n- 0.1 0.2 0.3\n+ 0.25 0.75 0.125\n' >"$tmp/w3u"
printf '0.1 0.2 0.3 0.4\n0.9 0.8 0.7 0.6\n' >"$tmp/w4"
printf '+ 0.5 0.5 0.5 0.5\n' >"$tmp/w4u"
for d in 3 4; do
  "$kmr" wellspaced --dim $d --updates "$tmp/w${d}u" --check --stats "$tmp/ws$d.json" "$tmp/w$d" >"$tmp/ws$d.out" 2>"$tmp/err"; rc=$?
  # The input vertices of the output (flag 0) are exactly the input after the updates, read back
  # from %.17g; the Steiner vertices (flag 1) number construction.steiner + Σ inserted − deleted.
  python3 - "$tmp/w$d" "$tmp/w${d}u" "$tmp/ws$d.out" "$tmp/ws$d.json" $d <<'PY' && [ $rc -eq 0 ] && ok || bad "wellspaced --dim $d --stats: rc=$rc $(head -c 300 "$tmp/err")"
import json, sys
inp, upd, out, st, d = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], int(sys.argv[5])
pts = {tuple(map(float, l.split())) for l in open(inp) if l.strip()}
n0, ups = len(pts), [l.split() for l in open(upd) if l.strip()]
for u in ups:
    p = tuple(map(float, u[1:]))
    (pts.add if u[0] == "+" else pts.remove)(p)
rows = [l.split() for l in open(out) if l.strip()]
assert all(len(r) == d + 1 and r[-1] in "01" for r in rows), rows[:3]
got = [tuple(map(float, r[:d])) for r in rows if r[-1] == "0"]
assert len(got) == len(set(got)) and set(got) == pts, (got, pts)
s = json.load(open(st))
assert s["dim"] == d and s["construction"]["input"] == n0 and len(s["updates"]) == len(ups), s
assert [u["op"] for u in s["updates"]] == [u[0] for u in ups], s["updates"]
assert all("from_scratch_seconds" in u for u in s["updates"]), s["updates"]
steiner = s["construction"]["steiner"] + sum(u["steiner_inserted"] - u["steiner_deleted"] for u in s["updates"])
assert steiner == sum(1 for r in rows if r[-1] == "1"), (steiner, len(rows))
PY
done
# An update that fails validation is named with its file and line.
printf '+ 0.5 0.5 0.5\n+ 0.5 0.5 0.5\n' >"$tmp/w3dup"
expect_error ws3-update-twice "w3dup:2" -- wellspaced --dim 3 --updates "$tmp/w3dup" "$tmp/w3"

# --- kmesh: two identical trajectories are refused, naming both lines ---------------------------
printf '0 0 1 1\n5 5 0 0\n0 0 1 1\n' >"$tmp/km"
expect_error kmesh-identical "identical trajectories" -- kmesh "$tmp/km" --until 1

# --- hull --float on near-collinear points: the non-robust baseline may fail, but then with exit 3
# and a message that says so and points to the exact mode, which must succeed on the same input.
python3 -c "
import random
random.seed(5)
for i in range(300):
    t = random.random(); print(t, 2 * t + 1e-16 * random.random(), 3 * t + 1e-16 * random.random())
print(0, 0, 1); print(1, 0, 0); print(0, 1, 0)" >"$tmp/nearline.xyz"
"$kmr" hull "$tmp/nearline.xyz" >"$tmp/exact.json" 2>"$tmp/err" && grep -q '"vertices": \[' "$tmp/exact.json" && ok || bad "hull (exact) on near-collinear points: $(head -c 200 "$tmp/err")"
"$kmr" hull "$tmp/nearline.xyz" --float >"$tmp/out" 2>"$tmp/err"; rc=$?
if [ $rc -eq 0 ] || { [ $rc -eq 3 ] && grep -q 'the --float baseline failed (it is not robust; run without --float)' "$tmp/err"; }; then ok; else
  bad "hull --float failure: rc=$rc $(head -c 200 "$tmp/err")"; fi

# --- --svg on a failing run: a regular file is removed; a FIFO or a device never -----------------
printf '0 0 0\n1 0 0\n0 1 0\n1 1 0\n' >"$tmp/flat.xyz"   # coplanar: `kmr hull` refuses it after opening --svg
expect_error svg-regular "coplanar" -- hull "$tmp/flat.xyz" --svg "$tmp/p.svg"
[ ! -e "$tmp/p.svg" ] && ok || bad "svg: the picture of a failed run was left behind"
mkfifo "$tmp/fifo"
(timeout 20 cat "$tmp/fifo" >/dev/null &)
expect_error svg-fifo "coplanar" -- hull "$tmp/flat.xyz" --svg "$tmp/fifo"
if [ -p "$tmp/fifo" ]; then
  ok
  # Only once a FIFO is known to survive: /dev/full opens, every write fails, and it must stay.
  printf '0 0 0\n1 0 0\n0 1 0\n0 0 1\n' >"$tmp/tet.xyz"
  if [ -c /dev/full ]; then
    expect_error svg-full "cannot write --svg file '/dev/full'" -- hull "$tmp/tet.xyz" --svg /dev/full
    [ -c /dev/full ] && ok || bad "svg: /dev/full was removed"
  fi
else
  bad "svg: a failed run unlinked the FIFO given as --svg"
fi

finish "options_test"
