#!/usr/bin/env bash
# Configures and builds kmr in build/ (Release, tests included). Usage: scripts/build.sh [extra cmake args]
# Uses ccache when it is installed (optional; nothing depends on it).
set -euo pipefail
cd "$(dirname "$0")/.."
launcher=()
if command -v ccache >/dev/null 2>&1; then
  export CCACHE_BASEDIR="$PWD"  # relative paths: clones and worktrees share cache entries
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" "$@" >/dev/null
cmake --build build -j 2
