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
"""
import math
import os
import struct
import subprocess

from decklib import check, cube, last_frame, run_deck, write_binary_stl, write_stl

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


def quat_matrix(w, x, y, z):
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]


def solid_centre(tris):
    """Volume and centre of mass of the solid a closed, outward triangle set bounds."""
    vol, centre = 0.0, [0.0, 0.0, 0.0]
    for p0, p1, p2 in tris:
        v6 = (p0[0] * (p1[1] * p2[2] - p1[2] * p2[1]) - p0[1] * (p1[0] * p2[2] - p1[2] * p2[0])
              + p0[2] * (p1[0] * p2[1] - p1[1] * p2[0]))
        vol += v6 / 6
        for k in range(3):
            centre[k] += v6 / 6 * (p0[k] + p1[k] + p2[k]) / 4
    return vol, [cc / vol for cc in centre]


def run(ctx, orient, deck_text=DECK):
    deck = os.path.join(ctx.work, f"in.{orient}")
    with open(deck, "w") as f:
        f.write(deck_text.format(x=ATOM[0], y=ATOM[1], z=ATOM[2], orient=orient))
    run_deck(ctx, deck, timeout=300)
    d = subprocess.run([ctx.vtkdump, os.path.join(ctx.work, "post", f"{orient}_0.vtp"), "id",
                        "points"], stdout=subprocess.PIPE, text=True, check=True).stdout
    cells = [[float(x) for x in l.split()[1:]] for l in d.splitlines() if l and l[0] != "#"]
    _, atoms = last_frame(os.path.join(ctx.work, f"{orient}.dump"))
    check(set(atoms) == {1}, f"orient {orient}: atoms {sorted(atoms)} in the dump")
    row = [float(x) for x in atoms[1]]
    return [[c[0:3], c[3:6], c[6:9]] for c in cells], row[0:3], row[3:7]


def test_orient(ctx):
    os.makedirs(os.path.join(ctx.work, "post"))
    tris = l_prism()
    write_stl(os.path.join(ctx.work, "ell.stl"), tris)
    c = centre_of_mass()

    # orient file: the file's triangles, translated so that c lands on the atom.
    cells, x, q = run(ctx, "file")
    shift = [x[k] - c[k] for k in range(3)]
    check(len(cells) == len(tris),
          f"orient file: {len(cells)} triangles in the .vtp, the file has {len(tris)}")
    worst = 0.0
    for t, cell in zip(tris, cells):
        for p, w in zip(t, cell):
            worst = max(worst, max(abs(w[k] - (p[k] + shift[k])) for k in range(3)))
    print(f"orient file: x {x}, q {q}; .vtp corners against file + (x - c): largest "
          f"difference {worst:.3g} m")
    check(worst <= TOL, f"orient file: the .vtp triangles are {worst:.3g} m off the file's")
    r = quat_matrix(*q)
    ez = [r[k][2] for k in range(3)]
    ex = [r[k][0] for k in range(3)]
    check(abs(abs(ez[2]) - 1) <= 1e-12,
          f"orient file: the rotation moves the prism's axis z: R e_z = {ez}")
    check(abs(abs(ex[0]) - math.sqrt(0.5)) <= 1e-12 and abs(abs(ex[1]) - math.sqrt(0.5)) <= 1e-12,
          f"orient file: R e_x = {ex} is not along a diagonal (45 degrees)")

    # orient none: identity quaternion; the principal frame on the world axes, turned 45 degrees
    # against the file, the centre of mass on the atom.
    cells, x, q = run(ctx, "none")
    check(q == [1.0, 0.0, 0.0, 0.0], f"orient none: quaternion {q}, expected 1 0 0 0")
    check(len(cells) == len(tris),
          f"orient none: {len(cells)} triangles in the .vtp, the file has {len(tris)}")
    far = 0.0
    for t, cell in zip(tris, cells):
        for p, w in zip(t, cell):
            far = max(far, max(abs(w[k] - (p[k] + shift[k])) for k in range(3)))
    check(far >= 1e-4, f"orient none: the triangles are the file's ({far:.3g} m): not turned")
    vol, centre = solid_centre(cells)
    off = max(abs(centre[k] - x[k]) for k in range(3))
    print(f"orient none: q {q}; centre of mass of the .vtp surface {centre}, atom {x}; "
          f"triangles {far:.3g} m from the file's")
    check(off <= 1e-12, f"orient none: centre of mass {centre} is not the atom's position {x}")
    check(abs(vol - 3 * A * A * H) <= 1e-9 * vol,
          f"orient none: volume {vol}, expected {3 * A * A * H}")
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
    check(not bad, f"orient none: {bad} corner coordinates not on the diagonal grid: the "
                   "principal axes are not the world axes")


def turned(tris, axis, angle, shift):
    """The triangles turned by `angle` about the unit `axis` (Rodrigues), then moved by shift,
    rounded to single precision as a binary STL stores them."""
    ux, uy, uz = axis
    c, s = math.cos(angle), math.sin(angle)
    r = [[c + ux * ux * (1 - c), ux * uy * (1 - c) - uz * s, ux * uz * (1 - c) + uy * s],
         [uy * ux * (1 - c) + uz * s, c + uy * uy * (1 - c), uy * uz * (1 - c) - ux * s],
         [uz * ux * (1 - c) - uy * s, uz * uy * (1 - c) + ux * s, c + uz * uz * (1 - c)]]
    single = lambda v: struct.unpack("<f", struct.pack("<f", v))[0]
    return [[[single(sum(r[i][k] * p[k] for k in range(3)) + shift[i]) for i in range(3)]
             for p in t] for t in tris]


def octahedron(h=0.0015):
    v = [(h, 0, 0), (-h, 0, 0), (0, h, 0), (0, -h, 0), (0, 0, h), (0, 0, -h)]
    tris = []
    for sx in (0, 1):
        for sy in (2, 3):
            for sz in (4, 5):
                t = [v[sx], v[sy], v[sz]]
                # outward: counter-clockwise seen from outside
                if (sx == 1) ^ (sy == 3) ^ (sz == 5):
                    t = [t[0], t[2], t[1]]
                tris.append(t)
    return tris


def test_orient_none_keeps_a_turned_isotropic_shape(ctx):
    """A cube and a regular octahedron (equal principal moments: every direction is principal)
    turned in their files by an arbitrary rotation, in single precision: `orient none` keeps the
    file's axes within mass_properties.h's tolerance (1e-5 of the moments), so the particle
    stands as in its file, every .vtp corner the file's moved by x_atom - centre of mass."""
    os.makedirs(os.path.join(ctx.work, "post"))
    n = math.sqrt(1 + 4 + 9)
    axis = (1 / n, -2 / n, 3 / n)
    shapes = {"cube": [[[c - 0.001 for c in p] for p in t] for t in cube()],
              "octa": octahedron()}
    for name, tris in shapes.items():
        file_tris = turned(tris, axis, 0.7, (0.003, -0.001, 0.002))
        write_binary_stl(os.path.join(ctx.work, "ell.stl"), file_tris)
        _, c = solid_centre(file_tris)
        cells, x, q = run(ctx, "none", DECK.replace("shape ell", "shape " + name))
        check(q == [1.0, 0.0, 0.0, 0.0], f"{name}, orient none: quaternion {q}, expected 1 0 0 0")
        worst = max(abs(w[k] - (p[k] - c[k] + x[k]))
                    for t, cell in zip(file_tris, cells) for p, w in zip(t, cell) for k in range(3))
        print(f"{name}: .vtp corners against the file's moved onto the atom: largest difference "
              f"{worst:.3g} m")
        check(len(cells) == len(file_tris) and worst <= 1e-12,
              f"{name}, orient none: the particle is turned against its file (corners {worst:.3g} m"
              " off): its equal principal moments were not taken as equal")
