#!/usr/bin/env bash
# Builds the project with AddressSanitizer and UndefinedBehaviorSanitizer (gcc) in its own build
# directory (build-asan) and runs the whole test suite under Xvfb there, like ./test: a memory
# error or undefined behaviour aborts the test that hit it. Leak detection is off: with it on,
# the tests that create a window or a GL context end on leak reports from Qt, Mesa and
# OpenImageIO at exit (docs/RELIABILITY.md); the fuzz harnesses (scripts/fuzz.sh) do check
# leaks, with named suppressions. scripts/sanitize.sh [CTEST_ARGS...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$root/scripts/packages.sh"
aniso_install_packages "${ANISO_PACKAGES[@]}"
build="${ANISO_ASAN_BUILD_DIR:-$root/build-asan}"
jobs="$(nproc 2>/dev/null || echo 2)"
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
# -O1 -g1 (line tables for the reports' stacks): the build takes a third less time than -O2 -g.
# Warnings stay warnings here: the release build of ./test holds them to -Werror, and gcc's
# warnings differ under the sanitizers' instrumentation (false "maybe-uninitialized" in <regex>).
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DANISO_WARNINGS_AS_ERRORS=OFF -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_C_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
cmake --build "$build" -j "$jobs"
cd "$build"
export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# Three tests stay out of this stage (docs/RELIABILITY.md): test_reference_image (minutes of the
# CPU reference's quadrature, whose code the reference tests of the command line and the window
# run here too), test_bench_command (the benchmark's own timing runs) and test_package (the
# Debian package's validators). CI's time (under 60 minutes) pays for the rest.
exec xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" ctest --output-on-failure -j "$jobs" \
  -E '^(test_reference_image|test_bench_command|test_package)$' "$@"
