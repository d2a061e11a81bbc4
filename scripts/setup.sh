#!/usr/bin/env bash
# Shared set-up for ./run and ./test: install what is missing (Debian 12), configure, build.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

packages=(cmake g++ make pkg-config libvtk9-dev libvtk9-qt-dev qtbase5-dev libopenimageio-dev
  openimageio-tools libglm-dev libgtest-dev libbenchmark-dev xvfb xauth libgl1-mesa-dri
  blender-data nlohmann-json3-dev libtinygltf-dev libocct-data-exchange-dev
  libocct-modeling-algorithms-dev libocct-ocaf-dev libocct-foundation-dev libocct-modeling-data-dev
  assimp-testmodels)

. "$root/scripts/packages.sh"
aniso_install_packages "${packages[@]}"

build="${ANISO_BUILD_DIR:-$root/build}"
jobs="$(nproc 2>/dev/null || echo 2)"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE="${ANISO_BUILD_TYPE:-Release}" >/dev/null
cmake --build "$build" -j "$jobs"
