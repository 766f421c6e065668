#!/usr/bin/env bash
# Installs every Debian package kmr needs, and only those missing. Idempotent.
set -euo pipefail
packages=(
  cmake ninja-build g++ make
  libboost-dev libgmp-dev libmpfr-dev libcgal-dev libeigen3-dev
  librapidcheck-dev libgtest-dev libgmock-dev libbenchmark-dev
  lcov clang-14 libclang-rt-14-dev llvm-14
  python3
  libxml2-utils
  libqhull-dev
  cmark-gfm
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
