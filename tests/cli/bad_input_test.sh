#!/usr/bin/env bash
# Bad input for every option and file format of every kmr command (spec/formats.md): each must end
# with exit status 2 and a message naming the problem; the accepted variants (CRLF, hex floats,
# comments, leading '+', exponents in dyadics) must give the same answer as the plain form.
# Usage: bad_input_test.sh path/to/kmr
set -u
kmr=$1
source "$(dirname "$0")/lib.sh"  # $tmp, ok, bad, expect_error, finish
expect_same() {  # expect_same NAME -- ARGS_A... :: ARGS_B...   (both exit 0 with equal stdout)
  local name=$1; shift 2
  local a=() b=()
  while [ "$1" != "::" ]; do a+=("$1"); shift; done; shift; b=("$@")
  local oa ob; oa=$(timeout 60 "$kmr" "${a[@]}" 2>&1); local ra=$?; ob=$(timeout 60 "$kmr" "${b[@]}" 2>&1); local rb=$?
  if [ $ra -eq 0 ] && [ $rb -eq 0 ] && [ "$oa" = "$ob" ]; then passed=$((passed+1)); else
    failed=$((failed+1)); echo "FAIL $name: rc $ra/$rb"; echo "  a: ${oa:0:300}"; echo "  b: ${ob:0:300}"; fi
}
f=$tmp
: >"$f/empty"
printf '\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR\x00\x00\x00\x10\x00\x00\x00\x10\x08\x06' >"$f/binary"
python3 -c "print(' '.join(['0.5'] * 200000))" >"$f/longline"

