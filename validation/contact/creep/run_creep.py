#!/usr/bin/python3
"""Creep at 97 % of the friction limit: 4 mm cubes of 12, 48, 192 and 768 triangles resting on
an incline with tan(theta) = 0.97 mu (mu = 0.3: theta = 16.22 deg), on a 2- and a 512-triangle
plane, must not move beyond their elastic tangential spring.

  /usr/bin/python3 run_creep.py [--exe build/src_plugin/driver/liggghts-tri] [--work DIR] [--reuse]

The deck is the twist case's (../twist/in.twist, `rest`: no spin, no push): the cube lands,
settles for 30 ms, then runs 111 ms more. The elastic spring's displacement is
m g sin(theta) / kt (0.44 um); a creeping contact keeps moving downhill. Measured: the largest
displacement from the position at the end of the settling (30 ms) to the end of the run,
and over the last 0.1 s. Target: both below 1e-8 m (no motion; the spring is already loaded).
Prints the table, writes creep.png next to this script.
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

DECK = os.path.join(REPO, "validation", "contact", "twist", "in.twist")
S, MU, G, DT, KT = 0.004, 0.3, 9.81, 1e-5, 1000.0
FRACTION = 0.97
THETA = math.degrees(math.atan(FRACTION * MU))
TOL, WINDOW = 1e-8, 0.1
SETTLE, STEPS = 3000, 11100
CASES = [(n, pn) for n in (1, 2, 4, 8) for pn in (1, 16)]  # cube N (12 N^2), plane N (2 N^2)


def run_case(exe, work, n, pn, reuse):
    out = "creep_c%d_p%d.txt" % (n, pn)
    path = os.path.join(work, out)
    if not (reuse and os.path.exists(path)):
        valtools.run_deck(exe, DECK, dict(out=out, theta="%.12g" % THETA, mu=MU,
                                          mesh="cube%d.stl" % n, plane="plane%d.stl" % pn, s=S,
                                          spin=0, vx0=0, settle=SETTLE, steps=STEPS, dt=DT),
                          work, path + ".screen")
    return valtools.read_rows(path)


def largest_displacement(rows):
    x0 = rows[0]
    return max(math.sqrt(sum((x[k] - x0[k]) ** 2 for k in (1, 2, 3))) for x in rows)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", default=valtools.default_exe())
    ap.add_argument("--work", default="/tmp/liggghts-tri-validation/creep")
    ap.add_argument("--reuse", action="store_true")
    args = ap.parse_args()
    exe = os.path.abspath(args.exe)
    os.makedirs(args.work, exist_ok=True)
    for n in (1, 2, 4, 8):
        meshgen.write_stl(os.path.join(args.work, "cube%d.stl" % n), *meshgen.cube(n, S))
    for pn in (1, 16):
        meshgen.write_stl(os.path.join(args.work, "plane%d.stl" % pn), *meshgen.plane(0.015, pn))
    res = []
    for n, pn in CASES:
        rows = run_case(exe, args.work, n, pn, args.reuse)
        t_end = rows[-1][0]
        win = [x for x in rows if x[0] >= t_end - WINDOW - 1e-12]
        mass = rows[0][9]
        res.append(dict(n=n, pn=pn, rows=rows, total=largest_displacement(rows),
                        window=largest_displacement(win), mass=mass,
                        wmax=max(math.sqrt(x[6] ** 2 + x[7] ** 2 + x[8] ** 2) for x in win)))
    elastic = res[0]["mass"] * G * math.sin(math.radians(THETA)) / KT
    print(valtools.machine_line())
    print("cube side %g m, mass %.6g kg, mu = %g, theta = %.4f deg (tan theta = %g mu), kn = 2000 "
          "N/m, kt = %g N/m, gamman = gammat = 3000 1/s, dt = %g s; elastic spring "
          "m g sin(theta) / kt = %.4g m" % (S, res[0]["mass"], MU, THETA, FRACTION, KT, DT,
                                           elastic))
    print()
    print("| cube triangles | plane triangles | displacement after settling (m) | displacement "
          "last 0.1 s (m) | max abs(omega) last 0.1 s (rad/s) | pass |")
    print("|---|---|---|---|---|---|")
    for r in res:
        r["ok"] = r["total"] < TOL and r["window"] < TOL
        print("| %d | %d | %.2e | %.2e | %.2e | %s |" % (12 * r["n"] ** 2, 2 * r["pn"] ** 2,
                                                     r["total"], r["window"], r["wmax"],
                                                     "PASS" if r["ok"] else "FAIL"))
    print()
    print("%d/%d pass" % (sum(r["ok"] for r in res), len(res)))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for r in res:
        x0 = r["rows"][0]
        ax.semilogy([1e3 * (x[0] - x0[0]) for x in r["rows"]],
                    [max(1e-18, math.sqrt(sum((x[k] - x0[k]) ** 2 for k in (1, 2, 3))))
                     for x in r["rows"]], lw=0.8,
                    label="%d-triangle cube, %d-triangle plane" % (12 * r["n"] ** 2,
                                                                   2 * r["pn"] ** 2))
    ax.axhline(TOL, color="k", ls="--", lw=1, label="target 1e-8 m")
    ax.axhline(elastic, color="gray", ls=":", lw=1, label="elastic spring m g sin / kt")
    ax.set_xlabel("time after settling (ms)")
    ax.set_ylabel("displacement from the settled position (m)")
    ax.set_title("Cubes at %g %% of the friction limit (theta %.2f deg, mu %g)"
                 % (100 * FRACTION, THETA, MU))
    ax.legend(fontsize=6)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    out = os.path.join(HERE, "creep.png")
    fig.savefig(out, dpi=110)
    print("plot:", out)
    return 0 if all(r["ok"] for r in res) else 1


if __name__ == "__main__":
    sys.exit(main())
