#!/usr/bin/env bash
# The main job: installs what is missing, builds, and runs `kmr audit` on built-in defaults.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
exec build/bin/kmr audit "$@"