# --- kmr wellspaced: INPUT (D coordinates in [0,1] per line) -------------------------------------
printf '0.25 0.25\n0.75 0.5\n' >"$f/ws"
printf '0.25 0.25\r\n0.75 0.5\r\n' >"$f/ws_crlf"
printf '0x1p-2 0.25  # hex float\n0.75 0x1.0p-1\n' >"$f/ws_hex"
printf '0.25 0.25\n0.75 0.5\n\n# comment only\n' >"$f/ws_comments"
printf '0.25\x00 0.25\n0.75 0.5\n' >"$f/ws_nul"
printf '1e400 0.25\n0.75 0.5\n' >"$f/ws_huge"
printf '1e-400 0.25\n0.75 0.5\n' >"$f/ws_under"
printf 'nan 0.25\n0.75 0.5\n' >"$f/ws_nan"
printf 'inf 0.25\n0.75 0.5\n' >"$f/ws_inf"
printf '1.0000001 0.25\n0.75 0.5\n' >"$f/ws_out"
printf -- '-0.1 0.25\n0.75 0.5\n' >"$f/ws_neg"
printf '0.25 0.25 0.25\n0.75 0.5\n' >"$f/ws_arity"
printf '0.25 0.25\n0.75 0.5\n0.25 0.25\n' >"$f/ws_dup"
printf '0.25 0.25\n' >"$f/ws_one"
printf '0.25 zero\n0.75 0.5\n' >"$f/ws_word"
printf '0.25 0.25,\n0.75 0.5\n' >"$f/ws_comma"
expect_same ws-crlf -- wellspaced --dim 2 "$f/ws" :: wellspaced --dim 2 "$f/ws_crlf"
expect_same ws-hex -- wellspaced --dim 2 "$f/ws" :: wellspaced --dim 2 "$f/ws_hex"
expect_same ws-comments -- wellspaced --dim 2 "$f/ws" :: wellspaced --dim 2 "$f/ws_comments"
expect_error ws-empty "at least 2 input points" -- wellspaced --dim 2 "$f/empty"
expect_error ws-binary "binary:1:" -- wellspaced --dim 2 "$f/binary"
expect_error ws-longline "longline:1: expected 2 coordinates, got 200000" -- wellspaced --dim 2 "$f/longline"
expect_error ws-nul "ws_nul:1: '0.25\\x00' is not a number" -- wellspaced --dim 2 "$f/ws_nul"
expect_error ws-huge "ws_huge:1: '1e400' is not finite" -- wellspaced --dim 2 "$f/ws_huge"
expect_error ws-underflow "ws_under:1: '1e-400' underflows to 0" -- wellspaced --dim 2 "$f/ws_under"
expect_error ws-nan "ws_nan:1: 'nan' is not finite" -- wellspaced --dim 2 "$f/ws_nan"
expect_error ws-inf "ws_inf:1: 'inf' is not finite" -- wellspaced --dim 2 "$f/ws_inf"
expect_error ws-outside "ws_out:1: coordinate '1.0000001' is outside [0,1]" -- wellspaced --dim 2 "$f/ws_out"
expect_error ws-negative "ws_neg:1: coordinate '-0.1' is outside [0,1]" -- wellspaced --dim 2 "$f/ws_neg"
expect_error ws-arity "ws_arity:1: expected 2 coordinates, got 3" -- wellspaced --dim 2 "$f/ws_arity"
expect_error ws-dup "ws_dup:3: duplicate point" -- wellspaced --dim 2 "$f/ws_dup"
expect_error ws-one "at least 2 input points" -- wellspaced --dim 2 "$f/ws_one"
expect_error ws-word "ws_word:1: 'zero' is not a number" -- wellspaced --dim 2 "$f/ws_word"
expect_error ws-comma "ws_comma:1: '0.25,' is not a number" -- wellspaced --dim 2 "$f/ws_comma"
expect_error ws-missing "cannot read file" -- wellspaced --dim 2 "$f/does-not-exist"
expect_error ws-directory "" -- wellspaced --dim 2 "$f"
# options
expect_error ws-no-dim "--dim D is required" -- wellspaced "$f/ws"
expect_error ws-dim-1 "--dim 1 is out of range [2, 4]" -- wellspaced --dim 1 "$f/ws"
expect_error ws-dim-5 "--dim 5 is out of range [2, 4]" -- wellspaced --dim 5 "$f/ws"
expect_error ws-dim-huge "is out of range [2, 4]" -- wellspaced --dim 99999999999999999999999 "$f/ws"
expect_error ws-dim-word "not an integer" -- wellspaced --dim two "$f/ws"
expect_error ws-dim-twice "option --dim is given twice" -- wellspaced --dim 2 --dim 3 "$f/ws"
expect_error ws-rho-1 "--rho must be > 1" -- wellspaced --dim 2 --rho 1 "$f/ws"
expect_error ws-rho-below "--rho must be > 1" -- wellspaced --dim 2 --rho 0.5 "$f/ws"
expect_error ws-rho-nan "--rho: 'nan' is not finite" -- wellspaced --dim 2 --rho nan "$f/ws"
expect_error ws-rho-huge "beta" -- wellspaced --dim 2 --rho 1e308 "$f/ws"
expect_error ws-rho-word "--rho: 'x' is not a number" -- wellspaced --dim 2 --rho x "$f/ws"
expect_error ws-beta-at-rho "--beta must be > --rho" -- wellspaced --dim 2 --rho 2 --beta 2 "$f/ws"
expect_error ws-beta-inf "--beta: 'inf' is not finite" -- wellspaced --dim 2 --beta inf "$f/ws"
expect_error ws-two-inputs "exactly one INPUT" -- wellspaced --dim 2 "$f/ws" "$f/ws"
expect_error ws-no-input "exactly one INPUT" -- wellspaced --dim 2
expect_error ws-unknown "unknown option '--frob'" -- wellspaced --dim 2 --frob "$f/ws"
expect_error ws-value-missing "option --rho needs a value" -- wellspaced --dim 2 "$f/ws" --rho
expect_error ws-stats-unwritable "cannot write --stats file" -- wellspaced --dim 2 --stats "$f/no/such/dir/s.json" "$f/ws"
# --updates FILE ('+'/'-' then D coordinates)
printf '+ 0.5 0.75\n' >"$f/up"
printf '+ 0.5 0.75\r\n' >"$f/up_crlf"
printf '* 0.5 0.75\n' >"$f/up_op"
printf '+0.5 0.75\n' >"$f/up_glued"
printf '+ 0.5\n' >"$f/up_arity"
printf '+ 0.25 0.25\n' >"$f/up_present"
printf -- '- 0.5 0.5\n' >"$f/up_absent"
printf -- '- 0.25 0.25\n' >"$f/up_toofew"
printf '+ 0.5 0.75\n+ 0.5 0.75\n' >"$f/up_twice"
printf '+ 0.5\x00 0.75\n' >"$f/up_nul"
expect_same up-crlf -- wellspaced --dim 2 --updates "$f/up" "$f/ws" :: wellspaced --dim 2 --updates "$f/up_crlf" "$f/ws"
expect_same up-empty -- wellspaced --dim 2 "$f/ws" :: wellspaced --dim 2 --updates "$f/empty" "$f/ws"
expect_error up-op "up_op:1: a line must start with '+' or '-'" -- wellspaced --dim 2 --updates "$f/up_op" "$f/ws"
expect_error up-glued "up_glued:1: a line must start with '+' or '-'" -- wellspaced --dim 2 --updates "$f/up_glued" "$f/ws"
expect_error up-arity "up_arity:1: expected 2 coordinates, got 1" -- wellspaced --dim 2 --updates "$f/up_arity" "$f/ws"
expect_error up-present "up_present:1: inserting a point that is already in the input" -- wellspaced --dim 2 --updates "$f/up_present" "$f/ws"
expect_error up-absent "up_absent:1: deleting a point that is not in the input" -- wellspaced --dim 2 --updates "$f/up_absent" "$f/ws"
expect_error up-toofew "up_toofew:1: fewer than 2 input points would remain" -- wellspaced --dim 2 --updates "$f/up_toofew" "$f/ws"
expect_error up-twice "up_twice:2: inserting a point that is already in the input" -- wellspaced --dim 2 --updates "$f/up_twice" "$f/ws"
expect_error up-nul "up_nul:1: '0.5\\x00' is not a number" -- wellspaced --dim 2 --updates "$f/up_nul" "$f/ws"
expect_error up-binary "binary:1:" -- wellspaced --dim 2 --updates "$f/binary" "$f/ws"
expect_error up-missing "cannot read file" -- wellspaced --dim 2 --updates "$f/does-not-exist" "$f/ws"

