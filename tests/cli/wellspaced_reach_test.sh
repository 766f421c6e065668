#!/usr/bin/env bash
# Issue 11 §1, "never an unbounded silent run": every `kmr wellspaced` run below must end within
# its own timeout (never by hanging ctest), either with an answer or with an upfront refusal
# (exit 2) that names the estimate and the options that fit (spec/wellspaced.md, "Output-size
# estimate"). Usage: wellspaced_reach_test.sh path/to/kmr
set -u
kmr=$1
source "$(dirname "$0")/lib.sh"  # $tmp, ok, bad, expect_error, finish
# run NAME SECONDS ARGS...: kmr ARGS with stdout/stderr in $tmp/out, $tmp/err; rc in $rc
run() {
  local name=$1 secs=$2; shift 2
  timeout "$secs" "$kmr" "$@" >"$tmp/out" 2>"$tmp/err"; rc=$?
  [ $rc -eq 124 ] && bad "$name: no answer within $secs s (a silent run)"
  return 0
}
json_field() { grep -oE "\"$1\": [0-9.e+-]+" "$2" | head -1 | sed 's/.*: //'; }

# 1. Two points 1 ulp apart (0.5 and the next double) at ρ = 1.2, β = 3, in [0,1]^2 and at a
#    corner: answered (exit 0) within 60 s, the inputs in the output, and the output no larger
#    than the estimate (the estimate is an envelope of the measured outputs).
printf '0.5 0.5\n0.50000000000000011 0.5\n' >"$tmp/ulp2"
printf '1 1\n0.99999999999999989 1\n' >"$tmp/ulp2c"
for f in ulp2 ulp2c; do
  run "$f" 60 wellspaced --dim 2 --rho 1.2 --beta 3 --stats "$tmp/s.json" "$tmp/$f"
  if [ $rc -eq 0 ]; then
    m=$(wc -l <"$tmp/out"); inputs=$(grep -c ' 0$' "$tmp/out")
    est=$(json_field estimated_vertices "$tmp/s.json")
    [ "$inputs" -eq 2 ] && [ "$m" -gt 2 ] && ok || bad "$f: $m vertices, $inputs inputs"
    awk -v m="$m" -v e="$est" 'BEGIN { exit !(e >= m) }' && ok || bad "$f: estimate $est below the output $m"
  elif [ $rc -ne 124 ]; then bad "$f: rc=$rc $(head -c 300 "$tmp/err")"; fi
done

# 2. The same pair in 4D at ρ = 1.2 (hours of StableWS): refused upfront, naming the estimate,
#    the limit and a ρ that fits; nothing on stdout.
printf '0.5 0.5 0.5 0.5\n0.50000000000000011 0.5 0.5 0.5\n' >"$tmp/ulp4"
run ulp4 20 wellspaced --dim 4 --rho 1.2 --beta 3 "$tmp/ulp4"
if [ $rc -eq 2 ] && [ ! -s "$tmp/out" ] && grep -q 'estimated at about' "$tmp/err" && grep -qF -- '--max-vertices 20000' "$tmp/err" \
  && grep -qF -- 'e.g. --rho ' "$tmp/err" && ! grep -q 'internal error' "$tmp/err"; then ok; else
  [ $rc -eq 124 ] || bad "ulp4: rc=$rc (want 2 and the estimate), stderr: $(head -c 300 "$tmp/err")"; fi

# 2b. With --beta given, the suggested ρ stays below it (ρ < β is required): at --beta 1.5 the
#     suggestion is a ρ < 1.5, or the message says none below --beta fits.
run ulp4-beta 20 wellspaced --dim 4 --rho 1.2 --beta 1.5 "$tmp/ulp4"
sugg=$(grep -oE 'e\.g\. --rho [0-9.]+' "$tmp/err" | sed 's/.*--rho //')
if [ $rc -eq 2 ] && { { [ -n "$sugg" ] && awk -v r="$sugg" 'BEGIN { exit !(r < 1.5) }'; } || grep -qF 'no rho below --beta 1.5 fits' "$tmp/err"; }; then ok; else
  [ $rc -eq 124 ] || bad "ulp4-beta: rc=$rc, suggested '$sugg' not below --beta 1.5: $(head -c 300 "$tmp/err")"; fi

