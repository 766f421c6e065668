# Sourced by every CLI test after it sets $kmr (and its other arguments): a scratch folder $tmp
# removed on exit, the pass/fail counters and their helpers.
#   ok / bad MESSAGE...                     count a pass / a failure (printed as "FAIL MESSAGE")
#   expect_error NAME STDERR_SUBSTRING -- ARGS...
#                                           runs "$kmr" ARGS (within ${expect_timeout:-60} s); a pass
#                                           when it exits 2 with STDERR_SUBSTRING on stderr and no
#                                           internal error
#   finish NAME                             prints the counts; the script's status: no failure and
#                                           at least one check run
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0 failed=0
ok() { passed=$((passed+1)); }
bad() { failed=$((failed+1)); echo "FAIL $*"; }
expect_error() {
  local name=$1 want=$2; shift 3
  timeout "${expect_timeout:-60}" "$kmr" "$@" >"$tmp/out" 2>"$tmp/err"; local rc=$?
  if [ $rc -eq 2 ] && grep -qF -- "$want" "$tmp/err" && ! grep -q 'internal error' "$tmp/err"; then ok; else
    bad "$name: rc=$rc (want 2 and '$want'), stderr: $(head -c 400 "$tmp/err")"; fi
}
finish() {
  echo "$1: $passed passed, $failed failed"
  [ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]
}