# --- kmr simulate sort FILE ('x0 v' decimal integers per line) -----------------------------------
printf '0 1\n10 -1\n' >"$f/s"
printf '0 1\r\n10 -1\r\n' >"$f/s_crlf"
printf '+0 +1  # comment\n\n10 -1\n' >"$f/s_plus"
printf '0 1\n0 1\n' >"$f/s_dup"
printf '0 1\x00\n10 -1\n' >"$f/s_nul"
printf '0x10 1\n' >"$f/s_hex"
printf '1e3 1\n' >"$f/s_exp"
printf '0.5 1\n' >"$f/s_frac"
printf '0\n' >"$f/s_arity"
python3 -c "print('9' * 20000, 1); print(0, 1)" >"$f/s_hugenum"
expect_same sort-crlf -- simulate sort "$f/s" --until 8 :: simulate sort "$f/s_crlf" --until 8
expect_same sort-plus-comments -- simulate sort "$f/s" --until 8 :: simulate sort "$f/s_plus" --until 8
expect_error sort-empty "empty: no points" -- simulate sort "$f/empty"
expect_error sort-binary "binary:1:" -- simulate sort "$f/binary"
expect_error sort-longline "longline:1: expected 2 integers" -- simulate sort "$f/longline"
expect_error sort-dup "identical trajectories" -- simulate sort "$f/s_dup"
expect_error sort-nul "s_nul:1: not an integer" -- simulate sort "$f/s_nul"
expect_error sort-hex "s_hex:1: not an integer: '0x10'" -- simulate sort "$f/s_hex"
expect_error sort-exp "s_exp:1: not an integer: '1e3'" -- simulate sort "$f/s_exp"
expect_error sort-frac "s_frac:1: not an integer: '0.5'" -- simulate sort "$f/s_frac"
expect_error sort-arity "s_arity:1: expected 2 integers" -- simulate sort "$f/s_arity"
expect_error sort-missing "cannot open" -- simulate sort "$f/does-not-exist"
expect_error sort-until-neg "--until must be >= 0" -- simulate sort "$f/s" --until -1
expect_error sort-until-nondyadic "not a dyadic number: '0.3'" -- simulate sort "$f/s" --until 0.3
expect_error sort-until-offlattice "is not a multiple of the lattice step" -- simulate sort "$f/s" --until 0.5 --lattice-bits 0
expect_error sort-until-hex "not a dyadic number: '0x1'" -- simulate sort "$f/s" --until 0x1
expect_error sort-bits-63 "--lattice-bits 63 is out of range [0, 62]" -- simulate sort "$f/s" --lattice-bits 63
expect_error sort-bits-neg "--lattice-bits -1 is out of range [0, 62]" -- simulate sort "$f/s" --lattice-bits -1
expect_error sort-until-twice "option --until is given twice" -- simulate sort "$f/s" --until 1 --until 2
expect_error sort-structure "unknown structure 'frob' (known: sort, hull)" -- simulate frob "$f/s"
expect_error sort-two-files "exactly one FILE" -- simulate sort "$f/s" "$f/s"
expect_same sort-hugenum -- simulate sort "$f/s_hugenum" --until 1 :: simulate sort "$f/s_hugenum" --until 1

