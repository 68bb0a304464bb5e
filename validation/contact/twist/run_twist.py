#!/usr/bin/python3
"""Twisting friction of a face contact: a 4 mm cube spinning about the normal of a plane is
braked by Coulomb friction spread over its face, stops, and stays at rest; resting and stopped
cubes on a plane and on inclines below atan(mu) neither turn nor walk.

  /usr/bin/python3 run_twist.py [--exe build/src_plugin/driver/liggghts-tri] [--work DIR] [--reuse]
                                [--layer inside|outside]

Spin: omega_z(t) fitted by a line while 0.85 > omega_z / omega_0 > 0.15; analytic rate
mu F_n r_mean / I_zz = 6 mu g cos(theta) r_mean / s^2, with r_mean = s (sqrt 2 + asinh 1) / 6 the
mean distance of a square face from its centre (I_zz = m s^2 / 6). The face in contact is the
flat of the contact surface: with the layer inside the mesh (the default) the cube's edges are
rounded with radius eps, and the flat is a square of side s - 2 eps (r_mean 5 % shorter than
the mesh face's); with `--layer outside`, the whole face, side s. Target: within 3 %.
Rest: over the last 0.1 s of the run (which starts at least 10 ms after the cube stopped):
max |omega| < 1e-5 rad/s, largest displacement from the window's first position < 1e-8 m.
Prints the tables, writes twist.png next to this script.
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

S, MU, G, DT, EPS = 0.004, 0.3, 9.81, 1e-5, 1e-4
LAYER = "inside"  # set by --layer


def r_mean():
    """Mean distance from its centre of the flat face in contact (side s - 2 eps, layer inside)."""
    side = S - 2 * EPS if LAYER == "inside" else S
    return side * (math.sqrt(2.0) + math.asinh(1.0)) / 6.0


TOL_RATE, TOL_OMEGA, TOL_DRIFT, WINDOW = 0.03, 1e-5, 1e-8, 0.1
SETTLE = 3000  # steps before the spin / push / measurement (30 ms)

# name, cube N (12 N^2 triangles), plane N (2 N^2 triangles), theta (deg), spin (rad/s), vx0,
# steps after settling
CASES = [
    ("spin", 1, 1, 0, 20.0, 0.0, 13000),
    ("spin", 4, 1, 0, 20.0, 0.0, 13000),
    ("spin", 1, 16, 0, 20.0, 0.0, 13000),
    ("spin", 4, 16, 0, 20.0, 0.0, 13000),
    ("spin", 4, 16, 10, 20.0, 0.0, 18000),
    ("rest", 1, 1, 0, 0.0, 0.0, 11100),
    ("rest", 4, 16, 0, 0.0, 0.0, 11100),
    ("rest", 1, 1, 5, 0.0, 0.0, 11100),
    ("rest", 4, 1, 10, 0.0, 0.0, 11100),
    ("rest", 1, 16, 15, 0.0, 0.0, 11100),
    ("rest", 4, 16, 15, 0.0, 0.0, 11100),
    ("slide", 1, 1, 0, 0.0, 0.05, 18000),
    ("slide", 4, 16, 10, 0.0, 0.05, 18000),
]


def name_of(c):
    kind, n, pn, th, spin, vx0, _ = c
    return "%s_c%d_p%d_t%d" % (kind, n, pn, th)


def run_case(exe, work, c, reuse):
    kind, n, pn, th, spin, vx0, steps = c
    out = name_of(c) + ".txt"
    path = os.path.join(work, out)
    if not (reuse and os.path.exists(path)):
        valtools.run_deck(exe, os.path.join(HERE, "in.twist"),
                          dict(out=out, theta=th, mu=MU, mesh="cube%d.stl" % n,
                               plane="plane%d.stl" % pn, s=S, spin=spin, vx0=vx0,
                               settle=SETTLE, steps=steps, dt=DT, eps=EPS, layer=LAYER),
                          work, path + ".screen")
    return valtools.read_rows(path)


def analyse(c, rows):
    kind, n, pn, th, spin, vx0, _ = c
    t0 = rows[0][0]
    r = dict(case=c, rows=rows, t0=t0, kind=kind)
    rate = 6.0 * MU * G * math.cos(math.radians(th)) * r_mean() / S ** 2
    r["rate_an"] = rate
    if kind == "spin":
        w0 = rows[0][8]
        sel = [x for x in rows if 0.15 * w0 < x[8] < 0.85 * w0]
        r["rate"] = -valtools.slope([x[0] for x in sel], [x[8] for x in sel])
        r["err"] = r["rate"] / rate - 1
    # Stopped: the first time after which the cube never again moves faster than 1e-5 m/s or
    # turns faster than 1e-4 rad/s.
    stop = t0
    for x in rows:
        if (math.hypot(x[4], x[5]) > 1e-5 or max(abs(x[6]), abs(x[7]), abs(x[8])) > 1e-4):
            stop = x[0]
    r["stop"] = stop - t0
    t_end = rows[-1][0]
    win = [x for x in rows if x[0] >= t_end - WINDOW - 1e-12]
    r["window_ok"] = win[0][0] >= stop + 0.01 - 1e-9
    r["wmax"] = max(math.sqrt(x[6] ** 2 + x[7] ** 2 + x[8] ** 2) for x in win)
    r["drift"] = max(math.sqrt((x[1] - win[0][1]) ** 2 + (x[2] - win[0][2]) ** 2 +
                               (x[3] - win[0][3]) ** 2) for x in win)
    r["ok_rest"] = r["window_ok"] and r["wmax"] < TOL_OMEGA and r["drift"] < TOL_DRIFT
    r["ok"] = r["ok_rest"] and (kind != "spin" or th != 0 or abs(r["err"]) <= TOL_RATE)
    return r


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", default=valtools.default_exe())
    ap.add_argument("--work", default="/tmp/liggghts-tri-validation/twist")
    ap.add_argument("--reuse", action="store_true")
    ap.add_argument("--only", default="", help="run only the cases whose name contains this")
    ap.add_argument("--layer", default="inside", choices=("inside", "outside"),
                    help="fix tri/particles layer (default inside: the mesh is the contact surface)")
    args = ap.parse_args()
    global LAYER
    LAYER = args.layer
    exe = os.path.abspath(args.exe)
    os.makedirs(args.work, exist_ok=True)
    for n in (1, 4):
        meshgen.write_stl(os.path.join(args.work, "cube%d.stl" % n), *meshgen.cube(n, S))
    for pn in (1, 16):
        meshgen.write_stl(os.path.join(args.work, "plane%d.stl" % pn), *meshgen.plane(0.015, pn))
    res = [analyse(c, run_case(exe, args.work, c, args.reuse)) for c in CASES
           if args.only in name_of(c)]

    print(valtools.machine_line())
    print("cube side %g m, mass %.6g kg, mu = %g (atan mu = %.2f deg), kn = 2000 N/m, "
          "kt = 1000 N/m, gamman = gammat = 3000 1/s, dt = %g s; eps = %g m, layer %s; r_mean = %.6g m"
          % (S, res[0]["rows"][0][9], MU, math.degrees(math.atan(MU)), DT, EPS, LAYER, r_mean()))
    print()
    print("| case | cube triangles | plane triangles | theta (deg) | start | analytic rate "
          "(rad/s^2) | measured rate (rad/s^2) | error | stopped after (ms) | max abs(omega) "
          "last 0.1 s (rad/s) | drift last 0.1 s (m) | pass |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in res:
        kind, n, pn, th, spin, vx0, _ = r["case"]
        start = ("omega_z %g rad/s" % spin if kind == "spin" else
                 "vx %g m/s" % vx0 if kind == "slide" else "at rest")
        spin_cols = ("%.1f | %.1f | %+.2f%%" % (r["rate_an"] if th == 0 else float("nan"),
                                                 r["rate"], 100 * r["err"])
                     if kind == "spin" else "- | - | -")
        if kind == "spin" and th != 0:
            spin_cols = "- (shared with sliding) | %.1f | -" % r["rate"]
        print("| %s | %d | %d | %d | %s | %s | %.1f | %.2e | %.2e | %s |" % (
            kind, 12 * n * n, 2 * pn * pn, th, start, spin_cols, 1e3 * r["stop"], r["wmax"],
            r["drift"], "PASS" if r["ok"] else "FAIL"))
    print()
    print("%d/%d pass" % (sum(r["ok"] for r in res), len(res)))
    if args.only:
        return 0 if all(r["ok"] for r in res) else 1

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 3, figsize=(16, 4.8))
    for r in res:
        if r["kind"] != "spin":
            continue
        kind, n, pn, th, spin, vx0, _ = r["case"]
        t = [1e3 * (x[0] - r["t0"]) for x in r["rows"]]
        ax[0].plot(t, [x[8] for x in r["rows"]],
                   label="%d-triangle cube, %d-triangle plane, %d deg" % (12 * n * n, 2 * pn * pn, th))
    w0 = res[0]["rows"][0][8]
    ta = w0 / res[0]["rate_an"]
    ax[0].plot([0, 1e3 * ta], [w0, 0], "k--", lw=1, label="distributed Coulomb, flat plane")
    ax[0].set_xlim(0, 1e3 * 1.5 * ta)
    ax[0].set_xlabel("time since spin-up (ms)")
    ax[0].set_ylabel("omega_z (rad/s)")
    ax[0].legend(fontsize=7)
    ax[0].grid(alpha=0.3)
    for r in res:
        kind, n, pn, th, spin, vx0, _ = r["case"]
        t_end = r["rows"][-1][0]
        win = [x for x in r["rows"] if x[0] >= t_end - WINDOW - 1e-12]
        lab = "%s %d/%d tri, %d deg" % (kind, 12 * n * n, 2 * pn * pn, th)
        ax[1].semilogy([1e3 * (x[0] - win[0][0]) for x in win],
                       [max(1e-16, math.sqrt(x[6] ** 2 + x[7] ** 2 + x[8] ** 2)) for x in win],
                       lw=0.8, label=lab)
        ax[2].semilogy([1e3 * (x[0] - win[0][0]) for x in win],
                       [max(1e-16, math.sqrt((x[1] - win[0][1]) ** 2 + (x[2] - win[0][2]) ** 2 +
                                             (x[3] - win[0][3]) ** 2)) for x in win],
                       lw=0.8, label=lab)
    ax[1].axhline(TOL_OMEGA, color="k", ls="--", lw=1)
    ax[2].axhline(TOL_DRIFT, color="k", ls="--", lw=1)
    ax[1].set_xlabel("time in the last 0.1 s (ms)")
    ax[1].set_ylabel("|omega| (rad/s); dashed: target")
    ax[2].set_xlabel("time in the last 0.1 s (ms)")
    ax[2].set_ylabel("displacement from the window's start (m); dashed: target")
    ax[1].legend(fontsize=6, ncol=2)
    ax[1].grid(alpha=0.3)
    ax[2].grid(alpha=0.3)
    fig.suptitle("Twisting friction of a 4 mm cube face on a plane, mu = %g" % MU)
    fig.tight_layout()
    out = os.path.join(HERE, "twist.png" if LAYER == "inside" else "twist_outside.png")
    fig.savefig(out, dpi=110)
    print("plot:", out)
    return 0 if all(r["ok"] for r in res) else 1


if __name__ == "__main__":
    sys.exit(main())
