#!/usr/bin/env bash
# The README's first command: installs what is missing, builds, runs the main example and
# says where the ParaView files are.
set -euo pipefail
top="$(cd "$(dirname "$0")/.." && pwd)"
bash "$top/examples/build.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$top/examples/falling"
"$top/build/src_plugin/driver/liggghts-tri" -in in.falling
/usr/bin/python3 render.py post/particles.pvd post/falling.png 4
echo
echo "ParaView: open $top/examples/falling/post/particles.pvd"
echo "Picture:  $top/examples/falling/post/falling.png"
