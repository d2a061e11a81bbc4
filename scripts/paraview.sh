#!/usr/bin/env bash
# The ParaView plugin alone (docs/PARAVIEW.md): the set-up of ./test, which builds it
# (ParaView 5.11 and what its tests need installed, python3-paraview unpacked beside the build,
# which Debian 12 cannot install with libvtk9-dev), then only its tests, ctest -L paraview, under
# Xvfb. Extra arguments go to ctest.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ANISO_PARAVIEW=ON "$root/scripts/setup.sh"
cd "${ANISO_BUILD_DIR:-$root/build}"
exec xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" ctest --output-on-failure \
  -j "$(nproc 2>/dev/null || echo 2)" -L paraview "$@"
