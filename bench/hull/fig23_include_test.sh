#!/usr/bin/env bash
# fig23_bench end to end on a small case (n = 10, 12; 2^4 time units; every gap checked): exit 0,
# one JSON line per size, and its --audit-json read back by `kmr audit --include` into the report
# on the F2.3 row (its verdict and a figure present). Usage: fig23_include_test.sh fig23_bench kmr
set -u
bench=$1 kmr=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$bench" --n 10,12 --until-log2 4 --check-every 1 --audit-json "$tmp/f.json" >"$tmp/out" || { echo "FAIL fig23_bench rc=$?"; exit 1; }
[ "$(grep -c '"check_failures": 0' "$tmp/out")" -eq 2 ] || { echo "FAIL expected two sizes without check failures"; cat "$tmp/out"; exit 1; }
grep -q '"claim":"F2.3-events-vs-kinetic-delaunay"' "$tmp/f.json" || { echo "FAIL no F2.3 result in the audit JSON"; exit 1; }
"$kmr" audit --quick --only L3.4.4 --include "$tmp/f.json" --report "$tmp/r" --quiet >"$tmp/table" || { echo "FAIL kmr audit --include rc=$?"; exit 1; }
grep -q "F2.3-events-vs-kinetic-delaunay" "$tmp/table" || { echo "FAIL F2.3 not in the audit table"; cat "$tmp/table"; exit 1; }
grep -q "flips / hull events" "$tmp/r/report.md" || { echo "FAIL the F2.3 figures are not in report.md"; exit 1; }
echo "fig23 include: ok"
