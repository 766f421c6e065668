#!/usr/bin/env bash
# Builds the libFuzzer harnesses with clang into a separate build dir.
# Usage: fuzz/build_libfuzzer.sh SOURCE_DIR BUILD_DIR [CLANGXX]   (used by ctest and fuzz/run.sh)
set -euo pipefail
src=$1 dir=$2 cxx=${3:-clang++-14}
cmake -S "$src" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$cxx" -DKMR_FUZZ=ON \
  -DKMR_TESTS=OFF -DKMR_ORACLES=OFF -DKMR_BENCH=OFF >/dev/null
cmake --build "$dir" -j 2 --target kmr_fuzzers
