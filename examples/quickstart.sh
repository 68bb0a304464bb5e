#!/usr/bin/env bash
# The README's first command: installs what is missing, builds, runs the hopper (the main
# example: 125 rocks discharging through a funnel, about a minute on 2 cores) and the small
# falling-particles demo, and says where the ParaView files are.
set -euo pipefail
top="$(cd "$(dirname "$0")/.." && pwd)"
bash "$top/examples/build.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
exe="$top/build/src_plugin/driver/liggghts-tri"

cd "$top/examples/hopper"
"$exe" -in in.hopper -var dir .

cd "$top/examples/falling"
"$exe" -in in.falling
/usr/bin/python3 render.py post/particles.pvd post/falling.png 4

echo
echo "ParaView: open $top/examples/hopper/post/particles.pvd"
echo "          with its walls $top/examples/hopper/post/particles_walls.pvd"
echo "          and $top/examples/falling/post/particles.pvd (picture: post/falling.png)"
echo "Discharge: $top/examples/hopper/post/discharge.txt"