# 3. ρ = 1.0000001 on three points (issue 11): refused upfront (the exact rank thresholds).
printf '0.5 0.5\n0.52 0.5\n0.9 0.1\n' >"$tmp/three"
run three 20 wellspaced --dim 2 --rho 1.0000001 "$tmp/three"
if [ $rc -eq 2 ] && [ ! -s "$tmp/out" ] && grep -q 'too close to 1' "$tmp/err"; then ok; else
  [ $rc -eq 124 ] || bad "three: rc=$rc (want 2, 'too close to 1'), stderr: $(head -c 300 "$tmp/err")"; fi

# 4. The suggested ρ fits: with --max-vertices 3000 the 2D pair at ρ = 1.2 is refused with a
#    suggestion; rerun with it, the run is accepted and its output is within the limit.
run limit 60 wellspaced --dim 2 --rho 1.2 --beta 3 --max-vertices 3000 "$tmp/ulp2"
sugg=$(grep -oE 'e\.g\. --rho [0-9.]+' "$tmp/err" | sed 's/.*--rho //')
if [ $rc -eq 2 ] && [ -n "$sugg" ]; then
  ok
  run limit-fits 60 wellspaced --dim 2 --rho "$sugg" --beta 3 --max-vertices 3000 "$tmp/ulp2"
  m=$(wc -l <"$tmp/out")
  [ $rc -eq 0 ] && [ "$m" -le 3000 ] && ok || bad "limit-fits: --rho $sugg: rc=$rc, $m vertices"
else bad "limit: rc=$rc, no suggested --rho: $(head -c 300 "$tmp/err")"; fi
# --max-vertices 0 lifts the limit; a bad value is refused (exit 2) naming the value or the option.
run no-limit 60 wellspaced --dim 2 --rho 1.2 --beta 3 --max-vertices 0 "$tmp/ulp2"
[ $rc -eq 0 ] && ok || bad "no-limit: rc=$rc"
run limit-word 20 wellspaced --dim 2 --max-vertices many "$tmp/ulp2"
[ $rc -eq 2 ] && grep -qF -- "'many'" "$tmp/err" && ok || bad "limit-word: rc=$rc $(head -c 200 "$tmp/err")"
run limit-negative 20 wellspaced --dim 2 --max-vertices -5 "$tmp/ulp2"
[ $rc -eq 2 ] && grep -qF -- '--max-vertices' "$tmp/err" && ok || bad "limit-negative: rc=$rc $(head -c 200 "$tmp/err")"

# 5. The estimate covers the points --updates inserts: three points far apart fit in 3000 vertices
#    at ρ = 1.2, but inserting the 1-ulp pair does not; refused upfront naming the insertions, and
#    the suggested ρ then runs all the updates within the limit.
printf '0.1 0.1\n0.9 0.9\n0.2 0.8\n' >"$tmp/far3"
printf '+ 0.5 0.5\n+ 0.50000000000000011 0.5\n- 0.2 0.8\n' >"$tmp/far3.up"
run updates-fit 60 wellspaced --dim 2 --rho 1.2 --beta 3 --max-vertices 3000 "$tmp/far3"
[ $rc -eq 0 ] && ok || bad "updates-fit: the input alone: rc=$rc $(head -c 200 "$tmp/err")"
run updates 60 wellspaced --dim 2 --rho 1.2 --beta 3 --max-vertices 3000 --updates "$tmp/far3.up" "$tmp/far3"
sugg=$(grep -oE 'e\.g\. --rho [0-9.]+' "$tmp/err" | sed 's/.*--rho //')
if [ $rc -eq 2 ] && [ ! -s "$tmp/out" ] && grep -qF 'with the 2 new points of --updates' "$tmp/err" && [ -n "$sugg" ]; then
  ok
  run updates-fits 60 wellspaced --dim 2 --rho "$sugg" --beta 3 --max-vertices 3000 --updates "$tmp/far3.up" "$tmp/far3"
  m=$(wc -l <"$tmp/out")
  [ $rc -eq 0 ] && [ "$m" -le 3000 ] && ok || bad "updates-fits: --rho $sugg: rc=$rc, $m vertices"
else bad "updates: rc=$rc (want 2 naming the insertions and a rho), stderr: $(head -c 300 "$tmp/err")"; fi

finish "wellspaced_reach_test"
