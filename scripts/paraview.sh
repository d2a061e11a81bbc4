#!/usr/bin/env bash
# The ParaView plugin's stage (CI runs it after ./test; docs/PARAVIEW.md): installs ParaView 5.11
# and what its tests need, unpacks python3-paraview beside the build (Debian 12 cannot install it
# with libvtk9-dev), builds the plugin in ./test's build directory (whatever ./test built is
# reused) and runs its tests, ctest -L paraview, under Xvfb. Extra arguments go to ctest.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$root/scripts/packages.sh"
aniso_install_packages "${ANISO_PACKAGES[@]}" "${ANISO_PARAVIEW_PACKAGES[@]}"
build="${ANISO_BUILD_DIR:-$root/build}"
aniso_unpack_package python3-paraview "$build/paraview/python3-paraview"
jobs="$(nproc 2>/dev/null || echo 2)"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE="${ANISO_BUILD_TYPE:-Release}" \
  -DANISO_PARAVIEW=ON >/dev/null
cmake --build "$build" -j "$jobs"
cd "$build"
exec xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" ctest --output-on-failure -j "$jobs" -L paraview "$@"
