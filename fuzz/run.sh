#!/usr/bin/env bash
# Runs a libFuzzer campaign. Usage: fuzz/run.sh NAME SECONDS [extra libFuzzer flags]
# NAME is one of the fuzz/<NAME>_fuzzer.cpp harnesses (figures of recorded runs: fuzz/campaigns.md). Builds build-fuzz/ with
# clang-14 and -DKMR_FUZZ=ON, then fuzzes with the seed corpus fuzz/corpus/NAME (read-only) and
# fuzz/NAME.dict if present; new inputs go to fuzz/out/NAME/, crashes to fuzz/out/NAME/crash-*.
set -euo pipefail
cd "$(dirname "$0")/.."
name=${1:?usage: fuzz/run.sh NAME SECONDS}
secs=${2:?usage: fuzz/run.sh NAME SECONDS}
shift 2
bash fuzz/build_libfuzzer.sh "$PWD" build-fuzz clang++-14
out=fuzz/out/$name
mkdir -p "$out"
dict=()
[[ -f fuzz/$name.dict ]] && dict=(-dict=fuzz/$name.dict)
# ASan keeps 2 frames (not 30) of each malloc's stack: the same findings, shorter allocation stacks in
# a report (replay a crash input with ASAN_OPTIONS=malloc_context_size=30 for full ones); sturm_count
# runs 1.8x the executions (user CPU 13.5-17.8 s -> 7.2-9.4 s for 200 inputs, interleaved, 3 rounds).
export ASAN_OPTIONS=${ASAN_OPTIONS:-malloc_context_size=2}
exec build-fuzz/bin/${name}_fuzzer "$out" fuzz/corpus/$name -max_total_time="$secs" -max_len=512 \
  -timeout=10 -artifact_prefix="$out/" -print_final_stats=1 "${dict[@]}" "$@"
