#!/usr/bin/env bash
# End-to-end checks of the kmr CLI against hand-derived outputs and its bad-input contract
# (clear message naming the problem, exit status 2). Usage: cli_test.sh path/to/kmr
set -u
kmr=$1
source "$(dirname "$0")/lib.sh"  # $tmp, ok, bad, expect_error, finish

expect_out() {  # expect_out NAME EXPECTED_STDOUT -- ARGS...
  local name=$1 want=$2; shift 3
  local got; got=$("$kmr" "$@" 2>"$tmp/err"); local rc=$?
  if [ $rc -eq 0 ] && [ "$got" = "$want" ]; then passed=$((passed+1)); else
    failed=$((failed+1)); echo "FAIL $name: rc=$rc"; echo "  want: $want"; echo "  got:  $got"; cat "$tmp/err"; fi
}

# t² − 2: roots ±√2; √2·1024 = 1448.15.
expect_out sqrt2 '{"degree": 2, "distinct_real_roots": 2, "intervals": [{"k": 1448, "roots": 1, "sign_change": true}]}' -- roots -- -2 0 1
expect_out sqrt2-window '{"degree": 2, "distinct_real_roots": 2, "intervals": [{"k": -1449, "roots": 1, "sign_change": true}, {"k": 1448, "roots": 1, "sign_change": true}]}' -- roots --from -4 --to 4 -- -2 0 1
# t²: a double root at the lattice point 0; no sign change.
expect_out double-root '{"degree": 2, "distinct_real_roots": 1, "intervals": [{"k": 0, "roots": 1, "sign_change": false}]}' -- roots --from -1 -- 0 0 1
# (t−1)(t−1−2^-12): two roots closer than δ = 2^-10 share one interval, even count: no sign change.
# = t² − (2 + 2^-12)t + (1 + 2^-12), times 4096: 4096t² − 8193t + 4097.
expect_out cluster '{"degree": 2, "distinct_real_roots": 2, "intervals": [{"k": 1024, "roots": 2, "sign_change": false}]}' -- roots -- 4097 -8193 4096
# (t − 3/2)³ · 8 = 8t³ − 36t² + 54t − 27: a triple root at the lattice point 1.5 (B = 1).
expect_out triple '{"degree": 3, "distinct_real_roots": 1, "intervals": [{"k": 3, "roots": 1, "sign_change": true}]}' -- roots --lattice-bits 1 -- -27 54 -36 8
# A root exactly at the window's end is outside [T0, T1); at its start, inside.
expect_out window-end '{"degree": 1, "distinct_real_roots": 1, "intervals": []}' -- roots --lattice-bits 0 --from 0 --to 5 -- -5 1
expect_out window-start '{"degree": 1, "distinct_real_roots": 1, "intervals": [{"k": 5, "roots": 1, "sign_change": true}]}' -- roots --lattice-bits 0 --from 5 --to 6 -- -5 1
# Leading zeros are decimal, not octal (regression: Boost reads "010" as 8).
expect_out leading-zeros '{"degree": 1, "distinct_real_roots": 1, "intervals": [{"k": 10, "roots": 1, "sign_change": true}]}' -- roots --lattice-bits 0 --from 0.0001220703125 -- -010 001
expect_out constant '{"degree": 0, "distinct_real_roots": 0, "intervals": []}' -- roots -- 7
expect_error zero-poly 'zero polynomial' -- roots -- 0 0
expect_error no-coeffs 'no coefficients' -- roots --
expect_error bad-coeff "not an integer: '1.5'" -- roots -- 1 1.5
expect_error bad-window 'empty window' -- roots --from 3 --to 2 -- 1 1
expect_error non-dyadic "'0.1'" -- roots --from 0.1 -- 1 1
expect_error unknown-option "unknown option '--frob'" -- roots --frob 1 -- 1 1

