#!/usr/bin/python3
"""Coulomb friction of a cube on a plane (fix tri/wall, tangential history): gravity tilted by
theta below and above atan(mu). Sticks below (displacement only the elastic tangential creep
m g sin(theta) / kt); slides above with a = g (sin theta - mu cos theta).

  /usr/bin/python3 run.py [--exe build/src_plugin/driver/liggghts-tri] [--work /tmp/...] [--reuse]

Sliding: a = least-squares slope of vx(t) over the second half of the tilted run.
Sticking: displacement from the moment of tilt to the end, and the drift over the last half.
Prints the table, writes friction.png next to this script.
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

S, N, MU, KT, G = 0.004, 2, 0.5, 1000.0, 9.81
THETAS = (10, 20, 25, 30, 35, 40)
TOL_A = 0.02


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", default=valtools.default_exe())
    ap.add_argument("--work", default="/tmp/liggghts-tri-validation/friction")
    ap.add_argument("--reuse", action="store_true")
    args = ap.parse_args()
    exe = os.path.abspath(args.exe)
    os.makedirs(args.work, exist_ok=True)
    meshgen.write_stl(os.path.join(args.work, "cube.stl"), *meshgen.cube(N, S))
    meshgen.write_stl(os.path.join(args.work, "plane.stl"), *meshgen.plane(0.015))
    res = []
    for th in THETAS:
        out = "tilt_%d.txt" % th
        if not (args.reuse and os.path.exists(os.path.join(args.work, out))):
            valtools.run_deck(exe, os.path.join(HERE, "in.tilt"),
                              dict(out=out, theta=th, mu=MU, kt=KT, mesh="cube.stl",
                                   plane="plane.stl", s=S),
                              args.work, os.path.join(args.work, out + ".screen"))
        rows = valtools.read_rows(os.path.join(args.work, out))
        m = rows[0][5]
        t = math.radians(th)
        half = rows[len(rows) // 2:]
        a_fit = valtools.slope([r[0] for r in half], [r[3] for r in half])
        a_an = G * (math.sin(t) - MU * math.cos(t))
        creep = m * G * math.sin(t) / KT
        r = dict(theta=th, rows=rows, a=a_fit, a_an=a_an, creep=creep,
                 disp=rows[-1][1] - rows[0][1], drift=rows[-1][1] - half[0][1],
                 wmax=max(abs(x[4]) for x in half), zrange=max(x[2] for x in half) -
                 min(x[2] for x in half), slides=math.tan(t) > MU)
        if r["slides"]:
            r["err"] = a_fit / a_an - 1
            r["ok"] = abs(r["err"]) <= TOL_A
        else:
            # sticks: no drift over the last half beyond 10 % of the elastic creep
            r["ok"] = abs(r["drift"]) <= 0.1 * creep
        res.append(r)

    print(valtools.machine_line())
    print("cube N=%d (%d triangles), side %g m, mass %.6g kg, mu = %g (atan mu = %.2f deg), "
          "kt = %g N/m; defaults of in.tilt otherwise" % (N, 12 * N * N, S, res[0]["rows"][0][5],
                                                        MU, math.degrees(math.atan(MU)), KT))
    print()
    print("| theta (deg) | regime | analytic a (m/s^2) | measured a (m/s^2) | error a |"
          " displacement (um) | elastic creep (um) | drift last half (um) | max abs(omega_y)"
          " last half (rad/s) | z range last half (um) | pass |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in res:
        print("| %d | %s | %.4f | %.4f | %s | %.3f | %.3f | %.3f | %.3g | %.3f | %s |" % (
            r["theta"], "slide" if r["slides"] else "stick", max(r["a_an"], 0.0), r["a"],
            "%+.1f%%" % (100 * r["err"]) if r["slides"] else "-", 1e6 * r["disp"],
            1e6 * r["creep"], 1e6 * r["drift"], r["wmax"], 1e6 * r["zrange"],
            "PASS" if r["ok"] else "FAIL"))
    print()
    print("%d/%d pass" % (sum(r["ok"] for r in res), len(res)))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(13, 4.8))
    th = [x / 10 for x in range(0, 451)]
    ax[0].plot(th, [max(0.0, G * (math.sin(math.radians(x)) - MU * math.cos(math.radians(x))))
                    for x in th], "k-", label="analytic g(sin theta - mu cos theta), 0 if stuck")
    ax[0].plot([r["theta"] for r in res], [r["a"] for r in res], "o", color="C3",
               label="measured (slope of vx, second half)")
    ax[0].axvline(math.degrees(math.atan(MU)), color="C2", ls="--", label="atan(mu)")
    ax[0].set_xlabel("tilt theta (deg)")
    ax[0].set_ylabel("acceleration along the incline (m/s^2)")
    ax[0].legend(fontsize=8)
    ax[0].grid(alpha=0.3)
    for r, c in zip(res, ("C0", "C1", "C2", "C3", "C4", "C5")):
        ax[1].plot([1e3 * (x[0] - r["rows"][0][0]) for x in r["rows"]],
                   [x[3] for x in r["rows"]], color=c, label="theta = %d deg" % r["theta"])
        if r["slides"]:
            ax[1].plot([0, 1e3 * (r["rows"][-1][0] - r["rows"][0][0])],
                       [0, r["a_an"] * (r["rows"][-1][0] - r["rows"][0][0])], "--", color=c,
                       lw=0.8)
    ax[1].set_xlabel("time since tilt (ms)")
    ax[1].set_ylabel("vx (m/s); dashed: analytic")
    ax[1].legend(fontsize=8)
    ax[1].grid(alpha=0.3)
    fig.suptitle("Cube (%d triangles) on a plane under tilted gravity, mu = %g" % (12 * N * N, MU))
    fig.tight_layout()
    out = os.path.join(HERE, "friction.png")
    fig.savefig(out, dpi=110)
    print("plot:", out)
    return 0 if all(r["ok"] for r in res) else 1


if __name__ == "__main__":
    sys.exit(main())
