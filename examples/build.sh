#!/usr/bin/env bash
# Installs what is missing (Debian 12 packages, no recommends) and builds liggghts-tri into
# ./build. Used by examples/quickstart.sh and tests/run-all.sh; safe to run again.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  liggghts libliggghts-dev openmpi-bin libopenmpi-dev libeigen3-dev libvtk9-dev libqhull-dev
  cmake g++ make python3
  libgtest-dev libfcl-dev            # tests: GoogleTest, FCL as the distance oracle
  liggghts-doc                       # tests: LIGGGHTS's tutorial decks (deck.liggghts_compat)
  clang libclang-rt-14-dev libomp-dev  # tests/fuzz: clang's libFuzzer, OpenMP for clang
  python3-matplotlib python3-vtk9    # pictures and validation plots (/usr/bin/python3)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  # Recommends would pull ParaView's Python, which conflicts with libvtk9-dev.
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build build -j"$(nproc)"