# Kinetic sorting: three points meeting at x = 5, t = 5 cross in one batch.
printf '0 1\n10 -1\n5 0\n' >"$tmp/meet.txt"
expect_out sort-meet '{"events": 2, "batches": 1, "max_batch": 2, "order": [1, 2, 0]}' -- simulate sort "$tmp/meet.txt" --until 20
# Separated crossings: 0: t, 1: 3 (crosses at 3), 2: 10 − t (crosses 1 at 7, 0 at 5).
printf '0 1\n3 0\n10 -1\n' >"$tmp/sep.txt"
expect_out sort-separate '{"events": 3, "batches": 3, "max_batch": 1, "order": [2, 1, 0]}' -- simulate sort "$tmp/sep.txt" --until 8
expect_out sort-early '{"events": 1, "batches": 1, "max_batch": 1, "order": [1, 0, 2]}' -- simulate sort "$tmp/sep.txt" --until 4
printf '0 1\n3 0\n0 1\n' >"$tmp/dup.txt"
expect_error sort-dup 'identical trajectories' -- simulate sort "$tmp/dup.txt"
printf '0 1\n3 x\n' >"$tmp/bad.txt"
expect_error sort-bad-line 'bad.txt:2' -- simulate sort "$tmp/bad.txt"
expect_error sort-missing 'cannot open' -- simulate sort "$tmp/none.txt"
expect_error sort-until 'not a multiple of the lattice step' -- simulate sort "$tmp/sep.txt" --until 0.0001220703125 --lattice-bits 2
# Crash hazard: a size whose trace cannot fit is refused before anything runs (map at 10^8 alone
# needs tens of GB; the sorts far more).
expect_error bench-too-big 'map at n=100000000 needs an estimated' -- bench sac --n 100000000
expect_error bench-too-big-sort 'quicksort at n=100000000 needs an estimated' -- bench sac --n 100000000 --program quicksort
# kmesh (Ch. 4, static construction): one point is its own mesh; integers of any size.
printf '# one point\n5 -7\n' >"$tmp/km1.txt"
expect_out kmesh-one '{"time": 0, "vertices": [[5, -7, 0]], "triangles": [], "events": 0, "batches": 0, "certificates": 0, "first_failure": null}' -- kmesh "$tmp/km1.txt"
# Two points 3 apart: 20·2^r ≥ 3 first at r = −2, so both activate at rank −2, and all 24 of their
# (−2)-satellites (radius 1/4, 30° apart, chords 0.129 > 1/16) have empty balls B(s, 1/16): converted.
printf '0 0\n3 0 0 0\n' >"$tmp/km2.txt"
"$kmr" kmesh "$tmp/km2.txt" --check --stats "$tmp/km2.json" >"$tmp/km2.out" 2>"$tmp/err"
if [ $? -eq 0 ] && grep -qF '{"rank": -2, "active": 2, "considered": 24, "converted": 24' "$tmp/km2.json"; then passed=$((passed+1)); else
  failed=$((failed+1)); echo "FAIL kmesh-two-check"; cat "$tmp/err"; fi
printf '0 0\n1 2 3\n' >"$tmp/km3.txt"
expect_error kmesh-arity 'km3.txt:2: expected' -- kmesh "$tmp/km3.txt"
printf '0 0\n1 2.5\n' >"$tmp/km4.txt"
expect_error kmesh-not-integer "km4.txt:2: '2.5' is not a decimal integer" -- kmesh "$tmp/km4.txt"
printf '0 0 1 0\n4 4\n0 0 0 1\n' >"$tmp/km5.txt"
expect_error kmesh-collision 'km5.txt:3 and /' -- kmesh "$tmp/km5.txt"
# Motion: (0,0) at rest and (3,0) moving by (1,0); --until 1/4 on the lattice 2^-2 is one interval.
printf '0 0\n3 0 1 0\n' >"$tmp/km6.txt"
"$kmr" kmesh "$tmp/km6.txt" --until 0.25 --lattice-bits 2 --check >"$tmp/km6.out" 2>"$tmp/err"
if [ $? -eq 0 ] && grep -qF '"time": 0.25,' "$tmp/km6.out"; then passed=$((passed+1)); else
  failed=$((failed+1)); echo "FAIL kmesh-until"; cat "$tmp/err"; fi
printf '0 + 9 9 0 0\n0.25 - 9 9 0 0\n' >"$tmp/km6u.txt"
"$kmr" kmesh "$tmp/km6.txt" --until 0.25 --lattice-bits 2 --updates "$tmp/km6u.txt" --check --stats "$tmp/km6.json" >/dev/null 2>"$tmp/err"
if [ $? -eq 0 ] && grep -qF '"what": "insert"' "$tmp/km6.json" && grep -qF '"what": "delete"' "$tmp/km6.json"; then passed=$((passed+1)); else
  failed=$((failed+1)); echo "FAIL kmesh-updates"; cat "$tmp/err"; fi
