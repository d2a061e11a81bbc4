#!/usr/bin/env bash
# Shared set-up for ./run and ./test: install what is missing (Debian 12), configure, build.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

packages=(cmake g++ make pkg-config libvtk9-dev libvtk9-qt-dev qtbase5-dev libopenimageio-dev
  openimageio-tools libglm-dev libgtest-dev libbenchmark-dev xvfb xauth libgl1-mesa-dri
  blender-data)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -gt 0 ]; then
  if [ "$(id -u)" -eq 0 ]; then
    echo "aniso: installing missing packages: ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  else
    echo "aniso: missing Debian packages: ${missing[*]}" >&2
    echo "aniso: install them with: sudo apt-get install ${missing[*]}" >&2
    exit 1
  fi
fi

build="${ANISO_BUILD_DIR:-$root/build}"
jobs="$(nproc 2>/dev/null || echo 2)"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE="${ANISO_BUILD_TYPE:-Release}" >/dev/null
cmake --build "$build" -j "$jobs"
