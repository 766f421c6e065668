#!/usr/bin/env bash
# Progress: on stderr when stderr is a terminal (a pseudo-terminal from `script`), never on stdout,
# never with --quiet, never when stderr is not a terminal.
# Usage: progress_test.sh path/to/kmr INPUT_2D
set -u
kmr=$1 input=$2
source "$(dirname "$0")/lib.sh"  # $tmp, ok, bad, expect_error, finish
on_tty() {  # on_tty TYPESCRIPT COMMAND...: stdout to $tmp/out, stderr on the pseudo-terminal
  local ts=$1; shift
  script -qec "$* >$tmp/out" "$ts" >/dev/null
}
check() {  # check NAME PATTERN ARGS...
  local name=$1 pattern=$2; shift 2
  on_tty "$tmp/ts" "$kmr" "$@"
  grep -qF -- "$pattern" "$tmp/ts" && ok || bad "$name: no progress '$pattern' on the terminal"
  grep -qF -- "$pattern" "$tmp/out" && bad "$name: progress on stdout" || ok
  on_tty "$tmp/ts" "$kmr" "$@" --quiet
  grep -qF -- "$pattern" "$tmp/ts" && bad "$name: progress despite --quiet" || ok
  "$kmr" "$@" >"$tmp/out" 2>"$tmp/err"
  [ -s "$tmp/err" ] && bad "$name: stderr not empty without a terminal" || ok
}
check audit "kmr audit [1/1] L3.4.4" audit --quick --only L3.4.4
check bench "kmr bench sac [1/7] map" bench sac --n 300 --edits 3
check wellspaced "kmr wellspaced: StableWS on" wellspaced --dim 2 "$input"
finish "progress_test"
