#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan) into ./build-fuzz and runs each one
# on a copy of its committed seed corpus; exits non-zero on any finding (crash, sanitizer
# report, failed check, timeout, out-of-memory). tests/run-all.sh calls it.
# By default (CI) each target runs a fixed number of inputs from a fixed seed, so that the
# step explores the same inputs on every machine and cannot turn red by chance; 120 s per
# target is only a bound for a very slow machine. What a random, timed campaign finds is
# fixed and its input added to the corpus (README.md).
#   TRI_FUZZ_SECONDS   instead: a timed run per target, with a random seed
#   TRI_FUZZ_TARGETS   space-separated subset (default: all five)
# Longer campaigns: tests/fuzz/README.md.
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$PWD
seconds=${TRI_FUZZ_SECONDS:-}
targets=${TRI_FUZZ_TARGETS:-"fuzz_stl fuzz_obj fuzz_ply fuzz_triangle_distance fuzz_particle_contacts"}

cmake -S tests/fuzz -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ >/dev/null
if ! cmake --build build-fuzz -j"$(nproc)" >build-fuzz/build.log 2>&1; then
  tail -n 60 build-fuzz/build.log
  exit 1
fi

# libFuzzer adds what it finds to the first corpus folder and writes crash files to the
# working directory: both go under build-fuzz/run, never into tests/fuzz/corpus.
run=build-fuzz/run
rm -rf "$run"
mkdir -p "$run"
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
failed=()
# Inputs per target in the fixed mode: 20-30 s each on the 2-core development machine.
runs_for() {
  case $1 in
    fuzz_obj) echo 60000 ;;
    fuzz_triangle_distance) echo 90000 ;;
    fuzz_particle_contacts) echo 20000 ;;
    *) echo 80000 ;;
  esac
}
for t in $targets; do
  mkdir -p "$run/$t/corpus" "$run/$t/artifacts"
  cp tests/fuzz/corpus/"$t"/* "$run/$t/corpus/"
  if [ -n "$seconds" ]; then
    mode=(-max_total_time="$seconds")
    echo "== $t: ${seconds} s, random seed"
  else
    mode=(-seed=1 -runs="$(runs_for "$t")" -max_total_time=120)
    echo "== $t: $(runs_for "$t") inputs, seed 1"
  fi
  if (cd "$run/$t" && "$root/build-fuzz/$t" "${mode[@]}" -rss_limit_mb=2048 \
        -timeout=10 -print_final_stats=1 -artifact_prefix=artifacts/ corpus >log 2>&1); then
    grep -E '^#[0-9]+[[:space:]]+DONE' "$run/$t/log" | tail -1 || true
  else
    failed+=("$t")
    tail -n 40 "$run/$t/log"
    echo "!! $t failed: reproducer in $run/$t/artifacts/ (run $root/build-fuzz/$t <file>)"
  fi
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzzing found problems in: ${failed[*]}"
  exit 1
fi
echo "fuzzing: no findings"
