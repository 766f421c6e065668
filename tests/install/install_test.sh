#!/usr/bin/env bash
# The installable package: `cmake --install BUILD --prefix P`, then a project outside kmr
# (tests/install/consumer) configures with find_package(kmr), builds against kmr::wellspaced and
# kmr::kinetic, and runs; the installed kmr executable answers --version.
# Usage: install_test.sh BUILD_DIR CONSUMER_SOURCE_DIR
set -eu
build=$1 consumer=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" >"$tmp/install.log"
test -x "$tmp/prefix/bin/kmr"
test -f "$tmp/prefix/include/kmr/wellspaced/well_spaced_set.hpp"
"$tmp/prefix/bin/kmr" --version | grep -q '^kmr '
# the exported targets find GMP on the consumer's machine, not at this build's absolute path
targets=$(find "$tmp/prefix" -name kmrTargets.cmake)
if grep -n 'libgmp' "$targets"; then echo "kmrTargets.cmake names this machine's GMP library"; exit 1; fi
gen=()
command -v ninja >/dev/null && gen=(-G Ninja)
# every layer folder of src/ (cli is the executable) is exported as kmr::<folder> with its headers,
# whether it was made with kmr_layer() or by hand (a later hull or kmesh included)
src=$(cd "$consumer/../../../src" && pwd)
layers=$(cd "$src" && for d in */; do d=${d%/}; [ "$d" != cli ] && [ -f "$d/CMakeLists.txt" ] && echo "$d"; done | paste -sd ";")
for l in ${layers//;/ }; do
  ls "$src/$l"/*.hpp >/dev/null 2>&1 || continue
  for h in "$src/$l"/*.hpp; do test -f "$tmp/prefix/include/kmr/$l/$(basename "$h")" || { echo "not installed: $l/$(basename "$h")"; exit 1; }; done
done
cmake -S "$consumer" -B "$tmp/build" "${gen[@]}" -DCMAKE_PREFIX_PATH="$tmp/prefix" -DCMAKE_BUILD_TYPE=Release \
  "-DCMAKE_CXX_FLAGS=${KMR_CONSUMER_CXX_FLAGS:-}" "-DCMAKE_EXE_LINKER_FLAGS=${KMR_CONSUMER_LINKER_FLAGS:-}" \
  "-DKMR_LAYERS=$layers" >"$tmp/configure.log" ||
  { cat "$tmp/configure.log"; exit 1; }
cmake --build "$tmp/build" >"$tmp/build.log" || { cat "$tmp/build.log"; exit 1; }
out=$("$tmp/build/consumer")
echo "$out"
echo "$out" | grep -q '^wellspaced ok [0-9]'
echo "$out" | grep -q '^kinetic ok 1$'
