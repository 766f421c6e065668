#!/usr/bin/env bash
# The test command: installs what is missing, builds, and runs the default ctest suite
# (labels unit, prop, oracle, fuzz, audit). Long campaigns are opt-in (see README).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j 2 --timeout 900
