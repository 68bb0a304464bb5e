#!/usr/bin/python3
"""Ball meets ball: two equal icospheres of 1280, 5120 and 20480 triangles (levels 3, 4, 5;
pair tri/gran, tangential history) meeting head-on with a tangential speed, against two ideal
balls of the icosphere's own mass and inertia (ideal_ball.py ideal_pair, a replica of
LIGGGHTS's pair gran hooke/stiffness contact with tangential history and nve/sphere) and
LIGGGHTS's own spheres; and a ball on another particle's facets: the same icospheres (levels
3, 4) striking a cube particle at rest (in.on_cube), against the ideal ball on a plane.

  /usr/bin/python3 run_pairs.py [--exe build/src_plugin/driver/liggghts-tri] [--work /tmp/oblique_pairs]
                                [--liggghts /usr/bin/liggghts] [--plot] [--label NAME]

Relative normal speed VN along x, relative tangential speed vt = ratio x VN along y (ratios
0.1, 0.3, 1, 3), each ball at half of it, no spin, no gravity; linear springs kn, kt = 2/7 kn
and kt = kn, gamman = gammat = 0, mu 0.3; four orientation seeds per case (each ball turned
its own way). Measured after the balls have parted: ball 1's vt' = vy, vn' = -vx and
omega' = omega_z. The reference is first checked against LIGGGHTS sphere pairs (their m,
I = 2/5 m r^2, r = R), then run with the mesh's mass and inertia. Errors: (vt'_tri - vt'_ref) /
(vt / 2) and (omega'_tri - omega'_ref) R / (vt / 2), each ball's incoming tangential speed
being vt / 2. A head-on frictionless diagnostic gives the restitution (ideal: 1) and the spin
left. The ball on the cube: as run.py's wall impacts (errors over the incoming vt), each ball
turned in its file by a random rotation of seed 11, 22, 33, 44 (`orient file`: the cube stays
square to the axes). Prints the README tables; with --plot writes oblique_pairs.png next to
this script.
--exe of an older build shows what it did (the README's comparison). Needs Debian's numpy and
matplotlib (/usr/bin/python3).
"""
import argparse
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(REPO, "validation", "meshes"))
sys.path.insert(0, os.path.join(REPO, "validation"))
import meshgen  # noqa: E402
from ideal_ball import DT, GAP, STEPS, ideal_ball, ideal_pair  # noqa: E402
import valtools  # noqa: E402

R, RHO, EPS = 0.002, 2500.0, 1e-5
KN, MU, VN = 20000.0, 0.3, 0.1
LEVELS = (3, 4, 5)
RATIOS = (0.1, 0.3, 1.0, 3.0)
SERIES = (("2/7", 2.0 / 7.0), ("1", 1.0))
SEEDS = (11, 22, 33, 44)
TOL = 0.01
QUIET = 20
CONTACT_COL = 10  # in.pair's `contacts` column
CUBE_LEVELS, CUBE_SIDE = (3, 4), 0.02


def after(path, contact_col=CONTACT_COL):
    """The last row of a trace, checked to be out of contact for the last QUIET rows and to
    have touched at all."""
    rows = np.array(valtools.read_rows(path))
    assert np.any(rows[:, contact_col] != 0), (path, "no contact")
    assert np.all(rows[-QUIET:, contact_col] == 0), (path, "still in contact at the end")
    return rows[-1]


def run(exe, deck, work, name, values, contact_col=CONTACT_COL):
    valtools.run_deck(exe, os.path.join(HERE, deck), dict(out=name, **values), work,
                      os.path.join(work, name + ".screen"))
    return after(os.path.join(work, name), contact_col)


def turned(verts, seed):
    """verts turned by a random rotation (a uniform unit quaternion from `seed`)."""
    q = np.random.default_rng(seed).normal(size=4)
    w, x, y, z = q / np.linalg.norm(q)
    rot = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                    [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                    [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])
    return [tuple(rot @ np.array(v)) for v in verts]


