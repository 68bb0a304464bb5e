#!/usr/bin/env bash
# Whether the kernel's lane loops were vectorised: the penalty Newton steps (4 iterations, a
# block of 16 lanes) and the brute-force block, read from the built library's code. They are
# `omp simd` loops, but g++ keeps such a loop scalar without a word when one statement in it
# cannot be vectorised, and the kernels then run 2-3x slower with the same results (g++ 12
# did so until tri_kernel got -fno-trapping-math -fno-math-errno, src_plugin/kernel/
# CMakeLists.txt). Passes when packed double arithmetic (..pd) outnumbers scalar (..sd) at
# least 2 to 1 in those functions; x86-64 only (elsewhere: skipped, exit 77).
#   lane_loops_vectorised.sh OBJDUMP LIBRARY
set -euo pipefail
objdump=$1
library=$2
if [ "$(uname -m)" != x86_64 ]; then
  echo "not x86-64: skipped"
  exit 77
fi
listing=$("$objdump" -d --no-show-raw-insn "$library")

count() { # prints "packed scalar" for the functions whose symbol matches $1
  awk -v re="$1" '
    /^[0-9a-f]+ <.*>:$/ { inside = ($0 ~ re); next }
    inside && NF >= 2 {
      op = $2
      if (op ~ /^v?(add|sub|mul|div)pd$/ || op ~ /^vf(n)?m(add|sub)[0-9]+pd$/) packed++
      else if (op ~ /^v?(add|sub|mul|div)sd$/ || op ~ /^vf(n)?m(add|sub)[0-9]+sd$/) scalar++
    }
    END { print packed + 0, scalar + 0 }' <<<"$listing"
}

status=0
check() { # name, symbol pattern
  local packed scalar
  read -r packed scalar < <(count "$2")
  echo "$1: $packed packed, $scalar scalar double-precision arithmetic instructions"
  if [ "$packed" -eq 0 ] || [ "$packed" -lt $((2 * scalar)) ]; then
    echo "FAIL: $1 is not vectorised"
    status=1
  fi
}
check "penalty, 4 Newton steps, 16 lanes" 'penalty_lanesILi4ELi16ELb0E|penalty_blockILi4EE'
check "brute-force block" 'brute_force_blockE'
exit $status
