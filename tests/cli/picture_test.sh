#!/usr/bin/env bash
# `kmr wellspaced --svg`: the picture is well-formed XML; it has one input/Steiner marker per output
# vertex with the exact coordinates printed on stdout; and its Voronoi cells tile the unit square
# (areas of the cell polygons, computed here from the SVG, sum to the frame's area) — a missing
# neighbour makes cells overlap, a wrong cut leaves holes. Bad uses exit 2.
# Usage: picture_test.sh path/to/kmr INPUT_2D [INPUT_2D...]
set -u
kmr=$1; shift
source "$(dirname "$0")/lib.sh"  # $tmp, ok, bad, expect_error, finish
# degenerate inputs too: a cocircular 6 x 6 grid (crossing empty-circle pairs) and collinear points
awk 'BEGIN { for (i = 0; i < 6; i++) for (j = 0; j < 6; j++) printf "%.17g %.17g\n", (i + 0.5) / 6, (j + 0.5) / 6 }' >"$tmp/grid.txt"
awk 'BEGIN { for (i = 1; i < 12; i++) printf "%.17g 0.5\n", i / 12 }' >"$tmp/line.txt"
for input in "$@" "$tmp/grid.txt" "$tmp/line.txt"; do
  name=$(basename "$input")
  "$kmr" wellspaced --dim 2 --svg "$tmp/p.svg" "$input" >"$tmp/out" 2>"$tmp/err" || { bad "$name: rc=$? $(cat "$tmp/err")"; continue; }
  xmllint --noout "$tmp/p.svg" && ok || bad "$name: not well-formed"
  # markers vs stdout: "x y flag" lines, compared as sorted text after %.17g both sides
  awk '{ print $1, $2, ($3 == 1 ? "steiner" : "input") }' "$tmp/out" | sort >"$tmp/want"
  grep -o '<circle [^>]*class="\(input\|steiner\)"[^>]*>' "$tmp/p.svg" |
    sed 's/.*class="\([a-z]*\)" data-x="\([^"]*\)" data-y="\([^"]*\)".*/\2 \3 \1/' | sort >"$tmp/got"
  cmp -s "$tmp/want" "$tmp/got" && ok || bad "$name: markers differ from stdout ($(wc -l <"$tmp/want") vs $(wc -l <"$tmp/got"))"
  cells=$(grep -c 'class="cell"' "$tmp/p.svg")
  [ "$cells" -eq "$(wc -l <"$tmp/out")" ] && ok || bad "$name: $cells cells for $(wc -l <"$tmp/out") vertices"
  # shoelace area of every cell polygon, in units of the frame (560 x 560 pixels)
  area=$(grep 'class="cell"' "$tmp/p.svg" | sed 's/.*points="\([^"]*\)".*/\1/' | awk '{
      n = split($0, p, " "); s = 0
      for (i = 1; i <= n; i++) { j = i % n + 1; split(p[i], a, ","); split(p[j], b, ","); s += a[1] * b[2] - b[1] * a[2] }
      total += (s < 0 ? -s : s) / 2 }
    END { printf "%.6f", total / (560 * 560) }')
  awk -v a="$area" 'BEGIN { exit !(a > 0.9995 && a < 1.0005) }' && ok || bad "$name: cells cover $area of the unit square, not 1"
done
"$kmr" wellspaced --dim 3 --svg "$tmp/q.svg" "$1" >/dev/null 2>"$tmp/err"
[ $? -eq 2 ] && grep -q -- "--svg draws 2D outputs only" "$tmp/err" && ok || bad "--svg with --dim 3: $(cat "$tmp/err")"
"$kmr" wellspaced --dim 2 --svg /proc/nonexistent/x.svg "$1" >"$tmp/out" 2>"$tmp/err"
[ $? -eq 2 ] && [ ! -s "$tmp/out" ] && grep -q "cannot write --svg file" "$tmp/err" && ok || bad "unwritable --svg: $(cat "$tmp/err")"
finish "picture_test"
