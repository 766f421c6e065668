#!/usr/bin/env bash
# Issue 11 §1 sweep (opt-in, minutes): `kmr wellspaced` on the pair ½, ½ + 2^-k along the first
# axis (k = 30 … 53; k = 53 is 1 ulp) at ρ/β = 1.1/2.2, 1.5/3, 2/4, 3/6, 4/8. Prints one line per
# run (k, ρ, exit status, |M|, vertices with hex-float coordinates) and the count answered.
# With JUDGE=<kmr_oracle_ws_judge> every answer is also judged by the CGAL oracle (exact).
# TMO=<seconds> limits each run (default 600; exit status 124 = timed out).
# Usage: scripts/ws_near_duplicate_sweep.sh KMR_BINARY [DIM] [KMIN] [KMAX]
set -u
kmr=$1
dim=${2:-2}
kmin=${3:-30}
kmax=${4:-53}
tmp=$(mktemp -d)
answered=0
total=0
judged_ok=0
for k in $(seq "$kmin" "$kmax"); do
  python3 - "$k" "$dim" > "$tmp/in.txt" <<'PY'
import sys
k, d = int(sys.argv[1]), int(sys.argv[2])
print(" ".join(["0.5"] * d))
print(" ".join([repr(0.5 + 2.0 ** -k)] + ["0.5"] * (d - 1)))
PY
  for rb in "1.1 2.2" "1.5 3" "2 4" "3 6" "4 8"; do
    set -- $rb
    total=$((total + 1))
    timeout "${TMO:-600}" "$kmr" wellspaced --quiet --dim "$dim" --rho "$1" --beta "$2" "$tmp/in.txt" > "$tmp/out.txt" 2> "$tmp/err.txt"
    rc=$?
    line="k=$k rho=$1 beta=$2 rc=$rc"
    if [ $rc -eq 0 ]; then
      answered=$((answered + 1))
      line="$line |M|=$(wc -l < "$tmp/out.txt") hex=$(grep -c 0x "$tmp/out.txt")"
      if [ -n "${JUDGE:-}" ]; then
        if "$JUDGE" --dim "$dim" --rho "$1" --input "$tmp/in.txt" "$tmp/out.txt" > /dev/null 2>&1; then
          judged_ok=$((judged_ok + 1)); line="$line judged=ok"
        else
          line="$line judged=FAIL"
        fi
      fi
    else
      line="$line $(head -c 120 "$tmp/err.txt" | tr '\n' ' ')"
    fi
    echo "$line"
  done
done
echo "answered $answered/$total${JUDGE:+, judged well-spaced and size-conforming $judged_ok/$answered}"
rm -rf "$tmp"