# --- kmr roots [--lattice-bits B] [--from T0] [--to T1] -- c0 ... cn -----------------------------
expect_same roots-plus -- roots -- -2 0 1 :: roots -- -2 +0 +1
expect_same roots-exponent-dyadic -- roots --from 1000 -- -2 0 1 :: roots --from 1e3 -- -2 0 1
expect_error roots-hex-coef "not an integer: '0x10'" -- roots -- 0x10 1
expect_error roots-exp-coef "not an integer: '1e3'" -- roots -- 1e3 1
expect_error roots-empty-coef "not an integer: ''" -- roots -- 1 ""
expect_error roots-nul-coef "not an integer" -- roots -- "$(printf '1\x01')" 1
expect_error roots-bits-neg "--lattice-bits -1 is out of range [0, 4096]" -- roots --lattice-bits -1 -- 1 1
expect_error roots-bits-big "--lattice-bits 4097 is out of range [0, 4096]" -- roots --lattice-bits 4097 -- 1 1
expect_error roots-from-hex "not a dyadic number: '0x10'" -- roots --from 0x10 -- 1 1
expect_error roots-from-twice "option --from is given twice" -- roots --from 0.5 --from 0.25 -- 1 1
expect_error roots-from-missing "option --from needs a value" -- roots --from
# --- kmr simulate hull FILE ('x y z vx vy vz' decimal integers per line) ---------------------------
printf '0 0 0 1 0 0\n10 0 0 0 1 0\n0 10 0 0 0 1\n0 0 10 1 1 1\n3 3 3 -1 2 0\n' >"$f/h"
printf '0 0 0 1 0 0\r\n10 0 0 0 1 0\r\n0 10 0 0 0 1\r\n0 0 10 1 1 1\r\n3 3 3 -1 2 0\r\n' >"$f/h_crlf"
printf '0 0 0 1 0 0\n10 0 0 0 1 0\n0 10 0 0 0 1\n0 0 10 1 1 1\n0 0 0 1 0 0\n' >"$f/h_dup"
printf '0 0 0 1 0 0\n10 0 0 0 1 0\n0 10 0 1 1 0\n5 5 0 0 0 0\n' >"$f/h_flat"
printf '0 0 0 1 0 0\n10 0 0 0 1 0\n0 10 0 1 1 0\n5 5 0 0 0 0\n1 1 10 0 0 1\n2 3 -10 0 0 0\n' >"$f/h_coplanar4"
printf '0 0 0 1 0\n' >"$f/h_arity"
expect_same hull-crlf -- simulate hull "$f/h" --until 8 :: simulate hull "$f/h_crlf" --until 8
expect_error hull-empty "empty: no points" -- simulate hull "$f/empty"
expect_error hull-arity "h_arity:1: expected 6 integers" -- simulate hull "$f/h_arity"
expect_error hull-dup "points 0 and 4 have identical trajectories" -- simulate hull "$f/h_dup"
expect_error hull-flat "stay coplanar for all time" -- simulate hull "$f/h_flat"
expect_error hull-coplanar4 "points 0, 1, 2 and 3 stay coplanar for all time" -- simulate hull "$f/h_coplanar4" --until 1
expect_error hull-until-offlattice "is not a multiple of the lattice step" -- simulate hull "$f/h" --until 0.5 --lattice-bits 0
expect_error roots-empty-window "empty window" -- roots --from 2 --to 2 -- 1 1
expect_error roots-zero "zero polynomial" -- roots -- 0 0 0
expect_error roots-no-coefs "no coefficients" -- roots --

