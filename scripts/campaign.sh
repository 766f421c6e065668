#!/usr/bin/env bash
# Property-test campaign: every RapidCheck property (ctest label `prop`) with many seeds and larger
# max_success / max_size than CI's, sharded the GoogleTest way so a CI matrix can split it.
# Usage: scripts/campaign.sh [--seeds N] [--first-seed S] [--max-success M] [--max-size Z]
#                            [--filter GTEST_FILTER] [--build DIR]
# Sharding: set GTEST_TOTAL_SHARDS and GTEST_SHARD_INDEX (GoogleTest's own variables) in each job;
# every binary then runs only its shard of the properties, for every seed. E.g. 4 machines:
#   GTEST_TOTAL_SHARDS=4 GTEST_SHARD_INDEX=$i scripts/campaign.sh --seeds 50 --max-success 2000
# Every failure prints the test, its seed and the exact replay command; exit 1 if any failed.
# Defaults: 20 seeds from 1, max_success 1000, max_size 200 (CI: seed 20121, max_success 100,
# RapidCheck's default max_size 100). Properties that cap their cases for CI (proptests/check_cases.hpp)
# scale those caps by max_success/100 and max_size/100 here (KMR_CAMPAIGN=1). Build first with
# scripts/build.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
seeds=20 first=1 max_success=1000 max_size=200 filter='*' dir=build
while (($#)); do
  case $1 in
    --seeds) seeds=$2; shift 2 ;;
    --first-seed) first=$2; shift 2 ;;
    --max-success) max_success=$2; shift 2 ;;
    --max-size) max_size=$2; shift 2 ;;
    --filter) filter=$2; shift 2 ;;
    --build) dir=$2; shift 2 ;;
    *) echo "campaign.sh: unknown option '$1' (see the header of scripts/campaign.sh)" >&2; exit 2 ;;
  esac
done
[[ $seeds =~ ^[0-9]+$ && $first =~ ^[0-9]+$ && $max_success =~ ^[0-9]+$ && $max_size =~ ^[0-9]+$ ]] || {
  echo "campaign.sh: --seeds, --first-seed, --max-success and --max-size take non-negative integers" >&2; exit 2; }
# The property binaries: every executable ctest runs under label prop.
mapfile -t bins < <(ctest --test-dir "$dir" -L prop -N -V 2>/dev/null | sed -n 's/^[0-9]*: Test command: \([^ ]*\).*/\1/p' | sort -u)
for i in "${!bins[@]}"; do [[ -x ${bins[$i]} ]] || unset 'bins[i]'; done
bins=("${bins[@]}")
((${#bins[@]})) || { echo "campaign.sh: no property tests in $dir (build with scripts/build.sh first)" >&2; exit 2; }
shards=${GTEST_TOTAL_SHARDS:-1} shard=${GTEST_SHARD_INDEX:-0}
echo "campaign: ${#bins[@]} property binaries, seeds $first..$((first + seeds - 1)), max_success=$max_success max_size=$max_size, shard $shard of $shards"
log=$(mktemp)
trap 'rm -f "$log"' EXIT
failures=0 runs=0
for ((seed = first; seed < first + seeds; ++seed)); do
  params="seed=$seed max_success=$max_success max_size=$max_size verbose_progress=0"
  for bin in "${bins[@]}"; do
    runs=$((runs + 1))
    if KMR_CAMPAIGN=1 RC_PARAMS="$params" "$bin" --gtest_filter="$filter" >"$log" 2>&1; then continue; fi
    mapfile -t failed < <(sed -n 's/^\[  FAILED  \] \([^ ,]*\).*/\1/p' "$log" | grep -v 'listed below' | grep '\.' | sort -u)
    ((${#failed[@]})) || failed=("(whole binary: exit status, see output)")
    for t in "${failed[@]}"; do
      failures=$((failures + 1))
      echo "FAIL $t  seed=$seed"
      echo "  replay: KMR_CAMPAIGN=1 RC_PARAMS=\"$params\" $bin --gtest_filter='$t'"
    done
    grep -E 'Falsifiable|reproduce=' "$log" | sed 's/^/  /' || true
  done
done
echo "campaign: $runs binary runs, $failures failing (test, seed) pairs"
((failures == 0))
