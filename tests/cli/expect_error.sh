# Sourced by the CLI tests: expect_error NAME STDERR_SUBSTRING -- ARGS... runs "$kmr" ARGS (within
# ${expect_timeout:-60} s) and counts a pass when it exits 2 with STDERR_SUBSTRING on stderr and no
# internal error. Needs $kmr, $tmp, $passed, $failed set by the caller.
expect_error() {
  local name=$1 want=$2; shift 3
  timeout "${expect_timeout:-60}" "$kmr" "$@" >"$tmp/out" 2>"$tmp/err"; local rc=$?
  if [ $rc -eq 2 ] && grep -qF -- "$want" "$tmp/err" && ! grep -q 'internal error' "$tmp/err"; then passed=$((passed+1)); else
    failed=$((failed+1)); echo "FAIL $name: rc=$rc (want 2 and '$want'), stderr:"; head -c 400 "$tmp/err"; echo; fi
}
