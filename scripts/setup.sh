#!/usr/bin/env bash
# Shared set-up for ./run and ./test: install what is missing (Debian 12), configure, build.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

. "$root/scripts/packages.sh"
aniso_install_packages "${ANISO_PACKAGES[@]}"

build="${ANISO_BUILD_DIR:-$root/build}"
# ParaView's Python for the plugin (paraview/CMakeLists.txt), unpacked beside the build.
aniso_unpack_package python3-paraview "$build/paraview/python3-paraview"
jobs="$(nproc 2>/dev/null || echo 2)"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE="${ANISO_BUILD_TYPE:-Release}" >/dev/null
cmake --build "$build" -j "$jobs"
