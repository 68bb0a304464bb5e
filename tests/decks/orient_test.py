#!/usr/bin/env python3
"""`orient file` against `orient none` for a file shape whose principal frame is turned against
the file's own: an L prism (legs of equal length, so its in-plane principal axes lie along the
diagonals, 45 degrees from the file's x and y), written here, off the origin, as an STL.

Checked, from fix tri/vtk's .vtp (triangle corners, read back by tri-vtk-dump FILE id points) and a dump
of the quaternion f_shapes[2..5]:
  * orient file: every triangle of the particle is the file's triangle translated by
    x_atom - c, with c the file's centre of mass (computed here by hand), corner for corner, to
    1e-12 m; the quaternion is a rotation that keeps z and turns x onto a diagonal;
  * orient none: quaternion 1 0 0 0, the same triangle set turned (at least 1e-4 m away from the
    file's), centred on the atom (mean of the triangles' volume-weighted centroids = x_atom),
    axes of the principal frame along the world's (the diagonal leg direction on x or y).
Coordinates are powers of two, so the STL's single-precision floats hold them exactly.
Standard library only.

usage: orient_test.py --exe LIGGGHTS_TRI --vtkdump TRI_VTK_DUMP --work DIR
"""
import argparse
import math
import os
import shutil
import subprocess
import sys

A = 2.0 ** -9             # leg unit: the outline (0,0) (2a,0) (2a,a) (a,a) (a,2a) (0,2a), m
H = 2.0 ** -10            # prism height, m
OFFSET = (2.0 ** -7, -(2.0 ** -8), 2.0 ** -8)   # where the outline's corner (0,0) sits in the file
ATOM = (0.001, -0.002, 0.0005)                  # the atom's position, m
TOL = 1e-12

DECK = """\
units           si
atom_style      sphere
atom_modify     map array sort 0 0.0
boundary        f f f
newton          off
communicate     single vel yes
region          box block -0.02 0.02 -0.02 0.02 -0.02 0.02 units box
create_box      1 box
neighbor        0.001 bin
neigh_modify    delay 0
timestep        1e-5
create_atoms    1 single {x} {y} {z} units box
fix shapes all tri/particles shape ell file ell.stl density 2500 epsilon 0.0001 orient {orient}
fix integr all tri/nve
fix out all tri/vtk every 1 file post/{orient}
dump d all custom 1 {orient}.dump id x y z f_shapes[2] f_shapes[3] f_shapes[4] f_shapes[5]
dump_modify d format "%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g"
run 0
"""


def l_prism():
    """Triangles of the L prism in the file (outward, counter-clockwise seen from outside)."""
    outline = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    v = [(OFFSET[0] + px * A, OFFSET[1] + py * A, OFFSET[2] + z) for z in (0.0, H)
         for px, py in outline]
    tris = []
    for i in range(6):
        j = (i + 1) % 6
        tris += [(i, j, j + 6), (i, j + 6, i + 6)]
    tris += [(6, 7, 8), (6, 8, 9), (6, 9, 10), (6, 10, 11)]
    tris += [(0, 2, 1), (0, 3, 2), (0, 4, 3), (0, 5, 4)]
    return [[v[k] for k in t] for t in tris]


def centre_of_mass():
    """Two boxes: [0,2a] x [0,a] (area 2a^2) and [0,a] x [a,2a] (area a^2)."""
    cx = (2 * A * A * A + A * A * 0.5 * A) / (3 * A * A)
    cy = (2 * A * A * 0.5 * A + A * A * 1.5 * A) / (3 * A * A)
    return (OFFSET[0] + cx, OFFSET[1] + cy, OFFSET[2] + H / 2)


def write_stl(path, triangles):
    with open(path, "w") as f:
        f.write("solid ell\n")
        for t in triangles:
            f.write(" facet normal 0 0 0\n  outer loop\n")
            for p in t:
                f.write("   vertex %r %r %r\n" % p)
            f.write("  endloop\n endfacet\n")
        f.write("endsolid ell\n")


def quat_matrix(w, x, y, z):
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]