def on_cube(exe, work, mass):
    """The icospheres on the top face of a cube particle at rest: (level, series, ratio) ->
    the worst |error| of vt' and omega' R over vt, over the seeds, and the worst |vz'/vn - 1|."""
    meshgen.write_stl(os.path.join(work, "cube.stl"), *meshgen.cube(1, CUBE_SIDE))
    out = {}
    for level in CUBE_LEVELS:
        verts, faces = meshgen.icosphere(level, R)
        for seed in SEEDS:
            meshgen.write_stl(os.path.join(work, "ico%d_s%d.stl" % (level, seed)),
                              turned(verts, seed), faces)
        m, inertia = mass[level]
        for sname, kfac in SERIES:
            for ratio in RATIOS:
                vt = ratio * VN
                ref = ideal_ball(m, inertia, R, KN, kfac * KN, MU, VN, vt)
                worst, bounce = 0.0, 0.0
                for seed in SEEDS:
                    row = run(exe, "in.on_cube", work, "cube_l%d_kt%s_r%g_s%d.txt" % (
                        level, sname.replace("/", "_"), ratio, seed),
                        dict(mesh="ico%d_s%d.stl" % (level, seed), cube="cube.stl",
                             side=CUBE_SIDE, R=R, eps=EPS, kn=KN, kt="%.17g" % (kfac * KN),
                             mu=MU, vn=VN, vt="%.17g" % vt, gap=GAP, dt=DT, steps=STEPS),
                        contact_col=8)
                    worst = max(worst, abs(row[2] - ref[0]) / vt, abs(row[6] - ref[2]) * R / vt)
                    bounce = max(bounce, abs(row[4] / VN - 1.0))
                out[level, sname, ratio] = (worst, bounce)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", default=valtools.default_exe())
    ap.add_argument("--liggghts", default="/usr/bin/liggghts")
    ap.add_argument("--work", default="/tmp/oblique_pairs")
    ap.add_argument("--plot", action="store_true", help="write oblique_pairs.png")
    args = ap.parse_args()
    exe = os.path.abspath(args.exe)
    os.makedirs(args.work, exist_ok=True)
    mass = {}
    for level in LEVELS:
        verts, faces = meshgen.icosphere(level, R)
        meshgen.write_stl(os.path.join(args.work, "ico%d.stl" % level), verts, faces)
        mass[level] = meshgen.mass_inertia(verts, faces, RHO)

    res, check = {}, []
    for level in LEVELS:
        m, inertia = mass[level]
        for sname, kfac in SERIES:
            kt = kfac * KN
            for ratio in RATIOS:
                vt = ratio * VN
                half = 0.5 * vt
                common = dict(kn=KN, kt="%.17g" % kt, mu=MU, vn=VN, vt="%.17g" % vt, gap=GAP,
                              dt=DT, steps=STEPS)
                tag = "l%d_kt%s_r%g" % (level, sname.replace("/", "_"), ratio)
                srow = run(args.liggghts, "in.sphere_pair", args.work, "sphere_%s.txt" % tag,
                           dict(r=R, mass="%.17g" % m, **common))
                rs = ideal_pair(srow[12], 0.4 * srow[12] * R * R, R, KN, kt, MU, VN, vt)
                check.append(max(abs(rs[0] - srow[2]) / half, abs(rs[1] + srow[1]) / (0.5 * VN),
                                 abs(rs[2] - srow[6]) * R / half))
                ref = ideal_pair(m, inertia, R, KN, kt, MU, VN, vt)
                ev, ew, off = [], [], []
                for seed in SEEDS:
                    row = run(exe, "in.pair", args.work, "tri_%s_s%d.txt" % (tag, seed),
                              dict(mesh="ico%d.stl" % level, R=R, eps=EPS, seed=seed, **common))
                    assert abs(row[12] / m - 1) < 1e-9, (tag, row[12], m)
                    ev.append((row[2] - ref[0]) / half)
                    ew.append((row[6] - ref[2]) * R / half)
                    off.append(max(abs(row[3]) / half, abs(row[4]) * R / half,
                                   abs(row[5]) * R / half))
                res[level, sname, ratio] = dict(ref=ref, ev=np.array(ev), ew=np.array(ew),
                                                off=np.array(off))
    normal = {}
    for level in LEVELS:
        bounce, spins = [], []
        for seed in SEEDS:
            row = run(exe, "in.pair", args.work, "normal_l%d_s%d.txt" % (level, seed),
                      dict(mesh="ico%d.stl" % level, R=R, eps=EPS, seed=seed, kn=KN, kt=KN,
                           mu=0, vn=VN, vt=0, gap=GAP, dt=DT, steps=STEPS))
            bounce.append(-row[1] / (0.5 * VN) - 1.0)
            spins.append(math.sqrt(row[4] ** 2 + row[5] ** 2 + row[6] ** 2) * R / (0.5 * VN))
        sphere = run(args.liggghts, "in.sphere_pair", args.work, "normal_sphere_l%d.txt" % level,
                     dict(r=R, mass="%.17g" % mass[level][0], kn=KN, kt=KN, mu=0, vn=VN, vt=0,
                          gap=GAP, dt=DT, steps=STEPS))
        normal[level] = (np.array(bounce), np.array(spins), -sphere[1] / (0.5 * VN) - 1.0)
    cube = on_cube(exe, args.work, mass)
    report(args, res, check, normal)
    report_cube(cube)
    if args.plot:
        plot(res)
    return 0


