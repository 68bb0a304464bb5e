"""A convex particle in a crease of a wall touches each flank in a spot of its own: the two
bottom edges of a prism resting in a V-groove (flanks 20 degrees up, normals 40 degrees apart,
inside the reduction's 45-degree split angle; the edges 2 mm apart) are two contacts, each with
its own overlap along its flank's normal. As one class they were one contact holding the
deeper edge's overlap alone, and the groove carried the prism with half its stiffness."""
import math
import os

from decklib import EPS, check, last_frame, run_deck, write_stl

MAT = {"kn": 2000.0, "kt": 1000.0, "gamman": 0.0, "gammat": 0.0, "mu": 0.5}
FLANK = math.radians(20.0)
HALF = 1e-3  # m, half the distance between the prism's bottom edges


def _meshes(work):
    # The prism: the triangle (-HALF, 0), (HALF, 0), (0, 1.5 HALF) in x-z, extruded over
    # y in [-HALF, HALF]; its centroid is HALF / 2 above its bottom face.
    t = [(-HALF, 0.0), (HALF, 0.0), (0.0, 1.5 * HALF)]
    lo = [(x, -HALF, z) for x, z in t]
    hi = [(x, HALF, z) for x, z in t]
    tris = [(lo[0], lo[2], lo[1]), (hi[0], hi[1], hi[2])]
    for i in range(3):
        j = (i + 1) % 3
        tris += [(lo[i], lo[j], hi[j]), (lo[i], hi[j], hi[i])]
    write_stl(os.path.join(work, "prism.stl"), [tri[::-1] for tri in tris])
    # The groove: two flanks rising at FLANK from the crease along y, 8 mm each way.
    w, s = 0.008, 0.006
    zt = w * math.tan(FLANK)
    left = [(-w, -s, zt), (0.0, -s, 0.0), (0.0, s, 0.0), (-w, s, zt)]
    right = [(0.0, -s, 0.0), (w, -s, zt), (w, s, zt), (0.0, s, 0.0)]
    quads = [left, right]
    write_stl(os.path.join(work, "groove.stl"),
              [tri for q in quads for tri in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))])


def test_prism_in_a_groove(ctx):
    """Two contacts, one per flank: the vertical force is 2 kn o cos(20 deg)."""
    _meshes(ctx.work)
    overlap = 0.5 * EPS  # of each edge, with the particle's and the wall's layers (2 EPS)
    gap = 2 * EPS - overlap  # each edge's distance from its flank
    z_edge = HALF * math.tan(FLANK) + gap / math.cos(FLANK)
    run_deck(ctx, "in.wall_crease", dict(MAT, zc=repr(z_edge + 0.5 * HALF)))
    step, rows = last_frame(os.path.join(ctx.work, "contact.dump"))
    f = [float(x) for x in rows[1][3:6]]
    fz = 2 * MAT["kn"] * overlap * math.cos(FLANK)
    print(f"force {f}, two contacts {fz!r}, one {fz / 2!r}")
    check(abs(f[2] - fz) <= 1e-9 * fz and abs(f[0]) <= 1e-9 * fz and abs(f[1]) <= 1e-9 * fz,
          f"groove force {f}, two contacts on the flanks give (0, 0, {fz!r})")
    with open(os.path.join(ctx.work, "contacts.txt")) as fh:
        lines = fh.read().split("ITEM: ENTRIES")[-1].split("\n")[1:]
    rows = [[float(x) for x in l.split()] for l in lines if l.strip()]
    check(len(rows) == 2, f"{len(rows)} contacts listed, expected one per flank")
    for r in rows:  # dump local writes 6 digits
        check(abs(r[0] - overlap) <= 1e-5 * overlap and
              abs(abs(r[1]) - math.sin(FLANK)) <= 1e-5 and abs(r[3] + math.cos(FLANK)) <= 1e-5,
              f"contact {r}: overlap {overlap!r} along a flank's normal")
    check(rows[0][1] * rows[1][1] < 0, f"contacts {rows}: one on each flank")
