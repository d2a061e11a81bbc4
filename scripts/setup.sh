#!/usr/bin/env bash
# Shared set-up for ./run and ./test: install what is missing (Debian 12), configure, build.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

. "$root/scripts/packages.sh"
aniso_install_packages "${ANISO_PACKAGES[@]}"

build="${ANISO_BUILD_DIR:-$root/build}"
jobs="$(nproc 2>/dev/null || echo 2)"
# The ParaView plugin is its own stage (scripts/paraview.sh, which sets ANISO_PARAVIEW=ON):
# with it, ./test would pass its 20 minutes (docs/PARAVIEW.md, "Where it is built and tested").
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE="${ANISO_BUILD_TYPE:-Release}" \
  -DANISO_PARAVIEW="${ANISO_PARAVIEW:-OFF}" >/dev/null
cmake --build "$build" -j "$jobs"
