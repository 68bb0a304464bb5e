#!/usr/bin/python3
"""Oblique impacts in the sphere limit: icospheres of 1280, 5120 and 20480 triangles (levels
3, 4, 5; fix tri/wall, tangential history) hitting a plane wall obliquely, against an ideal
ball of the icosphere's own mass, inertia and lever, and LIGGGHTS's own spheres (pair gran /
fix wall/gran model hooke/stiffness tangential history).

  /usr/bin/python3 run.py [--exe build/src_plugin/driver/liggghts-tri] [--work /tmp/oblique]
                          [--liggghts /usr/bin/liggghts] [--layer inside|outside] [--eps EPS]

Normal speed VN along -z, tangential speed vt = ratio x VN along +x (ratios 0.1, 0.3, 1, 3), no
spin, no gravity; linear springs kn, kt = 2/7 kn and kt = kn, gamman = gammat = 0, mu 0.3.
Measured after the ball has left the wall: vt' = vx and omega' = omega_y. The reference is
`ideal_ball` below, a replica of LIGGGHTS's hooke/stiffness wall contact with tangential
history and nve/sphere's velocity Verlet; it is first checked against LIGGGHTS spheres (its
m, I = 2/5 m r^2, r), then run with the icosphere's mesh mass, mesh inertia and the tri
contact lever: the contact point is midway through the overlap of the contact surfaces, as
LIGGGHTS's r - overlap/2: R - overlap/2 with the layer inside the mesh (the default: the
mesh, vertices at R, is the contact surface; the wall has no layer), R + eps - overlap/2 with
`--layer outside` (the contact surface the mesh grown by eps, the wall's layer eps). eps: 10 um (the peak overlap, 6.5 um, fits the particle's layer, the wall
contact's only one); `--layer outside --eps 5e-6` is the earlier deck (10 um of layers in all). Errors: (vt'_tri - vt'_ref) / vt and
(omega'_tri - omega'_ref) R / vt, vt the incoming tangential speed. Prints the README tables,
writes oblique.png next to this script. Needs Debian's numpy and matplotlib (/usr/bin/python3).
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
from ideal_ball import DT, GAP, STEPS, ideal_ball  # noqa: E402
import valtools  # noqa: E402

R, RHO = 0.002, 2500.0                  # m, kg/m^3
EPS = 1e-5                              # m, soft layer (--eps)
LAYER = "inside"                        # --layer: the particle's layer inside its mesh (default)
KN, MU, VN = 20000.0, 0.3, 0.1           # N/m, -, m/s
LEVELS = (3, 4, 5)
RATIOS = (0.1, 0.3, 1.0, 3.0)            # vt / vn
SERIES = (("2/7", 2.0 / 7.0), ("1", 1.0))  # kt / kn
SEEDS = (11, 22, 33, 44)                 # orient random SEED: four orientations
TOL = 0.01
QUIET = 20                               # the last QUIET rows must be out of contact


def mesh_mass_inertia(level):
    """Mass and moment of inertia about an axis through the centre of the closed mesh,
    density RHO (meshgen.mass_inertia)."""
    return meshgen.mass_inertia(*meshgen.icosphere(level, R), RHO)


def facets(level):
    """(largest sag R - distance of a face's plane from the centre, i.e. R (1 - cos of the
    largest half facet angle), mean edge length)."""
    verts, faces = meshgen.icosphere(level, R)
    v = np.array(verts)
    a, b, c = (v[[f[k] for f in faces]] for k in range(3))
    n = np.cross(b - a, c - a)
    d = np.einsum("ij,ij->i", a, n) / np.linalg.norm(n, axis=1)
    edges = np.concatenate([np.linalg.norm(b - a, axis=1), np.linalg.norm(c - b, axis=1),
                            np.linalg.norm(a - c, axis=1)])
    return R - d.min(), edges.mean()


def after(path, contact_col):
    """The last row of a trace (time z vx vy vz wx wy wz contact ...), checked to be out of
    contact for the last QUIET rows and to have touched at all."""
    rows = np.array(valtools.read_rows(path))
    assert np.any(rows[:, contact_col] != 0), (path, "no contact")
    assert np.all(rows[-QUIET:, contact_col] == 0), (path, "still in contact at the end")
    return rows[-1], rows


def main():
    global EPS, LAYER
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", default=valtools.default_exe())
    ap.add_argument("--liggghts", default="/usr/bin/liggghts")
    ap.add_argument("--work", default="/tmp/oblique")
    ap.add_argument("--layer", default="inside", choices=("inside", "outside"),
                    help="fix tri/particles layer (default inside: the mesh is the contact surface)")
    ap.add_argument("--eps", type=float, default=EPS, help="soft layer (m), default 1e-5")
    args = ap.parse_args()
    EPS, LAYER = args.eps, args.layer
    # the wall contact's soft layers: the particle's (inside), or the particle's and the wall's
    layers = EPS if LAYER == "inside" else 2 * EPS
    exe = os.path.abspath(args.exe)
    os.makedirs(args.work, exist_ok=True)
    for level in LEVELS:
        meshgen.write_stl(os.path.join(args.work, "ico%d.stl" % level),
                          *meshgen.icosphere(level, R))
    meshgen.write_stl(os.path.join(args.work, "plane.stl"), *meshgen.plane(0.01))

    mass = {lv: mesh_mass_inertia(lv) for lv in LEVELS}
    # the tri lever at zero overlap in the sphere limit: where the contact surfaces meet
    # (inside: the mesh, R; outside: the mesh grown by eps meets the wall's layer, R + eps)
    lever0 = R if LAYER == "inside" else R + EPS
    res = {}                  # (level, series, ratio) -> dict
    check = []                # the reference against LIGGGHTS spheres
    peak = 0.0
    for level in LEVELS:
        m, inertia = mass[level]
        for sname, kfac in SERIES:
            kt = kfac * KN
            for ratio in RATIOS:
                vt = ratio * VN
                common = dict(kn=KN, kt="%.17g" % kt, mu=MU, vn=VN, vt="%.17g" % vt, gap=GAP,
                              dt=DT, steps=STEPS)
                # LIGGGHTS sphere: radius = the tri lever at zero overlap, the mesh mass
                # (its inertia is 2/5 m r^2, not the mesh's)
                name = "sphere_l%d_kt%s_r%g.txt" % (level, sname.replace("/", "_"), ratio)
                valtools.run_deck(args.liggghts, os.path.join(HERE, "in.sphere"),
                                  dict(out=name, plane="plane.stl", r="%.17g" % lever0,
                                       mass="%.17g" % m, **common),
                                  args.work, os.path.join(args.work, name + ".screen"))
                srow, _ = after(os.path.join(args.work, name), 8)
                assert abs(srow[10] / m - 1) < 1e-12, (name, srow[10], m)
                isph = 0.4 * srow[10] * lever0 ** 2
                rv = ideal_ball(srow[10], isph, lever0, KN, kt, MU, VN, vt)
                check.append(max(abs(rv[0] - srow[2]) / vt, abs(rv[2] - srow[6]) * R / vt,
                                 abs(rv[1] - srow[4]) / VN))
                ref = ideal_ball(m, inertia, lever0, KN, kt, MU, VN, vt)
                ev, ew, off, vz = [], [], [], []
                for seed in SEEDS:
                    name = "tri_l%d_kt%s_r%g_s%d.txt" % (level, sname.replace("/", "_"),
                                                        ratio, seed)
                    valtools.run_deck(exe, os.path.join(HERE, "in.tri"),
                                      dict(out=name, mesh="ico%d.stl" % level,
                                           plane="plane.stl", R=R, eps=EPS, seed=seed,
                                           layer=LAYER, **common),
                                      args.work, os.path.join(args.work, name + ".screen"))
                    row, rows = after(os.path.join(args.work, name), 8)
                    assert abs(row[10] / m - 1) < 1e-9, (name, row[10], m)
                    peak = max(peak, rows[:, 9].max())
                    ev.append((row[2] - ref[0]) / vt)
                    ew.append((row[6] - ref[2]) * R / vt)
                    vz.append(row[4] / VN)
                    # out of the impact plane: sideways speed and spin about x and z
                    off.append(max(abs(row[3]) / vt, abs(row[5]) * R / vt,
                                   abs(row[7]) * R / vt))
                res[level, sname, ratio] = dict(
                    ref=ref, sphere=(srow[2], srow[4], srow[6]), ev=np.array(ev),
                    ew=np.array(ew), off=np.array(off), vz=np.array(vz))

    # diagnostic: a head-on frictionless impact (vt = 0, mu = 0) of the same icospheres; an
    # ideal ball leaves with vz' = vn and no spin
    normal = {}
    for level in LEVELS:
        spins, bounce = [], []
        for seed in SEEDS:
            name = "normal_l%d_s%d.txt" % (level, seed)
            valtools.run_deck(exe, os.path.join(HERE, "in.tri"),
                              dict(out=name, mesh="ico%d.stl" % level, plane="plane.stl", R=R,
                                   eps=EPS, seed=seed, kn=KN, kt=KN, mu=0, vn=VN, vt=0,
                                   gap=GAP, dt=DT, steps=STEPS, layer=LAYER),
                              args.work, os.path.join(args.work, name + ".screen"))
            row, _ = after(os.path.join(args.work, name), 8)
            spins.append(math.sqrt(row[5] ** 2 + row[6] ** 2 + row[7] ** 2) * R / VN)
            bounce.append(row[4] / VN - 1)
        normal[level] = (np.array(spins), np.array(bounce))

    print(valtools.machine_line())
    tc = math.pi * math.sqrt(mass[5][0] / KN)
    print("icosphere vertex radius R = %g m, density %g, epsilon = %g m (layer %s: %s), "
          "kn = %g N/m, gamman = gammat = 0, mu = %g, vn = %g m/s, dt = %g s (contact time "
          "pi sqrt(m / kn) = %.3g s = %d steps), %d steps; peak overlap %.3g m (in the wall "
          "contact's layers %g m; spring estimate vn sqrt(m / kn) = %.3g m); orientations: orient "
          "random %s" % (R, RHO, EPS, LAYER, "the particle's only" if LAYER == "inside" else
                         "the particle's and the wall's", KN, MU, VN, DT, tc, round(tc / DT),
                         STEPS, peak, layers, VN * math.sqrt(mass[5][0] / KN),
                         " ".join(map(str, SEEDS))))
    print()
    print("| level | triangles | mean edge (um) | facet sag R (1 - cos) (um) | mass (kg) | "
          "I mesh (kg m^2) | I / (2/5 m R^2) | I / (2/5 m lever0^2) |")
    print("|---|---|---|---|---|---|---|---|")
    for level in LEVELS:
        m, inertia = mass[level]
        sag, edge = facets(level)
        print("| %d | %d | %.1f | %.3f | %.6g | %.6g | %.5f | %.5f |" % (
            level, 20 * 4 ** level, 1e6 * edge, 1e6 * sag, m, inertia,
            inertia / (0.4 * m * R * R), inertia / (0.4 * m * lever0 ** 2)))
    print()
    print("reference (ideal_ball) against LIGGGHTS spheres (r = lever0 = %s = %g m, the mesh "
          "mass, I = 2/5 m r^2), %d runs: worst |difference| of vt', vz', omega' R = %.2g x the "
          "incoming speed" % ("R" if LAYER == "inside" else "R + eps", lever0,
                              len(check), max(check)))
    print()
    print("Errors against the ideal ball of the icosphere's mass and inertia, lever %s - "
          "overlap/2: e_v = (vt'_tri - vt'_ref) / vt, e_w = (omega'_tri - omega'_ref) R / vt; "
          "mean (signed) and worst |.| over the %d orientations; off-plane: worst of |vy'|, "
          "|omega_x'| R, |omega_z'| R over vt" % ("R" if LAYER == "inside" else "R + eps",
                                                  len(SEEDS)))
    print()
    print("| kt / kn | vt / vn | level | vt'/vt ref | omega' R / vt ref | LIGGGHTS sphere "
          "vt'/vt, omega' R/vt | e_v mean | e_v worst | e_w mean | e_w worst | off-plane "
          "worst | pass (1 %) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for sname, _ in SERIES:
        for ratio in RATIOS:
            for level in LEVELS:
                r = res[level, sname, ratio]
                vt = ratio * VN
                worst = max(np.abs(r["ev"]).max(), np.abs(r["ew"]).max())
                print("| %s | %g | %d | %.5f | %.5f | %.5f, %.5f | %+.3f%% | %.3f%% | %+.3f%% | "
                      "%.3f%% | %.3f%% | %s |" % (
                          sname, ratio, level, r["ref"][0] / vt, r["ref"][2] * R / vt,
                          r["sphere"][0] / vt, r["sphere"][2] * R / vt,
                          100 * r["ev"].mean(), 100 * np.abs(r["ev"]).max(),
                          100 * r["ew"].mean(), 100 * np.abs(r["ew"]).max(),
                          100 * r["off"].max(),
                          ("PASS" if worst <= TOL else "FAIL") if level == 5 else "-"))
    n5 = [(s, q) for s, _ in SERIES for q in RATIOS]
    ok = sum(1 for s, q in n5 if max(np.abs(res[5, s, q]["ev"]).max(),
                                     np.abs(res[5, s, q]["ew"]).max()) <= TOL)
    print()
    print("level 5: %d/%d (series, ratio) cases with vt' and omega' within %g %% in every "
          "orientation" % (ok, len(n5), 100 * TOL))
    for lv in LEVELS:
        rvz = [abs(res[lv, s, q]["vz"] - 1).max() for s, _ in SERIES for q in RATIOS]
        wv = max(max(np.abs(res[lv, s, q]["ev"]).max(), np.abs(res[lv, s, q]["ew"]).max())
                 * q / math.hypot(1, q) for s, _ in SERIES for q in RATIOS)
        print("level %d: worst |vz'/vn - 1| = %.3f%% (the ideal ball: 0, gamman = 0); worst "
              "error of vt', omega' R normalised by the impact speed sqrt(vn^2 + vt^2) instead "
              "of vt: %.3f%%" % (lv, 100 * max(rvz), 100 * wv))
    print()
    print("Diagnostic: head-on frictionless impact (vt = 0, mu = 0; the ideal ball leaves with "
          "vz' = vn and no spin), over the %d orientations:" % len(SEEDS))
    print()
    print("| level | |omega'| R / vn mean | |omega'| R / vn worst | vz'/vn - 1 mean | "
          "vz'/vn - 1 worst |")
    print("|---|---|---|---|---|")
    for lv in LEVELS:
        sp, bo = normal[lv]
        print("| %d | %.3f%% | %.3f%% | %+.4f%% | %+.4f%% |" % (
            lv, 100 * sp.mean(), 100 * sp.max(), 100 * bo.mean(),
            100 * bo[np.argmax(np.abs(bo))]))

    from error_plot import plot_errors
    plot_errors(res, LEVELS, SERIES, RATIOS, TOL,
                "|error| / incoming vt (%)  [omega': x R / vt]",
                "Oblique impact on a plane: icosphere (fix tri/wall) against the ideal ball of "
                "its mass, inertia and lever; lines: worst of %d orientations, open markers: "
                "mean |error|\nkn %g N/m, eps %g um (layer %s), vn %g m/s, mu %g, gamman = "
                "gammat = 0" % (len(SEEDS), KN, 1e6 * EPS, LAYER, VN, MU),
                os.path.join(HERE, "oblique.png" if LAYER == "inside" else "oblique_outside.png"),
                means=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