# Points at rest with updates: the Fig. 4.5 update repairs them (not the rebuild), checked by --check.
printf '0 0\n5 1\n2 7\n' >"$tmp/km10.txt"
printf '0 + 4 4 0 0\n0 - 5 1 0 0\n' >"$tmp/km10u.txt"
"$kmr" kmesh "$tmp/km10.txt" --updates "$tmp/km10u.txt" --check --stats "$tmp/km10.json" >/dev/null 2>"$tmp/err"
if [ $? -eq 0 ] && [ "$(grep -o '"repair": "fig4.5"' "$tmp/km10.json" | wc -l)" -eq 2 ]; then passed=$((passed+1)); else
  failed=$((failed+1)); echo "FAIL kmesh-updates-at-rest"; cat "$tmp/err"; fi
# --stats counts every --check run by claim: L4.2.4 (it reads the construction's order) once, after the
# construction, on each path (at rest with updates, static, moving); the checks of an updated mesh
# after every update and batch (U1: once per check point). The kinetic KDS counts the certificates its
# construction built and those each batch built and dropped; the Fig. 4.5 updater at rest has none.
"$kmr" kmesh "$tmp/km2.txt" --check --stats "$tmp/km2s.json" >/dev/null 2>"$tmp/err"
"$kmr" kmesh "$tmp/km6.txt" --until 0.25 --lattice-bits 2 --check --stats "$tmp/km6s.json" >/dev/null 2>>"$tmp/err"
if python3 - "$tmp/km10.json" "$tmp/km2s.json" "$tmp/km6s.json" "$tmp/km6.json" <<'PY'; then ok; else bad "kmesh-check-tally"; cat "$tmp/err"; fi
import json, sys
at_rest, static, moving, updated = (json.load(open(f)) for f in sys.argv[1:])
def runs(s, claim):
    c = [c for c in s["checks"] if c["claim"] == claim]
    assert len(c) == 1 and c[0]["violations"] == 0 and c[0]["ok"], (claim, c)
    return c[0]["runs"]
for s, points in ((at_rest, 3), (static, 1), (moving, 1 + len(moving["batches"]))):
    assert runs(s, "L4.2.4") == 1, s["checks"]
    assert runs(s, "U1") >= points, (runs(s, "U1"), points)
# At rest, the certificates at the end are those the construction built: M's (stdout's count) and S_N's.
assert static["certificates_initial"] >= sum(static["certificates"].values()) > 0, static
# Conservation: the certificates built at the construction, plus those built, minus those dropped by
# every batch and update, are the certificates kept at the end (counted apart, by the KDS's map).
for s in (static, moving, updated):
    flow = s["certificates_initial"] + sum(b["certificates_created"] - b["certificates_destroyed"] for b in s["batches"])
    assert flow == s["certificates_kept"], (flow, s["certificates_kept"])
assert any(b["certificates_created"] > 0 and b["certificates_destroyed"] > 0 for b in moving["batches"] + updated["batches"])
assert "certificates_initial" not in at_rest and not any("certificates_created" in b for b in at_rest["batches"])
PY
# Moving points: the kinetic KDS repairs every batch by Fig. 4.5 (checked by --check, L4.3.1 included);
# --rebuild runs the reference KDS instead.
"$kmr" kmesh "$tmp/km6.txt" --until 0.25 --lattice-bits 2 --check --stats "$tmp/km11.json" >/dev/null 2>"$tmp/err"
if [ $? -eq 0 ] && grep -qF '"repair": "fig4.5"' "$tmp/km11.json" && ! grep -qF '"repair": "rebuild"' "$tmp/km11.json"; then passed=$((passed+1)); else
  failed=$((failed+1)); echo "FAIL kmesh-kinetic-fig4.5"; cat "$tmp/err"; fi
"$kmr" kmesh "$tmp/km6.txt" --until 0.25 --lattice-bits 2 --rebuild --stats "$tmp/km12.json" >/dev/null 2>"$tmp/err"
if [ $? -eq 0 ] && grep -qF '"repair": "rebuild"' "$tmp/km12.json"; then passed=$((passed+1)); else
  failed=$((failed+1)); echo "FAIL kmesh-kinetic-rebuild"; cat "$tmp/err"; fi
