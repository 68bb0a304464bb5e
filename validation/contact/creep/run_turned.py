#!/usr/bin/python3
"""A cube turned in its file on an incline built as a tilted mesh (in.turned): the cube of 12 or
192 triangles (meshgen.py cube 1 or 4, side 4 mm), the incline of 2 or 512 triangles, both
turned about y by the 7-24-25 angle (16.26 degrees, 97.2 % of atan(mu) for mu 0.3), gravity
vertical, `orient file`. It lands flat and must stay: the largest displacement and spin from
t = 0.03 s to the end (0.3 s). Target as in run_creep.py: below 1e-8 m.

  /usr/bin/python3 run_turned.py [--exe build/src_plugin/driver/liggghts-tri] [--work DIR]
"""
import argparse
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(REPO, "validation", "meshes"))
sys.path.insert(0, os.path.join(REPO, "validation"))
import meshgen  # noqa: E402
import valtools  # noqa: E402

COS, SIN = 24.0 / 25.0, 7.0 / 25.0   # the 7-24-25 angle
SETTLED, TOL = 0.03, 1e-8
CASES = [(1, 1), (1, 16), (4, 1), (4, 16)]  # cube N (12 N^2 triangles), plane N (2 N^2)


def turned(verts):
    """About y by the 7-24-25 angle: +x goes down the incline, the face normal +z to (7, 0, 24)/25."""
    return [(COS * x + SIN * z, y, -SIN * x + COS * z) for x, y, z in verts]


def run_case(exe, work, n, pn):
    cube, plane = os.path.join(work, f"cube{n}.stl"), os.path.join(work, f"plane{pn}.stl")
    v, f = meshgen.cube(n, 0.004)
    meshgen.write_stl(cube, turned(v), f, name="cube")
    v, f = meshgen.plane(0.03, pn)
    meshgen.write_stl(plane, turned(v), f, name="plane")
    out = f"turned_c{n}_p{pn}.txt"
    valtools.run_deck(exe, os.path.join(HERE, "in.turned"), dict(mesh=cube, plane=plane, out=out),
                      work, os.path.join(work, out + ".screen"), exit_on_error=True)
    rows = valtools.read_rows(os.path.join(work, out))
    start = next(r for r in rows if r[0] >= SETTLED - 1e-12)
    moved = max(math.dist(r[1:4], start[1:4]) for r in rows if r[0] >= start[0])
    spin = max(math.hypot(*r[4:7]) for r in rows if r[0] >= start[0])
    return moved, spin


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", default=valtools.default_exe())
    ap.add_argument("--work", default="/tmp/liggghts-tri-validation/creep_turned")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    print(valtools.machine_line())
    print("| cube triangles | plane triangles | displacement after 0.03 s (m) | max abs(omega) (rad/s) | pass |")
    print("|---|---|---|---|---|")
    for n, pn in CASES:
        moved, spin = run_case(a.exe, a.work, n, pn)
        print(f"| {12 * n * n} | {2 * pn * pn} | {moved:.2e} | {spin:.2e} | "
              f"{'PASS' if moved < TOL else 'FAIL'} |", flush=True)


if __name__ == "__main__":
    main()
