#!/usr/bin/env bash
# Builds the libFuzzer harnesses (fuzz/) with clang, AddressSanitizer and UndefinedBehavior-
# Sanitizer, writes their seed corpora (fuzz_make_seeds) and runs each harness for SECONDS
# (default 20, CI's smoke). A crash, a sanitizer report, a leak or a hang fails the run; the
# input that caused it is kept in $ANISO_FUZZ_OUT (default ./out/fuzz) as crash-*/timeout-*.
# Keep what a finding teaches as a regression file under tests/data/fuzz/<harness>/.
#   scripts/fuzz.sh [SECONDS] [HARNESS...]
#   scripts/fuzz.sh smoke     CI's smoke: each harness of the default list for the number of
#                             inputs in scripts/fuzz_smoke_runs (about 10 s each here; at most
#                             60 s), from a fresh corpus: the same inputs on every machine, so
#                             the smoke finds nothing new by running faster or slower.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$root/scripts/packages.sh"
# What the build needs (its find_package of OpenImageIO names openimageio-tools' programs), with
# clang and its libFuzzer and sanitizer runtimes.
aniso_install_packages "${ANISO_PACKAGES[@]}" clang libclang-rt-14-dev

seconds="${1:-20}"
shift || true
smoke=0
if [ "$seconds" = smoke ]; then
  smoke=1
  seconds=60
