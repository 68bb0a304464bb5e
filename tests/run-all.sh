#!/usr/bin/env bash
# The README's test command: installs what is missing, builds, runs every test (CTest:
# GoogleTest kernel and io tests, deck tests through liggghts-tri), then builds the whole
# suite again with AddressSanitizer + UndefinedBehaviorSanitizer and runs it once more.
# TRI_SKIP_SANITIZERS=1 skips the second part (it takes ~11 minutes on 2 cores).
# Last, the libFuzzer targets (tests/fuzz, clang): TRI_SKIP_FUZZ=1 skips them (~5 minutes).
set -euo pipefail
cd "$(dirname "$0")/.."
bash examples/build.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
ctest --test-dir build --output-on-failure -j"$(nproc)" "$@"

if [ "${TRI_SKIP_SANITIZERS:-0}" != 1 ]; then
  cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTRI_SANITIZE=ON -DTRI_NATIVE=OFF
  cmake --build build-asan -j"$(nproc)"
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  # Our own code (kernel, io, tools) with leak checking.
  ctest --test-dir build-asan --output-on-failure -j"$(nproc)" -L 'kernel|io|tools'
  # The decks run LIGGGHTS and Open MPI, whose start-up and shut-down allocations are never
  # freed (traced: none in src_plugin). LIGGGHTS's own error exits read freed memory; the
  # driver's (src_plugin/driver/error_output.cpp) stand in for them, so no suppression is needed.
  ASAN_OPTIONS="detect_leaks=0" \
    ctest --test-dir build-asan --output-on-failure -j"$(nproc)" -L deck
fi

if [ "${TRI_SKIP_FUZZ:-0}" != 1 ]; then
  bash tests/fuzz/run-fuzz.sh
fi