# --- kmr kmesh FILE ('x y' or 'x y vx vy' decimal integers) [--updates 'T ± x y vx vy'] -----------
printf '0 0\n3 1\n1 5\n' >"$f/km"
printf '0 0\r\n3 1\r\n1 5\r\n' >"$f/km_crlf"
printf '# three points\n0 0 0 0\n\n3 1 # at rest\n+1 5 0 -0\n' >"$f/km_comments"
printf '0 0\n1\x00 2\n' >"$f/km_nul"
printf '7 7\n' >"$f/km_one"
printf '0 0 1 0\n' >"$f/km_moving"
printf '0 + 4 0 0 0\n' >"$f/kmu_collide"
printf '1 + 9 9 0 0\n' >"$f/kmu_late"
printf '0 + 3 1 0 0\n' >"$f/kmu_present"
printf '0 - 7 7 0 0\n' >"$f/kmu_last"
printf -- '-1 + 9 9 0 0\n' >"$f/kmu_neg"
printf '0\x00 + 9 9 0 0\n' >"$f/kmu_nul"
printf '0 - 3 1 0 0\n0.5 + 3 1 0 0\n' >"$f/kmu_again"
expect_same kmesh-crlf -- kmesh "$f/km" :: kmesh "$f/km_crlf"
expect_same kmesh-comments -- kmesh "$f/km" :: kmesh "$f/km_comments"
expect_error kmesh-no-file "kmr kmesh needs exactly one input FILE" -- kmesh
expect_error kmesh-two-files "kmr kmesh needs exactly one input FILE" -- kmesh "$f/km" "$f/km"
expect_error kmesh-missing "cannot read file '$f/nope'" -- kmesh "$f/nope"
expect_error kmesh-empty "no input point" -- kmesh "$f/empty"
expect_error kmesh-binary "binary:1: expected 'x y' or 'x y vx vy'" -- kmesh "$f/binary"
expect_error kmesh-nul "km_nul:2: '1\\x00' is not a decimal integer" -- kmesh "$f/km_nul"
expect_error kmesh-long-line "longline:1: expected 'x y' or 'x y vx vy'" -- kmesh "$f/longline"
expect_error kmesh-bits-big "--lattice-bits 63 is out of range [0, 62]" -- kmesh "$f/km" --lattice-bits 63
expect_error kmesh-bits-neg "--lattice-bits -1 is out of range [0, 62]" -- kmesh "$f/km" --lattice-bits -1
expect_error kmesh-until-neg "--until: time -1 is negative" -- kmesh "$f/km" --until -1
expect_error kmesh-until-text "--until: 'abc' is not a dyadic decimal time" -- kmesh "$f/km" --until abc
expect_error kmesh-unknown-option "unknown option '--bogus'" -- kmesh "$f/km" --bogus
expect_error kmesh-stats-unwritable "cannot write --stats file '$f/no/dir/s.json'" -- kmesh "$f/km" --stats "$f/no/dir/s.json"
expect_error kmesh-updates-missing "cannot read file '$f/nope'" -- kmesh "$f/km" --updates "$f/nope"
expect_error kmesh-update-late "kmu_late:1: update at time 1 is after --until 0" -- kmesh "$f/km" --updates "$f/kmu_late"
expect_error kmesh-update-present "kmu_present:1: inserts a trajectory that is already present" -- kmesh "$f/km" --updates "$f/kmu_present"
expect_error kmesh-update-last "kmu_last:1: deletes the last trajectory" -- kmesh "$f/km_one" --updates "$f/kmu_last"
expect_error kmesh-update-neg "kmu_neg:1: time -1 is negative" -- kmesh "$f/km" --updates "$f/kmu_neg" --until 1
expect_error kmesh-update-nul "kmu_nul:1: '0\\x00' is not a dyadic decimal time" -- kmesh "$f/km" --updates "$f/kmu_nul"
# (0,0) moving by (1,0) meets the inserted (4,0) at t = 4 (within --until 8); both places named.
expect_error kmesh-update-collides "kmu_collide:1 and $f/km_moving:1: the two points collide at time 4" -- kmesh "$f/km_moving" --updates "$f/kmu_collide" --until 8
# A collision at a time that is not dyadic is named exactly; one beyond the doubles (10^400) too.
printf '0 0 3 0\n1 0\n' >"$f/km_third"
expect_error kmesh-collides-third "km_third:2 and $f/km_third:1: the two points collide at time 1/3" -- kmesh "$f/km_third" --until 1
python3 -c "print('0 0 1 0'); print(10**400, 0)" >"$f/km_far_collision"
expect_error kmesh-collides-huge "km_far_collision:2 and $f/km_far_collision:1: the two points collide at time 1$(printf '0%.0s' $(seq 400)) (" -- kmesh "$f/km_far_collision" --until "1$(printf '0%.0s' $(seq 401))" --lattice-bits 0
# Nothing half-applied: a refused run writes no stdout and leaves no --stats or --svg file, also when
# the bad line comes after valid ones (a point file's line 2, an update file's line 2, a deletion of
# an absent trajectory, a collision).
printf '0 0\n1 2.5\n' >"$f/km4_bad2"
printf '0 + 9 9 0 0\n0.5 - 7 7 0 0\n' >"$f/kmu_absent"
printf '0 + 9 9 0 0\n0.5 + 9 9\n' >"$f/kmu_arity2"
nothing_written() {
  local name=$1; shift
  rm -f "$tmp/nw.json" "$tmp/nw.svg"
  timeout 60 "$kmr" kmesh "$@" --check --stats "$tmp/nw.json" --svg "$tmp/nw.svg" >"$tmp/nw.out" 2>"$tmp/err"; local rc=$?
  if [ $rc -eq 2 ] && [ ! -s "$tmp/nw.out" ] && [ ! -e "$tmp/nw.json" ] && [ ! -e "$tmp/nw.svg" ] && [ -s "$tmp/err" ]; then
    passed=$((passed+1)); else failed=$((failed+1)); echo "FAIL $name: rc=$rc, stdout $(wc -c <"$tmp/nw.out") bytes, files: $(ls "$tmp"/nw.json "$tmp"/nw.svg 2>/dev/null)"; fi
}
nothing_written kmesh-nothing-written-points "$f/km4_bad2"
nothing_written kmesh-nothing-written-updates "$f/km" --updates "$f/kmu_arity2" --until 1
nothing_written kmesh-nothing-written-absent "$f/km" --updates "$f/kmu_absent" --until 1
nothing_written kmesh-nothing-written-collision "$f/km_moving" --updates "$f/kmu_collide" --until 8
# Deleting a trajectory and inserting it again later is valid: the two lives do not overlap. The
# repaired mesh has the vertices and triangles of a from-scratch run (certificate counts may differ).
timeout 60 "$kmr" kmesh "$f/km" --updates "$f/kmu_again" --until 1 --lattice-bits 1 >"$tmp/again" 2>"$tmp/err"; ra=$?
timeout 60 "$kmr" kmesh "$f/km" --until 1 --lattice-bits 1 >"$tmp/scratch" 2>&1; rb=$?
if [ $ra -eq 0 ] && [ $rb -eq 0 ] && [ "$(sed 's/"events".*//' "$tmp/again")" = "$(sed 's/"events".*//' "$tmp/scratch")" ]; then passed=$((passed+1)); else
  failed=$((failed+1)); echo "FAIL kmesh-reinsert: rc $ra/$rb"; head -c 300 "$tmp/err"; echo; fi

