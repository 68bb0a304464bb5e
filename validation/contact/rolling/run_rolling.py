#!/usr/bin/python3
"""Rolling without spurious rolling resistance: icospheres (1280 and 5120 triangles) rolling
down a 20 degree incline in the smooth regime (soft contact: static overlap ~50 um, far above
the facets' sag of 9 um and 2 um), gamman 0 and 200, against the rigid-body acceleration for
the ball's own inertia and lever; a stiff contact (overlap 0.4 um, below the sag) beside it.

  /usr/bin/python3 run_rolling.py [--exe build/src_plugin/driver/liggghts-tri] [--work DIR] [--reuse]

Rigid body rolling without slip with rolling radius r (the lever: the distance of the centre
from the contact line, measured as r = (dv/dt) / (d omega_y/dt)) and moment of inertia I about
a horizontal axis through the centre (integrated from the mesh here, density 2500; the deck's
mass is checked against it): a = g sin(theta) / (1 + I / (m r^2)). Measured: least-squares
slopes of v_x(t) and omega_y(t) from 10 ms after the tilt to the end (80 ms). Target: within
1 % for the soft runs. Prints the table, writes rolling.png next to this script.
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
import valtools  # noqa: E402

R, RHO, G, THETA, MU, DT = 0.002, 2500.0, 9.81, 20.0, 0.5, 1e-5
TOL = 0.01
SKIP = 0.01  # s after the tilt before the fit
# name, icosphere level, kn (N/m), gamman (1/s); kt = 2/7 kn, gammat = 200 1/s in all runs
CASES = [
    ("soft", 3, 15.0, 0.0),
    ("soft", 3, 15.0, 200.0),
    ("soft", 4, 15.0, 0.0),
    ("soft", 4, 15.0, 200.0),
    ("stiff", 3, 2000.0, 200.0),
    ("stiff", 4, 2000.0, 200.0),
]
GAMMAT = 200.0


def name_of(c):
    kind, level, kn, gn = c
    return "%s_l%d_g%d" % (kind, level, gn)


def mesh_mass_inertia(level):
    """Mass and moment of inertia about an axis through the centre of the closed mesh,
    density RHO (meshgen.mass_inertia)."""
    return meshgen.mass_inertia(*meshgen.icosphere(level, R), RHO)


def run_case(exe, work, c, reuse):
    kind, level, kn, gn = c
    out = name_of(c) + ".txt"
    path = os.path.join(work, out)
    if not (reuse and os.path.exists(path)):
        valtools.run_deck(exe, os.path.join(HERE, "in.roll"),
                          dict(out=out, theta=THETA, mu=MU, mesh="ico%d.stl" % level,
                               plane="plane.stl", r=R, kn=kn, kt=kn * 2.0 / 7.0, gamman=gn,
                               gammat=GAMMAT, dt=DT),
                          work, path + ".screen")
    return np.array(valtools.read_rows(path))


def analyse(c, rows):
    kind, level, kn, gn = c
    m, inertia = mesh_mass_inertia(level)
    t = rows[:, 0]
    sel = t > t[0] + SKIP
    a = np.polyfit(t[sel], rows[sel, 3], 1)[0]
    alpha = np.polyfit(t[sel], rows[sel, 6], 1)[0]
    r = a / alpha
    a_rigid = G * math.sin(math.radians(THETA)) / (1.0 + inertia / (m * r * r))
    err = a / a_rigid - 1.0
    # the lowest point above the plane's surface: a faceted ball hops when it leaves contact
    return dict(case=c, rows=rows, m=m, inertia=inertia, deck_mass=rows[0, 8], a=a, r=r,
                a_rigid=a_rigid, err=err, ok=(kind != "soft" or abs(err) <= TOL))


def plot(res, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.5))
    for r in res:
        kind, level, kn, gn = r["case"]
        rows = r["rows"]
        t = rows[:, 0] - rows[0, 0]
        label = "%d tri, kn %g, gamman %g" % (20 * 4 ** level, kn, gn)
        ax[0].plot(t * 1e3, rows[:, 3], lw=1, label=label)
        ax[1].plot(t * 1e3, (rows[:, 3] - r["a_rigid"] * t - rows[0, 3]) * 1e3, lw=1,
                   label=label)
        if kind == "stiff":
            ax[2].plot(t * 1e3, (rows[:, 2] - rows[0, 2]) * 1e6, lw=0.8, label=label)
    ax[0].set_xlabel("time after the tilt (ms)")
    ax[0].set_ylabel("v_x (m/s)")
    ax[0].set_title("speed down the incline")
    ax[0].legend(fontsize=7)
    ax[1].set_xlabel("time after the tilt (ms)")
    ax[1].set_ylabel("v_x - v_rigid (mm/s)")
    ax[1].set_title("against the rigid-body line (own I and lever)")
    ax[1].legend(fontsize=7)
    ax[2].set_xlabel("time after the tilt (ms)")
    ax[2].set_ylabel("z - z_0 (um)")
    ax[2].set_title("stiff contact: the centre's height (facets)")
    ax[2].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", default=valtools.default_exe())
    ap.add_argument("--work", default="/tmp/liggghts-tri-validation/rolling")
    ap.add_argument("--reuse", action="store_true")
    args = ap.parse_args()
    exe = os.path.abspath(args.exe)
    os.makedirs(args.work, exist_ok=True)
    for level in (3, 4):
        meshgen.write_stl(os.path.join(args.work, "ico%d.stl" % level),
                          *meshgen.icosphere(level, R))
    meshgen.write_stl(os.path.join(args.work, "plane.stl"), *meshgen.plane(0.016, 1))
    res = [analyse(c, run_case(exe, args.work, c, args.reuse)) for c in CASES]
    print(valtools.machine_line())
    print("icosphere vertex radius %g m, density %g, theta %g deg, mu %g, kt = 2/7 kn, "
          "gammat = %g 1/s, eps = 0.1 mm, dt = %g s" % (R, RHO, THETA, MU, GAMMAT, DT))
    print()
    print("| contact | triangles | kn (N/m) | gamman (1/s) | mass (kg) | I (kg m^2) | lever r (mm) "
          "| rigid-body a (m/s^2) | measured a (m/s^2) | error | pass |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in res:
        kind, level, kn, gn = r["case"]
        assert abs(r["deck_mass"] / r["m"] - 1) < 1e-9, (r["deck_mass"], r["m"])
        print("| %s | %d | %g | %g | %.6g | %.6g | %.5f | %.5f | %.5f | %+.2f%% | %s |"
              % (kind, 20 * 4 ** level, kn, gn, r["m"], r["inertia"], r["r"] * 1e3,
                 r["a_rigid"], r["a"], 100 * r["err"],
                 ("PASS" if r["ok"] else "FAIL") if kind == "soft" else "(shown)"))
    n_soft = sum(1 for r in res if r["case"][0] == "soft")
    print()
    print("%d/%d soft runs within %g %%" % (sum(1 for r in res if r["case"][0] == "soft"
                                                and r["ok"]), n_soft, 100 * TOL))
    out = os.path.join(HERE, "rolling.png")
    plot(res, out)
    print("plot:", out)


if __name__ == "__main__":
    main()