# --check compares the kept certificates' names with a recomputation from scratch (kmesh17). A valid
# run where satellites keep a witness other than the nearest must pass (it exited 1 when a
# ball-not-empty certificate's ends were ordered before its witness was dropped).
printf '0 0\n4 0 0 1\n9 7\n' >"$tmp/km13.txt"
printf '0.125 + 3 3 1 0\n0.25 - 9 7 0 0\n' >"$tmp/km13u.txt"
"$kmr" kmesh "$tmp/km13.txt" --until 0.25 --lattice-bits 3 --updates "$tmp/km13u.txt" --check >/dev/null 2>"$tmp/err"
if [ $? -eq 0 ] && [ ! -s "$tmp/err" ]; then passed=$((passed+1)); else
  failed=$((failed+1)); echo "FAIL kmesh-check-witness"; cat "$tmp/err"; fi
# Inserting and deleting a far point raises the top rank and lowers it back; the update must
# re-decide the falling top rank whole, or the boundary is left split between two nuclei and its
# convexity uncertified (spec/kmesh.md, "rigid boundary"). --check checks the boundary: it must pass.
printf '0 0\n1 1\n0 2\n6 -3\n' >"$tmp/km16.txt"
printf '0 + 28 30 0 0\n0 - 28 30 0 0\n' >"$tmp/km16u.txt"
"$kmr" kmesh "$tmp/km16.txt" --updates "$tmp/km16u.txt" --check >/dev/null 2>"$tmp/err"
if [ $? -eq 0 ] && [ ! -s "$tmp/err" ]; then passed=$((passed+1)); else
  failed=$((failed+1)); echo "FAIL kmesh-check-split-boundary"; cat "$tmp/err"; fi
# (161,0) moving (-1,0): ~50 strict certificates vanish at t = 1 (e.g. |xy| > 20·2^3); they fail at 1
# and are repaired by a batch at 1, and --check also checks the mesh at T after the last batch.
printf '0 0\n161 0 -1 0\n' >"$tmp/km14.txt"
"$kmr" kmesh "$tmp/km14.txt" --until 1 --lattice-bits 4 --check --stats "$tmp/km14.json" >/dev/null 2>"$tmp/err"
if [ $? -eq 0 ] && grep -qF '{"time": 1, "what": "events"' "$tmp/km14.json"; then passed=$((passed+1)); else
  failed=$((failed+1)); echo "FAIL kmesh-check-at-horizon"; cat "$tmp/err"; fi
# The same with the reference KDS: --rebuild --check checks the last snapshot moved to T (L4.3.1).
"$kmr" kmesh "$tmp/km14.txt" --until 1 --lattice-bits 4 --rebuild --check --stats "$tmp/km15.json" >/dev/null 2>"$tmp/err"
if [ $? -eq 0 ] && [ ! -s "$tmp/err" ] && grep -qF '"repair": "rebuild"' "$tmp/km15.json" && grep -qF '{"time": 1, "what": "events"' "$tmp/km15.json"; then passed=$((passed+1)); else
  failed=$((failed+1)); echo "FAIL kmesh-rebuild-check-at-horizon"; cat "$tmp/err"; fi
# (-1,160) moving (1,0) passes (0,0) at distance exactly 160 = 20*2^3 at t = 1: ~55 strict certificates
# touch 0 there without a sign change; both KDSs must repair them at 1 (before: --check exit 1, S1/S3).
printf '0 0\n-1 160 1 0\n' >"$tmp/km16.txt"
for kds in kinetic rebuild; do
  flag=(); [ $kds = rebuild ] && flag=(--rebuild)
  "$kmr" kmesh "$tmp/km16.txt" --until 1 --lattice-bits 4 "${flag[@]}" --check --stats "$tmp/km16.json" >/dev/null 2>"$tmp/err"
  if [ $? -eq 0 ] && [ ! -s "$tmp/err" ] && grep -qF '{"time": 1, "what": "events"' "$tmp/km16.json"; then passed=$((passed+1)); else
    failed=$((failed+1)); echo "FAIL kmesh-touch-at-horizon ($kds)"; cat "$tmp/err"; fi