# Updates at one time apply in file order: a trajectory deleted at 1/2 and then inserted again at
# 1/2 never coexists with itself (valid; the mesh of a run without updates), nor does one inserted
# after a deletion at the place the deleted point leaves; inserted before that deletion, the two
# points meet at 1/2.
printf '0.5 - 3 1 0 0\n0.5 + 3 1 0 0\n' >"$f/kmu_same_time"
printf '0.5 + 2 1 2 0\n0.5 - 3 1 0 0\n' >"$f/kmu_meet_first"
printf '0.5 - 3 1 0 0\n0.5 + 2 1 2 0\n' >"$f/kmu_meet_after"
timeout 60 "$kmr" kmesh "$f/km" --updates "$f/kmu_same_time" --until 1 --lattice-bits 1 --check >"$tmp/again" 2>"$tmp/err"; ra=$?
timeout 60 "$kmr" kmesh "$f/km" --until 1 --lattice-bits 1 >"$tmp/scratch" 2>&1; rb=$?
if [ $ra -eq 0 ] && [ $rb -eq 0 ] && [ "$(sed 's/"events".*//' "$tmp/again")" = "$(sed 's/"events".*//' "$tmp/scratch")" ]; then passed=$((passed+1)); else
  failed=$((failed+1)); echo "FAIL kmesh-reinsert-same-time: rc $ra/$rb"; head -c 300 "$tmp/err"; echo; fi
