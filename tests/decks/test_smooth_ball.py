"""A finely meshed ball against a wall is measured on the smooth surface its vertices sample
(smooth_surface.h): an oblique impact of a randomly turned 5120-triangle icosphere rebounds as
the ideal ball of its mass, inertia and lever does (the validation study's own reference,
validation/contact/oblique/run.py ideal_ball), and a frictionless head-on impact leaves it
without spin. On its facets the same impacts were off by 11 % and spun at 10 % of vn over R.
The deck is the validation study's (validation/contact/oblique/in.tri).

Two such balls meet as balls (contact/ball_contact.h): a head-on frictionless collision of two
randomly turned 1280-triangle icospheres, undamped, keeps its energy and leaves them without
spin, and an oblique one rebounds as two ideal balls do (ideal_pair; the study is
validation/contact/oblique/run_pairs.py, the deck its in.pair). On their facets the head-on
collision lost 0.7 % of the speed (1.4 % of the energy) and spun the balls at 8 % of the speed
over R, and the oblique one missed the spin by 18 %. A ball on another particle's facets (a
cube's face) is measured on its smooth surface, as on a wall: on the facets its spin was off by
up to 100 % and it bounced off 3.7 % faster than it came (in.on_cube)."""
import math
import os
import sys

import decklib
from decklib import check, run_deck

ROOT = os.path.join(decklib.HERE, "..", "..")
DECK = os.path.join(ROOT, "validation", "contact", "oblique", "in.tri")
PAIR_DECK = os.path.join(ROOT, "validation", "contact", "oblique", "in.pair")
CUBE_DECK = os.path.join(ROOT, "validation", "contact", "oblique", "in.on_cube")
sys.path.insert(0, os.path.join(ROOT, "validation", "meshes"))
sys.path.insert(0, os.path.join(ROOT, "validation", "contact", "oblique"))
import meshgen  # noqa: E402

# EPS: the impact's peak overlap (6.5 um) within the ball's layer, the wall having none.
R, EPS, KN, MU, VN, RHO = 0.002, 1e-5, 20000.0, 0.3, 0.1, 2500.0
LEVEL = 4


def _last_row(work):
    rows = []
    with open(os.path.join(work, "trace.txt")) as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                rows.append([float(x) for x in line.split()])
    check(len(rows) > 20 and all(r[8] == 0 for r in rows[-20:]) and
          any(r[8] > 0 for r in rows), "the ball touched the wall and left it")
    return rows[-1]  # time z vx vy vz omegax omegay omegaz contacts overlap mass


def _run(ctx, seed, vt, mu, kt):
    meshgen.write_stl(os.path.join(ctx.work, "ico.stl"), *meshgen.icosphere(LEVEL, R))
    meshgen.write_stl(os.path.join(ctx.work, "plane.stl"), *meshgen.plane(0.01))
    run_deck(ctx, DECK, dict(mesh="ico.stl", plane="plane.stl", R=R, eps=EPS, kn=KN,
                             kt="%.17g" % kt, mu=mu, vn=VN, vt="%.17g" % vt, seed=seed,
                             steps=700, out="trace.txt"))
    return _last_row(ctx.work)


def test_smooth_ball_head_on(ctx):
    """Frictionless, head-on: the ball leaves straight up at vn, not spinning."""
    for seed in (11, 22):
        row = _run(ctx, seed, 0.0, 0.0, KN)
        spin = max(abs(w) for w in row[5:8]) * R / VN
        check(spin < 1e-3, f"seed {seed}: spin {spin:.2e} x vn / R, expected < 1e-3")
        check(abs(row[4] / VN - 1.0) < 1e-3, f"seed {seed}: vz'/vn = {row[4] / VN:.6f}")
        print(f"seed {seed}: spin {spin:.2e} vn/R, vz'/vn {row[4] / VN:.6f}")


def test_smooth_ball_oblique(ctx):
    """kt = kn, vt = 0.3 vn (sticking, where a sphere's rebound is a near-cancellation of two
    lobes of the tangential force): vt' and omega' within 1 % of vt of the ideal ball's."""
    from ideal_ball import ideal_ball  # validation/contact/oblique/ideal_ball.py
    m, inertia = meshgen.mass_inertia(*meshgen.icosphere(LEVEL, R), RHO)
    vt = 0.3 * VN
    ref = ideal_ball(m, inertia, R, KN, KN, MU, VN, vt)  # the mesh is the contact surface
    row = _run(ctx, 33, vt, MU, KN)
    ev, ew = (row[2] - ref[0]) / vt, (row[6] - ref[2]) * R / vt
    check(abs(ev) < 0.01 and abs(ew) < 0.01,
          f"vt' off by {100 * ev:+.3f} %, omega' by {100 * ew:+.3f} % of vt (limit 1 %)")
    print(f"vt' {100 * ev:+.4f} %, omega' R {100 * ew:+.4f} % of vt")


