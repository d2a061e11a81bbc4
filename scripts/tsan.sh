#!/usr/bin/env bash
# Builds the tests of the threaded parts with ThreadSanitizer (gcc) in their own build directory
# (build-tsan) and runs them: the parallel loop of the environment bakes and the reference
# integrator (core/env/parallel.h: environment, cube map, sampling distribution, reference) and
# the LUT bakes with their cancellation (core/lut). A data race or a lock-order inversion fails
# the test that hit it. Not here: what runs on Qt's thread pool (the LUT scheduler, the window's
# background loads): Debian's Qt is not instrumented, its QThreadPool hands work over under its
# own futex locks, which ThreadSanitizer cannot see, and every hand-off is reported as a race
# (docs/RELIABILITY.md). OpenImageIO and OpenEXR run without their own threads here for the same
# reason (OPENIMAGEIO_OPTIONS).
#   scripts/tsan.sh [CTEST_ARGS...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$root/scripts/packages.sh"
aniso_install_packages "${ANISO_PACKAGES[@]}"
build="${ANISO_TSAN_BUILD_DIR:-$root/build-tsan}"
jobs="$(nproc 2>/dev/null || echo 2)"
tests=(test_environment test_cubemap test_env_sampling test_reference_integrator test_lut
  test_lut_cache test_lut_cancel)
flags="-fsanitize=thread -O1 -g1"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DANISO_PARAVIEW=OFF \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-DNDEBUG" \
  -DANISO_WARNINGS_AS_ERRORS=OFF -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" >/dev/null
cmake -S "$root" -B "$build" -DANISO_BUILD_SET="$(IFS=';'; echo "${tests[*]}")" >/dev/null
cmake --build "$build" -j "$jobs" --target aniso_build_set
cd "$build"
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1"
export OPENIMAGEIO_OPTIONS="threads=1,exr_threads=-1"
regex="^($(IFS='|'; echo "${tests[*]}"))\$"
exec xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" ctest --output-on-failure -j "$jobs" \
  -R "$regex" "$@"