def report(args, res, check, normal):
    print(valtools.machine_line())
    print("binary: %s" % os.path.abspath(args.exe))
    print("icosphere vertex radius R = %g m, density %g, epsilon = %g m (inside the mesh), kn = "
          "%g N/m, gamman = gammat = 0, mu = %g, relative vn = %g m/s, dt = %g s, %d steps; "
          "orientations: orient random %s" % (R, RHO, EPS, KN, MU, VN, DT, STEPS,
                                              " ".join(map(str, SEEDS))))
    print()
    print("reference (ideal_pair) against LIGGGHTS sphere pairs (r = R, the mesh mass, I = 2/5 m "
          "r^2), %d runs: worst |difference| of vt', vn', omega' R = %.2g x the incoming speed"
          % (len(check), max(check)))
    print()
    print("| kt / kn | vt / vn | level | vt'/vt ref | omega' R / vt ref | e_v mean | e_v worst | "
          "e_w mean | e_w worst | off-plane worst | pass (1 %) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for sname, _ in SERIES:
        for ratio in RATIOS:
            for level in LEVELS:
                r = res[level, sname, ratio]
                half = 0.5 * ratio * VN
                worst = max(np.abs(r["ev"]).max(), np.abs(r["ew"]).max())
                print("| %s | %g | %d | %.5f | %.5f | %+.3f%% | %.3f%% | %+.3f%% | %.3f%% | "
                      "%.3f%% | %s |" % (
                          sname, ratio, level, r["ref"][0] / half, r["ref"][2] * R / half,
                          100 * r["ev"].mean(), 100 * np.abs(r["ev"]).max(),
                          100 * r["ew"].mean(), 100 * np.abs(r["ew"]).max(),
                          100 * r["off"].max(), "PASS" if worst <= TOL else "FAIL"))
    for level in LEVELS:
        cases = [(s, q) for s, _ in SERIES for q in RATIOS]
        ok = sum(1 for s, q in cases if max(np.abs(res[level, s, q]["ev"]).max(),
                                            np.abs(res[level, s, q]["ew"]).max()) <= TOL)
        print("level %d: %d/%d (series, ratio) cases with vt' and omega' within %g %% in every "
              "orientation" % (level, ok, len(cases), 100 * TOL))
    print()
    print("Head-on, frictionless (vt = 0, mu = 0; ideal balls part at the speed they met, "
          "without spin), over the %d orientations:" % len(SEEDS))
    print()
    print("| level | restitution - 1, worst | LIGGGHTS spheres, restitution - 1 | "
          "|omega'| R / (vn / 2) worst |")
    print("|---|---|---|---|")
    for level in LEVELS:
        bo, sp, sph = normal[level]
        print("| %d | %+.2e | %+.2e | %.2e |" % (level, bo[np.argmax(np.abs(bo))], sph,
                                                 sp.max()))


def report_cube(cube):
    print()
    print("A ball on a cube particle at rest (side %g m, 12 triangles): worst |error| of vt' and "
          "omega' R over vt against the ideal ball on a plane, and worst |vz'/vn - 1|, over the "
          "%d turns:" % (CUBE_SIDE, len(SEEDS)))
    print()
    print("| kt / kn | vt / vn | " + " | ".join("level %d: vt', omega' | level %d: vz'" % (lv, lv)
                                              for lv in CUBE_LEVELS) + " |")
    print("|---|---|" + "---|---|" * len(CUBE_LEVELS))
    for sname, _ in SERIES:
        for ratio in RATIOS:
            print("| %s | %g | " % (sname, ratio) + " | ".join(
                "%.3f%% | %.4f%%" % (100 * cube[lv, sname, ratio][0],
                                     100 * cube[lv, sname, ratio][1]) for lv in CUBE_LEVELS)
                  + " |")


def plot(res):
    from error_plot import plot_errors
    plot_errors(res, LEVELS, SERIES, RATIOS, TOL,
                "worst |error| over %d orientations / incoming vt (%%)" % len(SEEDS),
                "Ball meets ball: two icospheres (pair tri/gran) against two ideal balls of "
                "their mass and inertia\nkn %g N/m, eps %g um, relative vn %g m/s, mu %g, "
                "gamman = gammat = 0" % (KN, 1e6 * EPS, VN, MU),
                os.path.join(HERE, "oblique_pairs.png"))

if __name__ == "__main__":
    sys.exit(main())
