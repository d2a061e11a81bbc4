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
# -O1 -g1: optimised as sanitizer builds usually are, line tables for the reports' stacks.
# The tests' own sources are built with AddressSanitizer only (ANISO_TEST_COMPILE_OPTIONS): what
# they test, the project's libraries and programs, has both; UndefinedBehaviorSanitizer in
# GoogleTest's and QTest's macros doubled a test's compile.
# Warnings stay warnings here: the release build of ./test holds them to -Werror, and gcc's
# warnings differ under the sanitizers' instrumentation (false "maybe-uninitialized" in <regex>).
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DANISO_PARAVIEW=OFF \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DANISO_WARNINGS_AS_ERRORS=OFF -DANISO_TEST_TIMEOUT_SCALE=3 -DCMAKE_CXX_FLAGS="$flags" \
  -DANISO_TEST_COMPILE_OPTIONS=-fno-sanitize=undefined \
  -DCMAKE_C_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
# Left out of this stage (docs/RELIABILITY.md, "The suite under AddressSanitizer ..."), to keep
# CI's whole run under 60 minutes: the CPU reference's quadrature (test_reference_image), the
# benchmark's timing runs and the package's validators, and the offscreen renders whose time
# under the sanitizers is the LUT bakes and many frames of shading (25 to 130 s each here); the
# classes they drive run here through the shorter command-line tests and the window tests.
skipped='^(test_reference_image|test_bench_command|test_package|test_render_sources|test_render_converge|test_render_reference|test_view_quality|test_gltf_render_cli|test_render_surface_cli|test_render_cli|test_render_parts_cli|test_render_mis_outliers|test_render_cli_models|test_render_sampling|test_render_features|test_render_turntable_cli|test_render_leadr)$'
# Only what the chosen tests need is built (not the benchmarks' programs): the programs the
# tests run and each test's executable (a test that runs a script has none).
known=" $(cmake --build "$build" --target help | sed -n 's/^\.\.\. \([^ ]*\).*/\1/p' | tr '\n' ' ') "
targets=(aniso aniso-mesh-reader)
while read -r t; do
  if [[ "$known" == *" $t "* ]]; then
    targets+=("$t")
  fi
done < <(cd "$build" && ctest -N -E "$skipped" | sed -n 's/^ *Test *#[0-9]*: *//p')
# One goal for all of them (ANISO_BUILD_SET, CMakeLists.txt): make builds the goals of one command
# line one after another, a test's single source on one core.
cmake -S "$root" -B "$build" -DANISO_BUILD_SET="$(IFS=';'; echo "${targets[*]}")" >/dev/null
cmake --build "$build" -j "$jobs" --target aniso_build_set
cd "$build"
# allocator_may_return_null=1: an allocation past the reader program's address-space limit
# fails as it does without the sanitizer (malloc returns null and VTK's reader refuses the file,
# test_fuzz_findings' past-memory/), instead of ending the program with a report.
export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:allocator_may_return_null=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
exec xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" ctest --output-on-failure -j "$jobs" \
  -E "$skipped" "$@"
