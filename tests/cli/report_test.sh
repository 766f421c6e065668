#!/usr/bin/env bash
# `kmr audit --report`: every SVG parses as XML, index.html passes `xmllint --html` without a
# message, every ID of spec/claims.md (read here with awk, not with kmr's parser) has an entry,
# every ctest replay command names at least one registered test; `--only NOSUCH` exits 2 listing
# the known IDs; `kmr --version`; no progress output when stderr is not a terminal.
# Usage: report_test.sh path/to/kmr path/to/spec/claims.md path/to/build [REPORT_DIR JSON]
# With REPORT_DIR and JSON (written by the ctest `audit.quick` run), validates that report of the whole
# quick audit instead of making a small one.
set -u
kmr=$1 claims=$2 build=$3
source "$(dirname "$0")/lib.sh"  # $tmp, ok, bad, expect_error, finish

if [ $# -ge 5 ]; then
  mkdir -p "$tmp/r" && cp -r "$4"/. "$tmp/r/" && cp "$5" "$tmp/a.json" || { echo "FAIL no report in $4"; exit 1; }
  # one SVG per plot of the JSON (a plot object is the only one with a "bounds" key)
  plots=$(grep -o '"bounds":' "$tmp/a.json" | wc -l)
  svgs=$(ls "$tmp"/r/*.svg 2>/dev/null | wc -l)
  [ "$plots" -eq "$svgs" ] && [ "$plots" -ge 10 ] && ok || bad "$svgs SVG files for $plots plots in the JSON"
  grep -q '"pass":false' "$tmp/a.json" && bad "the quick audit has a failing claim" || ok
else
  # plus an included result whose every text is hostile to Markdown, HTML and SVG
  cat >"$tmp/odd.json" <<'ODD'
[{"claim":"ODD<&|`]x","title":"a | b < c & d `e` ]f[ $x_1 < y^2$ **","pass":true,"summary":"s | t <b>not bold</b> &amp;\nnext","seconds":0.5,
  "thesis":"about 30 % | <i>","figures":{"n | m <x>":"1 | 2 `3`"},"plots":[{"title":"odd ](evil.svg) [x] <t> & | `c` bell\u0007",
  "x":{"label":"x <&>","unit":"u|v","log":false,"categories":[]},"y":{"label":"y","unit":"","log":false,"categories":[]},
  "series":[{"name":"s<&\"'>","points":[[1,2],[2,3]]}],"bounds":[]}]}]
ODD
  "$kmr" audit --quick --only L3.4.4 --report "$tmp/r" --json "$tmp/a.json" --include "$tmp/odd.json" >"$tmp/out" 2>"$tmp/err"
  rc=$?
  [ $rc -eq 0 ] && ok || bad "audit --report rc=$rc"
  [ -s "$tmp/err" ] && bad "stderr not empty without a terminal: $(head -c 300 "$tmp/err")" || ok
fi
n_svg=0
for f in "$tmp"/r/*.svg; do
  [ -e "$f" ] || continue
  n_svg=$((n_svg+1))
  xmllint --noout "$f" 2>"$tmp/x" && ok || bad "$(basename "$f") is not well-formed XML: $(head -3 "$tmp/x")"
done
[ $n_svg -ge 1 ] && ok || bad "no SVG plot written"
xmllint --html --noout "$tmp/r/index.html" 2>"$tmp/h"
if [ $? -eq 0 ] && [ ! -s "$tmp/h" ]; then ok; else bad "index.html: $(head -5 "$tmp/h")"; fi
grep -q 'kmr_version":"' "$tmp/a.json" && ok || bad "JSON without kmr_version"
# report.md as GitHub renders it (cmark-gfm, scripts/install-deps.sh): the images are the SVGs, no
# text of a check became markup, a | inside a figure stays in its cell
if command -v cmark-gfm >/dev/null; then
  cmark-gfm --unsafe -e table "$tmp/r/report.md" >"$tmp/md.html"  # --unsafe: raw HTML kept, so it shows
  # (a plot may show twice: on its row and on a row measured "via" its check, e.g. L3.3.9 via T3.3.8)
  for f in "$tmp"/r/*.svg; do
    grep -qF "<img src=\"$(basename "$f")\"" "$tmp/md.html" && ok || bad "report.md does not show $(basename "$f")"
  done
  (cd "$tmp/r" && ls *.svg) | sort >"$tmp/svg_files"
  grep -o '<img [^>]*>' "$tmp/md.html" | sed 's/.*src="\([^"]*\)".*/\1/' | sort -u >"$tmp/img_srcs"
  cmp -s "$tmp/svg_files" "$tmp/img_srcs" && ok || bad "report.md's images are not the SVG files: $(diff "$tmp/svg_files" "$tmp/img_srcs" | head -3)"
  grep -q '<b>not bold\|<i>\|<t>' "$tmp/md.html" && bad "a check's text became HTML markup in report.md" || ok
  grep -q '<td>n | m &lt;x&gt;</td>' "$tmp/md.html" || [ $# -ge 5 ] && ok || bad "a figure with | broke its table row"
else
  bad "cmark-gfm not installed (scripts/install-deps.sh): report.md not rendered"
fi
grep -q "src=\"http\|<script\|<link" "$tmp/r/index.html" && bad "index.html fetches something or runs a script" || ok
# every ledger ID: first cell of each table row that is neither the header nor the rule
awk -F'|' '/^\| / && !/^\| ID \|/ { gsub(/^ +| +$/, "", $2); print $2 }' "$claims" >"$tmp/ids"
[ "$(wc -l <"$tmp/ids")" -gt 50 ] && ok || bad "awk found too few ledger IDs"
while read -r id; do
  grep -qF "### $id — " "$tmp/r/report.md" || { bad "report.md lacks $id"; continue; }
  grep -qF "<h3>$id <span" "$tmp/r/index.html" || { bad "index.html lacks $id"; continue; }
  ok
done <"$tmp/ids"
# every ctest replay command runs at least one registered test
ctest --test-dir "$build" -N >"$tmp/tests" 2>/dev/null
sed -n "s/.*ctest --test-dir build -R '\([^']*\)'.*/\1/p" "$tmp/r/report.md" | sort -u >"$tmp/regexes"
[ -s "$tmp/regexes" ] && ok || bad "no ctest replay command in report.md"
if [ "${KMR_ALL_TESTS_BUILT:-1}" = 1 ]; then
  # each alternative on its own: one misspelt name beside a correct one must not pass
  tr '|' '\n' <"$tmp/regexes" | sort -u >"$tmp/alternatives"
  while read -r re; do
    grep -Eq "Test +#[0-9]+: .*($re)" "$tmp/tests" && ok || bad "replay regex part '$re' matches no ctest test"
  done <"$tmp/alternatives"
else
  echo "note: oracles or benchmarks not built (KMR_ORACLES/KMR_BENCH off): replay regexes not matched against ctest"
fi
# --only without a match
"$kmr" audit --only NOSUCH >"$tmp/out" 2>"$tmp/err"
rc=$?
if [ $rc -eq 2 ] && grep -q "no claim matches --only 'NOSUCH'" "$tmp/err" && grep -q "T3.4.3" "$tmp/err" && [ ! -s "$tmp/out" ]; then ok
else bad "--only NOSUCH: rc=$rc, stderr: $(cat "$tmp/err")"; fi
# ... and it writes no file: neither --json nor --report is created
"$kmr" audit --only NOSUCH --json "$tmp/nosuch.json" --report "$tmp/nosuch" >/dev/null 2>&1
[ $? -eq 2 ] && [ ! -e "$tmp/nosuch.json" ] && [ ! -e "$tmp/nosuch" ] && ok || bad "--only NOSUCH left a --json or --report file"
# a bad --include fails before --json writes anything
"$kmr" audit --only L3.4.4 --include "$tmp/missing.json" --json "$tmp/inc.json" >/dev/null 2>&1
[ $? -eq 2 ] && [ ! -e "$tmp/inc.json" ] && ok || bad "a bad --include left a --json file"
# --include and --json may name the same file: the included results are read before it is rewritten
"$kmr" audit --quick --only 'L3.4.4$' --json "$tmp/same.json" >/dev/null 2>&1 &&
  "$kmr" audit --quick --only 'L3.4.4$' --include "$tmp/same.json" --json "$tmp/same.json" >/dev/null 2>&1
[ $? -eq 0 ] && [ "$(grep -o '"claim":"L3.4.4"' "$tmp/same.json" | wc -l)" -eq 2 ] && ok || bad "--include F --json F lost results"
v=$("$kmr" --version) && [[ "$v" =~ ^kmr\ [0-9]+\.[0-9]+ ]] && ok || bad "kmr --version printed '$v'"
"$kmr" audit --report /proc/nonexistent/x --only L3.4.4 --quick >/dev/null 2>"$tmp/err"
[ $? -eq 2 ] && grep -q "cannot create report directory" "$tmp/err" && ok || bad "unwritable --report: $(cat "$tmp/err")"
finish "report_test"
