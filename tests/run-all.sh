#!/usr/bin/env bash
# The README's test command: installs what is missing, builds, runs every test (CTest:
# GoogleTest kernel and io tests, deck tests through liggghts-tri).
set -euo pipefail
cd "$(dirname "$0")/.."
bash examples/build.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
ctest --test-dir build --output-on-failure -j"$(nproc)" "$@"