def run(a, orient):
    with open(os.path.join(a.work, f"in.{orient}"), "w") as f:
        f.write(DECK.format(x=ATOM[0], y=ATOM[1], z=ATOM[2], orient=orient))
    p = subprocess.run([a.exe, "-in", f"in.{orient}", "-log", "none"], cwd=a.work,
                       env=dict(os.environ, OMP_NUM_THREADS="1"), stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True, errors="replace", timeout=300)
    if p.returncode != 0:
        raise RuntimeError(f"orient {orient}: exit {p.returncode}\n{p.stdout[-3000:]}")
    d = subprocess.run([a.vtkdump, os.path.join(a.work, "post", f"{orient}_0.vtp"), "id", "points"],
                       stdout=subprocess.PIPE, text=True, check=True).stdout
    cells = [[float(x) for x in l.split()[1:]] for l in d.splitlines() if l and l[0] != "#"]
    with open(os.path.join(a.work, f"{orient}.dump")) as f:
        row = [float(x) for x in f.read().split("ITEM: ATOMS")[1].splitlines()[1].split()]
    return [[c[0:3], c[3:6], c[6:9]] for c in cells], row[1:4], row[4:8]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--vtkdump", required=True)
    ap.add_argument("--work", required=True)
    a = ap.parse_args()
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(os.path.join(a.work, "post"))
    tris = l_prism()
    write_stl(os.path.join(a.work, "ell.stl"), tris)
    c = centre_of_mass()
    failures = []

    # orient file: the file's triangles, translated so that c lands on the atom.
    cells, x, q = run(a, "file")
    shift = [x[k] - c[k] for k in range(3)]
    if len(cells) != len(tris):
        failures.append(f"orient file: {len(cells)} triangles in the .vtp, the file has {len(tris)}")
    worst = 0.0
    for t, cell in zip(tris, cells):
        for p, w in zip(t, cell):
            worst = max(worst, max(abs(w[k] - (p[k] + shift[k])) for k in range(3)))
    print(f"orient file: x {x}, q {q}; .vtp corners against file + (x - c): largest "
          f"difference {worst:.3g} m")
    if worst > TOL:
        failures.append(f"orient file: the .vtp triangles are {worst:.3g} m off the file's")
    r = quat_matrix(*q)
    ez = [r[k][2] for k in range(3)]
    ex = [r[k][0] for k in range(3)]
    if abs(abs(ez[2]) - 1) > 1e-12:
        failures.append(f"orient file: the rotation moves the prism's axis z: R e_z = {ez}")
    if abs(abs(ex[0]) - math.sqrt(0.5)) > 1e-12 or abs(abs(ex[1]) - math.sqrt(0.5)) > 1e-12:
        failures.append(f"orient file: R e_x = {ex} is not along a diagonal (45 degrees)")

    # orient none: identity quaternion; the principal frame on the world axes, turned 45 degrees
    # against the file, the centre of mass on the atom.
    cells, x, q = run(a, "none")
    if q != [1.0, 0.0, 0.0, 0.0]:
        failures.append(f"orient none: quaternion {q}, expected 1 0 0 0")
    far = 0.0
    for t, cell in zip(tris, cells):
        for p, w in zip(t, cell):
            far = max(far, max(abs(w[k] - (p[k] + shift[k])) for k in range(3)))
    if far < 1e-4:
        failures.append(f"orient none: the triangles are the file's ({far:.3g} m): not turned")
    vol, centre = 0.0, [0.0, 0.0, 0.0]
    for p0, p1, p2 in cells:
        v6 = (p0[0] * (p1[1] * p2[2] - p1[2] * p2[1]) - p0[1] * (p1[0] * p2[2] - p1[2] * p2[0])
              + p0[2] * (p1[0] * p2[1] - p1[1] * p2[0]))
        vol += v6 / 6
        for k in range(3):
            centre[k] += v6 / 6 * (p0[k] + p1[k] + p2[k]) / 4
    centre = [cc / vol for cc in centre]
    off = max(abs(centre[k] - x[k]) for k in range(3))
    print(f"orient none: q {q}; centre of mass of the .vtp surface {centre}, atom {x}; "
          f"triangles {far:.3g} m from the file's")
    if off > 1e-12:
        failures.append(f"orient none: centre of mass {centre} is not the atom's position {x}")
    if abs(vol - 3 * A * A * H) > 1e-9 * vol:
        failures.append(f"orient none: volume {vol}, expected {3 * A * A * H}")
    # The L's symmetry axis (the diagonal from the outer corner) lies on a world axis: some
    # corners share their x or y coordinate with the centre along a whole leg, which is only
    # so when the diagonals map to x/y. Test it: all corner coordinates, relative to the
    # centre, in x and y take values +-k a / sqrt 2 (k half-integer multiples).
    unit = A / math.sqrt(2) / 6
    bad = 0
    for cell in cells:
        for w in cell:
            for k in (0, 1):
                u = (w[k] - x[k]) / unit
                if abs(u - round(u)) > 1e-6:
                    bad += 1
    if bad:
        failures.append(f"orient none: {bad} corner coordinates not on the diagonal grid: the "
                        "principal axes are not the world axes")

    if failures:
        print("FAIL orient:\n  " + "\n  ".join(failures))
        return 1
    print("PASS orient")
    return 0


if __name__ == "__main__":
    sys.exit(main())