fi
harnesses=("$@")
if [ ${#harnesses[@]} -eq 0 ]; then
  # fuzz_step and fuzz_iges are run by name: OpenCASCADE 7.6 crashes on entities it cannot read
  # within seconds of mutation (docs/RELIABILITY.md, Fuzzing), which the reader program's process
  # contains but a smoke would report every time.
  harnesses=(fuzz_ply fuzz_stl fuzz_off fuzz_obj fuzz_vtk fuzz_vtp fuzz_vtm fuzz_gltf fuzz_glb
    fuzz_text_values fuzz_session fuzz_image fuzz_material_library fuzz_mtl fuzz_command_line)
fi
build="${ANISO_FUZZ_BUILD_DIR:-$root/build-fuzz}"
out="${ANISO_FUZZ_OUT:-$root/out/fuzz}"
jobs="$(nproc 2>/dev/null || echo 2)"
sanitize="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined"
# Warnings stay warnings here (clang warns differently from the gcc build that holds them to
# -Werror), as in scripts/sanitize.sh.
# -O1 -gline-tables-only: as OSS-Fuzz builds its targets (line tables for the findings' stacks).
# The compiler's own linker: gold (the other builds' choice, cmake/AnisoLinker.cmake) warns
# about every symbol of clang's AddressSanitizer runtime it cannot export.
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DANISO_FUZZ=ON -DANISO_PARAVIEW=OFF \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
  -DANISO_WARNINGS_AS_ERRORS=OFF -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DANISO_LINKER=default \
  -DCMAKE_CXX_FLAGS="$sanitize -fno-omit-frame-pointer" -DCMAKE_C_FLAGS="$sanitize" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
cmake -S "$root" -B "$build" \
  -DANISO_BUILD_SET="fuzz_make_seeds;$(IFS=';'; echo "${harnesses[*]}")" >/dev/null
cmake --build "$build" -j "$jobs" --target aniso_build_set

seeds="$out/seeds"
rm -rf "$seeds"
# The seed writer is no harness: OpenCASCADE's writers keep memory to the end, not a finding.
ASAN_OPTIONS=detect_leaks=0 "$build/fuzz/fuzz_make_seeds" "$seeds" >/dev/null
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:fast_unwind_on_malloc=0"
export LSAN_OPTIONS="suppressions=$root/fuzz/lsan.supp"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# The harnesses of what the reader program runs (fuzz/fuzz_reader_program.cxx).
reader_harnesses="fuzz_obj fuzz_vtk fuzz_vtp fuzz_vtm fuzz_gltf fuzz_glb fuzz_step fuzz_iges"
# Whether a harness's run ended on an allocation past the memory limit and on nothing else:
# every report's summary is libFuzzer's out-of-memory (RSS past -rss_limit_mb) or ASan's
# out-of-memory or allocation-size-too-big (operator new past max_allocation_size_mb or past what
# ASan can allocate at all), with no sanitizer's runtime error.
past_memory_only() {
  local summaries
  summaries=$(grep -o 'SUMMARY: [A-Za-z]*: [A-Za-z-]*' "$1" | sort -u)
  [ -n "$summaries" ] &&
    ! grep -q 'runtime error' "$1" &&
    ! grep -v -x 'SUMMARY: libFuzzer: out-of-memory\|SUMMARY: AddressSanitizer: out-of-memory\|SUMMARY: AddressSanitizer: allocation-size-too-big' <<<"$summaries" | grep -q .
}

# One harness: its run, then one line of outcome in $out/$h.result (and the finding's report
# after it); fails on a finding.
fuzz_one() {
  local h="$1"
  local corpus="$out/corpus/$h"
  local result="$out/$h.result"
  local limit=()
  if [ "$smoke" -eq 1 ]; then
    local runs
    runs=$(awk -v h="$h" '$1 == h { print $2 }' "$root/scripts/fuzz_smoke_runs")
    if [ -z "$runs" ]; then
      echo "fuzz: $h has no line in scripts/fuzz_smoke_runs" >"$result"
      return 1
    fi
    limit=(-runs="$runs")
    rm -rf "$corpus"
  fi
  mkdir -p "$corpus" "$out/findings/$h"
  local seed_dir="$seeds/${h#fuzz_}"
  local regressions="$root/tests/data/fuzz/${h#fuzz_}"
  local extra=()
  [ -d "$regressions" ] && extra+=("$regressions")
  local log="$out/$h.log"
  local memory=(-rss_limit_mb=2048)
  if [[ " $reader_harnesses " == *" $h "* ]]; then
    # The reader program gives its reader max(512 MiB, 64 x the file's size) of address space
    # (limitChildMemory, vtkpasses/mesh/MeshReaderProcess.cxx); the inputs here are small, so
    # an allocation past 512 MiB is one the program's reader does not get. As there, it fails
    # instead of ending the run: malloc returns null (VTK's arrays then throw std::bad_alloc,
    # which the program reports as "PATH: the reader ran out of memory"). ASan's operator new
    # still reports such an allocation (below). Without this bound an input that declares a
    # 1.8 GB array (a DIMENSIONS line) spends the -timeout in ASan's allocator.
    export ASAN_OPTIONS="$ASAN_OPTIONS:allocator_may_return_null=1:max_allocation_size_mb=512"
  fi
  # -seed=1: the same mutations from run to run (how far a run gets depends on the time).
  # -timeout=30: a hang, not a slow machine (CI's ran the VTK harness at a third of the speed
  # here).
  if "$build/fuzz/$h" -seed=1 -max_total_time="$seconds" "${limit[@]}" -timeout=30 "${memory[@]}" \
      -artifact_prefix="$out/findings/$h/" -print_final_stats=1 \
      "$corpus" "$seed_dir" "${extra[@]}" >"$log" 2>&1; then
    local executed cov time
    executed=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
    cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo "?")
    time=$(grep -o 'Done [0-9]* runs in [0-9]* second' "$log" | grep -o 'in [0-9]*' | grep -o '[0-9]*' || echo "$seconds")
    echo "fuzz: $h: ${executed} inputs in ${time} s, coverage ${cov} edges, no finding" >"$result"
  elif [[ " $reader_harnesses " == *" $h "* ]] && past_memory_only "$log"; then
    # VTK's, tinygltf's and OpenCASCADE's readers allocate what a file claims; in the
    # application they run in the reader program under its memory limit, which refuses such a
    # file ("PATH: the reader ran out of memory", or the reader's own allocation error), so this
    # is no finding of the harness's own. The run stops there; the input is kept for
    # tests/data/fuzz/open/ or past-memory/ (test_fuzz_findings).
    echo "fuzz: $h: an input past the memory limit, which the reader program's limit refuses" \
      "(input in $out/findings/$h/), no other finding" >"$result"
  else
    {
      echo "fuzz: $h: FINDING (log $log, input in $out/findings/$h/)"
      # The report from its first line (the top of the stack), then the summary.
      sed -n '/ERROR: \|ALARM: \|==WARNING: \|runtime error/,$p' "$log" | head -60
      tail -8 "$log"
    } >"$result"
    return 1
  fi
}

# Each harness writes its inputs (fuzz/fuzz_input.h), and the reader program's harnesses their
# fixtures and caches (fuzz/fuzz_reader_program.cxx), under TMPDIR, a file and a folder per
# process: here a folder of this run's own, removed at its end (a finding's input is kept in
# $out/findings), where they were left in /tmp, some 30 entries a run.
TMPDIR="$(mktemp -d "${TMPDIR:-/tmp}/aniso-fuzz.XXXXXX")"
export TMPDIR
trap 'rm -rf "$TMPDIR"' EXIT
# The harnesses run side by side, one a core (each is one process of one thread); their
# outcomes are printed in the list's order.
for h in "${harnesses[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do
    wait -n || true
  done
  rm -f "$out/$h.result" "$out/$h.passed"
  { fuzz_one "$h" && touch "$out/$h.passed"; } &
done
wait || true
passed=0
failed=0
for h in "${harnesses[@]}"; do
  if [ -f "$out/$h.passed" ]; then
    cat "$out/$h.result"
    passed=$((passed + 1))
  else
    cat "$out/$h.result" >&2 2>/dev/null || echo "fuzz: $h: ended without an outcome" >&2
    failed=$((failed + 1))
  fi
done
echo "fuzz: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