def _run_pair(ctx, level, seed, vt, mu, kt):
    meshgen.write_stl(os.path.join(ctx.work, "ico.stl"), *meshgen.icosphere(level, R))
    run_deck(ctx, PAIR_DECK, dict(mesh="ico.stl", R=R, eps=EPS, kn=KN, kt="%.17g" % kt, mu=mu,
                                  vn=VN, vt="%.17g" % vt, seed=seed, steps=400,
                                  out="pair.txt"))
    rows = []
    with open(os.path.join(ctx.work, "pair.txt")) as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                rows.append([float(x) for x in line.split()])
    check(len(rows) > 20 and all(r[10] == 0 for r in rows[-20:]) and
          any(r[10] > 0 for r in rows), "the balls touched and parted")
    # time vx1 vy1 vz1 omegax1 omegay1 omegaz1 vx2 vy2 omegaz2 contacts overlap mass1
    return rows[-1]


def test_ball_pair_head_on(ctx):
    """Two 1280-triangle balls, frictionless, undamped, head-on: they part at the speed they
    met (restitution 1 within 1e-3, the facets gave 0.993) and without spin."""
    for seed in (11, 33):
        row = _run_pair(ctx, 3, seed, 0.0, 0.0, KN)
        e = -row[1] / (0.5 * VN)
        spin = max(abs(w) for w in row[4:7]) * R / (0.5 * VN)
        check(abs(e - 1.0) < 1e-3, f"seed {seed}: restitution {e:.6f}, expected 1 within 1e-3")
        check(spin < 1e-3, f"seed {seed}: spin {spin:.2e} x (vn / 2) / R, expected < 1e-3")
        check(abs(row[1] + row[7]) < 1e-12 * VN, "momentum: the balls part at opposite speeds")
        print(f"seed {seed}: restitution {e:.6f}, spin {spin:.2e} (vn / 2) / R")


def test_ball_pair_oblique(ctx):
    """kt = 2/7 kn, vt = vn (gross slip, then rolling): each ball's vt' and omega' within 1 %
    of its incoming tangential speed of the ideal pair's (the facets: 6 % in omega')."""
    from ideal_ball import ideal_pair  # validation/contact/oblique/ideal_ball.py
    m, inertia = meshgen.mass_inertia(*meshgen.icosphere(3, R), RHO)
    kt, vt = 2.0 / 7.0 * KN, VN
    ref = ideal_pair(m, inertia, R, KN, kt, MU, VN, vt)
    row = _run_pair(ctx, 3, 22, vt, MU, kt)
    half = 0.5 * vt
    ev, ew = (row[2] - ref[0]) / half, (row[6] - ref[2]) * R / half
    check(abs(ev) < 0.01 and abs(ew) < 0.01,
          f"vt' off by {100 * ev:+.3f} %, omega' by {100 * ew:+.3f} % of vt / 2 (limit 1 %)")
    print(f"vt' {100 * ev:+.4f} %, omega' R {100 * ew:+.4f} % of vt / 2")


def test_ball_on_a_cube_particle(ctx):
    """A 1280-triangle ball, turned in its file, strikes a cube particle at rest obliquely
    (kt = kn, vt = vn): it leaves as the ideal ball leaves a plane, vt' and omega' within 1 % of
    vt and vz' = vn within 1e-3."""
    from ideal_ball import ideal_ball  # validation/contact/oblique/ideal_ball.py
    verts, faces = meshgen.icosphere(3, R)
    c, s = math.cos(0.7), math.sin(0.7)  # a turn about (1, 1, 1) / sqrt(3)
    k = 1.0 / math.sqrt(3.0)
    rot = [[c + k * k * (1 - c), k * k * (1 - c) - k * s, k * k * (1 - c) + k * s],
           [k * k * (1 - c) + k * s, c + k * k * (1 - c), k * k * (1 - c) - k * s],
           [k * k * (1 - c) - k * s, k * k * (1 - c) + k * s, c + k * k * (1 - c)]]
    turned = [tuple(sum(rot[i][j] * v[j] for j in range(3)) for i in range(3)) for v in verts]
    meshgen.write_stl(os.path.join(ctx.work, "ball.stl"), turned, faces)
    meshgen.write_stl(os.path.join(ctx.work, "cube.stl"), *meshgen.cube(1, 0.02))
    vt = VN
    run_deck(ctx, CUBE_DECK, dict(mesh="ball.stl", cube="cube.stl", side=0.02, R=R, eps=EPS,
                                  kn=KN, kt=KN, mu=MU, vn=VN, vt=vt, out="trace.txt"))
    row = _last_row(ctx.work)
    m, inertia = meshgen.mass_inertia(verts, faces, RHO)
    ref = ideal_ball(m, inertia, R, KN, KN, MU, VN, vt)
    ev, ew = (row[2] - ref[0]) / vt, (row[6] - ref[2]) * R / vt
    check(abs(ev) < 0.01 and abs(ew) < 0.01,
          f"vt' off by {100 * ev:+.3f} %, omega' by {100 * ew:+.3f} % of vt (limit 1 %)")
    check(abs(row[4] / VN - 1.0) < 1e-3, f"vz'/vn = {row[4] / VN:.6f}")
    print(f"vt' {100 * ev:+.4f} %, omega' R {100 * ew:+.4f} % of vt, vz'/vn {row[4] / VN:.6f}")
