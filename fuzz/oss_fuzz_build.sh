#!/usr/bin/env bash
# Builds every fuzz harness under the OSS-Fuzz build contract (also ClusterFuzzLite's):
# honours $CC, $CXX, $CFLAGS, $CXXFLAGS (sanitizer and coverage flags, incl. -fsanitize=fuzzer-no-link),
# $LIB_FUZZING_ENGINE (what a harness links instead of a main, e.g. -fsanitize=fuzzer) and $OUT
# (where the harnesses go). For each harness NAME it writes $OUT/NAME_fuzzer, its seed corpus
# $OUT/NAME_fuzzer_seed_corpus.zip (fuzz/corpus/NAME) and, if present, $OUT/NAME_fuzzer.dict.
# Build folder: $WORK/kmr-fuzz-build ($WORK as in OSS-Fuzz; a temporary folder when unset).
# Used by .clusterfuzzlite/build.sh and, locally with clang-14 + libFuzzer, by fuzz/build_libfuzzer.sh.
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
: "${CC:?set CC}" "${CXX:?set CXX}" "${OUT:?set OUT}" "${LIB_FUZZING_ENGINE:?set LIB_FUZZING_ENGINE}"
work=${WORK:-$(mktemp -d)}
build=$work/kmr-fuzz-build
mkdir -p "$OUT"
launcher=()
if command -v ccache >/dev/null 2>&1; then
  export CCACHE_BASEDIR="$src"
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
# Build type None: the contract's flags alone set the optimisation (Release would append -O3 to them).
cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=None "${launcher[@]}" \
  -DCMAKE_C_COMPILER="$CC" -DCMAKE_CXX_COMPILER="$CXX" -DCMAKE_C_FLAGS="${CFLAGS:-}" -DCMAKE_CXX_FLAGS="${CXXFLAGS:-}" \
  -DKMR_FUZZ=ON -DKMR_FUZZ_ENGINE="$LIB_FUZZING_ENGINE" -DKMR_TESTS=OFF -DKMR_ORACLES=OFF -DKMR_BENCH=OFF >/dev/null
cmake --build "$build" -j "$(nproc)" --target kmr_fuzzers
for f in "$build"/fuzz-bin/*_fuzzer; do
  name=$(basename "$f" _fuzzer)
  cp "$f" "$OUT/"
  rm -f "$OUT/${name}_fuzzer_seed_corpus.zip"
  (cd "$src/fuzz/corpus/$name" && zip -q -r "$OUT/${name}_fuzzer_seed_corpus.zip" .)
  if [[ -f $src/fuzz/$name.dict ]]; then cp "$src/fuzz/$name.dict" "$OUT/${name}_fuzzer.dict"; fi
done
