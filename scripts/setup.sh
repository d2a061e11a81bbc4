#!/usr/bin/env bash
# Shared set-up for ./run and ./test: install what is missing (Debian 12), configure, build.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

. "$root/scripts/packages.sh"
build="${ANISO_BUILD_DIR:-$root/build}"
# The ParaView plugin (docs/PARAVIEW.md): ./test builds and tests it (ANISO_PARAVIEW=ON, with
# ParaView 5.11's packages and python3-paraview unpacked beside the build); ./run leaves it out.
paraview="${ANISO_PARAVIEW:-OFF}"
if [ "$paraview" = OFF ]; then
  aniso_install_packages "${ANISO_PACKAGES[@]}"
else
  aniso_install_packages "${ANISO_PACKAGES[@]}" "${ANISO_PARAVIEW_PACKAGES[@]}"
  aniso_unpack_package python3-paraview "$build/paraview/python3-paraview"
fi

jobs="$(nproc 2>/dev/null || echo 2)"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE="${ANISO_BUILD_TYPE:-Release}" \
  -DANISO_PARAVIEW="$paraview" >/dev/null
cmake --build "$build" -j "$jobs"