expect_error kmesh-meet-before-delete "kmu_meet_first:1 and $f/km:2: the two points collide at time 1/2" -- kmesh "$f/km" --updates "$f/kmu_meet_first" --until 1
timeout 60 "$kmr" kmesh "$f/km" --updates "$f/kmu_meet_after" --until 1 --lattice-bits 1 --check >/dev/null 2>"$tmp/err"
if [ $? -eq 0 ]; then passed=$((passed+1)); else failed=$((failed+1)); echo "FAIL kmesh-meet-after-delete"; head -c 300 "$tmp/err"; echo; fi

# --- kmr audit, kmr bench, kmr -------------------------------------------------------------------
expect_error audit-only-nothing "no claim matches --only 'ZZZ'" -- audit --only ZZZ
expect_error audit-json-unwritable "cannot write --json file" -- audit --quick --only A2.1-lattice --json "$f/no/such/dir/a.json"
expect_error audit-seed-neg "--seed -1 is out of range" -- audit --seed -1 --only A2.1
expect_error audit-positional "takes no positional argument" -- audit extra
expect_error bench-program "unknown --program" -- bench sac --program nope
expect_error bench-n-neg "--n -5 is out of range" -- bench sac --n -5
expect_error unknown-command "unknown command 'frob'" -- frob

# --- a run that fails after its --svg file was opened leaves no file behind ----------------------
printf '0 0 0\n1 0 0\n0 1 0\n1 1 0\n' >"$f/flat.xyz"
expect_error hull-svg-failed-run "all points are coplanar" -- hull "$f/flat.xyz" --svg "$f/flat.svg"
if [ -e "$f/flat.svg" ]; then failed=$((failed+1)); echo "FAIL hull-svg-failed-run: left $f/flat.svg behind"; else passed=$((passed+1)); fi

finish "bad input"