done
# (0,0) moving (1,1) meets (4,4) at t = 4: refused when T ≥ 4, accepted before.
printf '0 0 1 1\n4 4\n' >"$tmp/km7.txt"
expect_error kmesh-collision-later 'collide at time 4' -- kmesh "$tmp/km7.txt" --until 5
expect_error kmesh-until-off-lattice 'not a multiple of the lattice step' -- kmesh "$tmp/km6.txt" --until 0.125 --lattice-bits 2
printf '0 - 1 1 0 0\n' >"$tmp/km8.txt"
expect_error kmesh-delete-absent 'km8.txt:1: deletes a trajectory that is not present' -- kmesh "$tmp/km6.txt" --updates "$tmp/km8.txt"
printf '0 + 1 1\n' >"$tmp/km9.txt"
expect_error kmesh-update-arity "km9.txt:1: expected 'T + x y vx vy'" -- kmesh "$tmp/km6.txt" --updates "$tmp/km9.txt"
printf '# nothing\n' >"$tmp/km0.txt"
expect_error kmesh-empty 'no input point' -- kmesh "$tmp/km0.txt"
expect_error unknown-command "unknown command 'frob'" -- frob

# kmr hull (thesis §2.2). A tetrahedron: outward normals −z, −y, −x, (1,1,1), counter-clockwise from outside.
printf '0 0 0\n1 0 0\n0 1 0\n0 0 1\n' >"$tmp/tet.xyz"
expect_out hull-tet '{"n": 4, "vertices": [0, 1, 2, 3], "facets": [[0, 1, 3], [0, 2, 1], [0, 3, 2], [1, 2, 3]]}' -- hull "$tmp/tet.xyz"
expect_out hull-tet-float '{"n": 4, "vertices": [0, 1, 2, 3], "facets": [[0, 1, 3], [0, 2, 1], [0, 3, 2], [1, 2, 3]]}' -- hull "$tmp/tet.xyz" --float
# The cube [0,2]^3 with its centre (8), face centres (9-12) and edge midpoints (13, 14): only the corners
# are vertices; each square is a fan from its lexicographically smallest corner (z = 0: [0,2,3], [0,3,1]).
printf '# cube\n0 0 0\n2 0 0\n0 2 0\n2 2 0\n0 0 2\n2 0 2\n0 2 2\n2 2 2\n\n1 1 1  # centre\n1 1 0\n1 0 1\n0 1 1\n2 1 1\n1 0 0\n0 1 0\n' >"$tmp/cube.xyz"
expect_out hull-cube '{"n": 15, "vertices": [0, 1, 2, 3, 4, 5, 6, 7], "facets": [[0, 1, 5], [0, 2, 3], [0, 3, 1], [0, 4, 6], [0, 5, 4], [0, 6, 2], [1, 3, 7], [1, 7, 5], [2, 6, 7], [2, 7, 3], [4, 5, 7], [4, 7, 6]]}' -- hull "$tmp/cube.xyz"
# Duplicates: 3 and 5 repeat 0 and 1, 6 repeats 4; the lowest index names each point; decimals as doubles.
printf '1.0 0 0\n0 0 0\n0 1 0\n1 0 0\n0 0 1e0\n0.0 -0 0\n0 0 1\n' >"$tmp/dup.xyz"
expect_out hull-dup '{"n": 7, "vertices": [0, 1, 2, 4], "facets": [[0, 1, 2], [0, 2, 4], [0, 4, 1], [1, 4, 2]]}' -- hull "$tmp/dup.xyz"
printf '0 0 0\n1 0 0\n0 1 0\n3 3 0\n' >"$tmp/flat.xyz"
expect_error hull-coplanar 'all points are coplanar' -- hull "$tmp/flat.xyz"
printf '0 0 0\n1 1 1\n2 2 2\n' >"$tmp/line.xyz"
expect_error hull-collinear 'all points are collinear' -- hull "$tmp/line.xyz"
printf '0 0 0\n1 0 0\n0 1 0\n0 0 inf\n' >"$tmp/inf.xyz"
expect_error hull-inf 'inf.xyz:4: not a decimal number' -- hull "$tmp/inf.xyz"
printf '0 0 0\n1 0 0\n0 1 0\n0 0 1e999\n' >"$tmp/big.xyz"
expect_error hull-overflow "big.xyz:4: not a finite double: '1e999'" -- hull "$tmp/big.xyz"
printf '0 0 0\n1 0\n' >"$tmp/arity.xyz"
expect_error hull-arity 'arity.xyz:2: expected 3 numbers' -- hull "$tmp/arity.xyz"
expect_error hull-missing 'cannot open' -- hull "$tmp/none.xyz"
"$kmr" hull "$tmp/cube.xyz" --stats "$tmp/stats.json" >/dev/null && grep -q '"inserted": ' "$tmp/stats.json" \
  && passed=$((passed+1)) || { failed=$((failed+1)); echo "FAIL hull-stats"; }

finish "cli"
