#!/usr/bin/env bash
# Wrong command lines of every kmr command (issue 13 §2 and §7): a missing or extra FILE, a missing
# required option, an option that does not apply, an empty window, the zero polynomial, an output
# file or directory that cannot be created, an unknown subcommand or program. Each must end with
# exit status 2 and the message written here (hand-written expectations, one per case), never an
# internal error; bad file contents are bad_input_test.sh's.
# Usage: usage_errors_test.sh path/to/kmr
set -u
kmr=$1
source "$(dirname "$0")/lib.sh"  # $tmp, ok, bad, expect_error, finish
expect_timeout=120
printf '0.25 0.25\n0.75 0.5\n' >"$tmp/ws"
printf '0 0 0\n1 0 0\n0 1 0\n0 0 1\n' >"$tmp/xyz"
: >"$tmp/file"              # a regular file: nothing can be created under it
nodir=$tmp/file/sub         # so every path under it is unwritable, whatever the user's rights

expect_error audit_positional "kmr audit takes no positional argument" -- audit extra
expect_error audit_json "cannot write --json file '$nodir/a.json'" -- audit --quick --only 'A2.1-next-failure$' --json "$nodir/a.json"
expect_error audit_report "cannot create report directory '$nodir'" -- audit --quick --only 'A2.1-next-failure$' --report "$nodir"
expect_error bench_positional "kmr bench sac takes no positional argument" -- bench sac extra
expect_error bench_program "kmr bench sac: unknown --program" -- bench sac --program nope
expect_error bench_subcommand "kmr bench: unknown subcommand 'frob'" -- bench frob
expect_error hull_missing "cannot open '$tmp/missing'" -- hull "$tmp/missing"
expect_error hull_stats "cannot write '$nodir/s.json'" -- hull "$tmp/xyz" --stats "$nodir/s.json"
expect_error kmesh_none "kmr kmesh needs exactly one input FILE" -- kmesh
expect_error kmesh_two "kmr kmesh needs exactly one input FILE" -- kmesh "$tmp/ws" "$tmp/ws"
expect_error roots_none "no coefficients given (usage: kmr roots -- c0 c1 ... cn)" -- roots
expect_error roots_zero "the zero polynomial has no isolated roots" -- roots -- 0 0 0
expect_error roots_window "empty window: --from 1 is not below --to 1" -- roots --from 1 --to 1 -- 1 1
expect_error roots_window_reversed "empty window: --from 2 is not below --to -2" -- roots --from 2 --to -2 -- 1 1
expect_error sort_two "kmr simulate sort takes exactly one FILE" -- simulate sort "$tmp/ws" "$tmp/ws"
expect_error sort_missing "cannot open '$tmp/missing'" -- simulate sort "$tmp/missing"
expect_error hull_sim_two "kmr simulate hull takes exactly one FILE" -- simulate hull "$tmp/ws" "$tmp/ws"
expect_error hull_sim_missing "cannot open '$tmp/missing'" -- simulate hull "$tmp/missing"
expect_error ws_none "kmr wellspaced needs exactly one INPUT file" -- wellspaced
expect_error ws_no_dim "--dim D is required (2, 3 or 4)" -- wellspaced "$tmp/ws"
expect_error ws_svg_3d "--svg draws 2D outputs only (use --dim 2)" -- wellspaced --dim 3 --svg "$tmp/o.svg" "$tmp/ws"
expect_error ws_stats "cannot write --stats file '$nodir/s.json'" -- wellspaced --dim 2 --stats "$nodir/s.json" "$tmp/ws"
# Nothing was written where it could not be (and no stray output file appeared for the 3D --svg).
[ ! -e "$tmp/o.svg" ] && passed=$((passed+1)) || { failed=$((failed+1)); echo "FAIL ws_svg_3d: wrote $tmp/o.svg"; }
finish "usage errors"
