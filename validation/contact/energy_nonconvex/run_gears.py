#!/usr/bin/python3
"""Energy across contact-class changes of non-convex bodies: two gears (8 teeth, the mesh of
examples/falling) thrown at each other spinning, no damping, no friction, no gravity. The
kinetic energy after they separate against before, over 4 time steps, for the default
reduction (clusters) and the baseline `none` (one force per triangle contact: conservative
by construction up to the integrator).

  /usr/bin/python3 run_gears.py [--exe build/src_plugin/driver/liggghts-tri] [--work DIR] [--reuse]

Target (issue 10, item 4): |E_after / E_before - 1| <= 1e-4 at the default dt (1e-6 s here:
contact time pi sqrt(m_eff / kn) = 0.14 ms, 140 steps) and shrinking at least linearly with dt.
Prints the table, writes energy_nonconvex.png next to this script.
"""
import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(REPO, "validation"))
sys.path.insert(0, os.path.join(REPO, "tests", "decks"))
import valtools  # noqa: E402
from decklib import snapshots  # noqa: E402

GEAR = os.path.join(REPO, "examples", "falling", "meshes", "gear.stl")
DTS = [2e-6, 1e-6, 5e-7, 2.5e-7]
T_END = 6e-3  # s: they meet after about 1.5 ms and have separated by then
SEEDS = [1, 2, 3]
REDUCTIONS = ["clusters", "none"]


def energy(rows):
    e = 0.0
    for r in rows.values():
        m, vx, vy, vz, wx, wy, wz, lx, ly, lz = map(float, r)
        e += 0.5 * m * (vx * vx + vy * vy + vz * vz) + 0.5 * (wx * lx + wy * ly + wz * lz)
    return e


def run(exe, work, red, seed, dt, reuse):
    out = "gears_%s_s%d_dt%g.dump" % (red, seed, dt)
    path = os.path.join(work, out)
    if not (reuse and os.path.exists(path)):
        valtools.run_deck(exe, os.path.join(HERE, "in.gears"),
                          dict(gear=GEAR, seed=seed, red=red, dt=dt,
                               steps=int(round(T_END / dt)), out=out),
                          work, path + ".screen")
    snaps = snapshots(path)
    with open(os.path.join(work, "touch_" + out + ".txt")) as f:
        touch = [int(float(l)) for l in f if not l.startswith("#")]
    if not any(touch) or touch[-1] != 0:
        sys.exit("%s: the gears did not meet, or are still in contact at the end" % out)
    return energy(snaps[-1][1]) / energy(snaps[0][1]) - 1.0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", default=valtools.default_exe())
    ap.add_argument("--work", default="/tmp/liggghts-tri-validation/energy_nonconvex")
    ap.add_argument("--reuse", action="store_true")
    args = ap.parse_args()
    exe = os.path.abspath(args.exe)
    os.makedirs(args.work, exist_ok=True)
    err = {(red, seed, dt): run(exe, args.work, red, seed, dt, args.reuse)
           for red in REDUCTIONS for seed in SEEDS for dt in DTS}
    print(valtools.machine_line())
    print("two gears (examples/falling/meshes/gear.stl, scale 0.001), density 2500, eps 0.1 mm, "
          "kn 2000 N/m, no damping, no friction, relative speed 0.6 m/s, spinning")
    print()
    print("| reduction | orient seed | " + " | ".join("dE/E at dt %g s" % dt for dt in DTS)
          + " | ratio dt 2e-6 / dt 2.5e-7 |")
    print("|---|---|" + "---|" * len(DTS) + "---|")
    for red in REDUCTIONS:
        for seed in SEEDS:
            e = [err[(red, seed, dt)] for dt in DTS]
            ratio = abs(e[0]) / abs(e[-1]) if e[-1] != 0 else float("inf")
            print("| %s | %d | " % (red, seed) + " | ".join("%+.2e" % x for x in e)
                  + " | %.1f |" % ratio)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for red, style in zip(REDUCTIONS, ("-o", "--s")):
        for seed in SEEDS:
            ax.loglog(DTS, [max(1e-12, abs(err[(red, seed, dt)])) for dt in DTS], style,
                      label="%s, seed %d" % (red, seed))
    ax.loglog(DTS, [1e-4 * dt / 1e-6 for dt in DTS], "k:", label="first order through 1e-4 at 1e-6")
    ax.axhline(1e-4, color="gray", lw=0.8)
    ax.set_xlabel("dt (s)")
    ax.set_ylabel("|E_after / E_before - 1|")
    ax.set_title("Two gears colliding, no damping or friction")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    out = os.path.join(HERE, "energy_nonconvex.png")
    fig.savefig(out, dpi=110)
    print("plot:", out)


if __name__ == "__main__":
    main()
