#!/usr/bin/env bash
# Builds the libFuzzer harnesses with clang-14 through the OSS-Fuzz build contract
# (fuzz/oss_fuzz_build.sh with CC, CXX, CFLAGS, CXXFLAGS, LIB_FUZZING_ENGINE, OUT set as OSS-Fuzz
# would for libFuzzer + ASan + UBSan), into BUILD_DIR (harnesses in BUILD_DIR/bin), then checks what
# it produced: every harness of LIST (default: all fuzz/*_fuzzer.cpp) is there with its seed-corpus
# zip, and runs over its whole seed corpus (-runs=0) without a finding.
# Usage: fuzz/build_libfuzzer.sh SOURCE_DIR BUILD_DIR [CLANGXX]   (used by ctest and fuzz/run.sh)
set -euo pipefail
src=$1 dir=$2 cxx=${3:-clang++-14}
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
flags="-O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=undefined -fsanitize=fuzzer-no-link"
CC=${cxx/clang++/clang} CXX=$cxx CFLAGS=$flags CXXFLAGS=$flags LIB_FUZZING_ENGINE=-fsanitize=fuzzer \
  OUT=$dir/bin WORK=$dir bash "$src/fuzz/oss_fuzz_build.sh"
status=0
# The contract's flags are the compiler's flags: no kmr source is compiled with an optimisation level
# of its own on top of them (a CMake build type would append one, e.g. Release's -O3).
commands=$dir/kmr-fuzz-build/compile_commands.json
if [[ ! -s $commands ]]; then
  echo "build_libfuzzer: no $commands to check the flags against" >&2
  status=1
elif grep -qE '"command": .* -O([0-9sgz]|fast) .* -O([0-9sgz]|fast) ' "$commands"; then
  echo "build_libfuzzer: a compile adds an optimisation level to CXXFLAGS ($commands)" >&2
  status=1
fi
for cpp in "$src"/fuzz/*_fuzzer.cpp; do
  name=$(basename "$cpp" _fuzzer.cpp)
  bin=$dir/bin/${name}_fuzzer
  if [[ ! -x $bin || ! -s $dir/bin/${name}_fuzzer_seed_corpus.zip ]]; then
    echo "build_libfuzzer: missing $bin or its seed corpus zip" >&2; status=1; continue
  fi
  if ! "$bin" -runs=0 "$src/fuzz/corpus/$name" >"$dir/check-$name.log" 2>&1; then
    echo "build_libfuzzer: $name fails on its own seed corpus:" >&2; tail -20 "$dir/check-$name.log" >&2; status=1
  fi
done
exit $status
