#!/usr/bin/python3
"""Energy across contact-class changes of non-convex bodies: two gears (8 teeth, the mesh of
examples/falling), two voxel jacks (a cube with an arm on each face, 7 cubes of 1 mm) or two
voxel U shapes (7 cubes of 1 mm), and for comparison two convex random rocks (40 triangles,
4 mm), thrown at each other spinning, no damping, no friction, no
gravity. The kinetic energy after they separate against before, over 4 time steps, for the
default reduction (clusters) and the baseline `none` (one force per triangle contact:
conservative by construction up to the integrator).

  /usr/bin/python3 run_gears.py [--exe build/src_plugin/driver/liggghts-tri] [--work DIR] [--reuse]
                                [--shapes gear jack u rock] [--bodies 2|6]

--bodies 6: six bodies (jacks, U shapes or rocks) thrown from the corners of an octahedron
towards its centre (in.six), meeting two, three and four at a time, over 15 ms.

Target (issue 10, item 4): |E_after / E_before - 1| <= 1e-4 at the default dt (1e-6 s here:
contact time pi sqrt(m_eff / kn) = 0.14 ms for the gears, 140 steps) and shrinking at least
linearly with dt.
Prints the table, writes energy_nonconvex.png next to this script.
"""
import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(REPO, "validation"))
sys.path.insert(0, os.path.join(REPO, "tests", "decks"))
sys.path.insert(0, os.path.join(REPO, "validation", "meshes"))
import meshgen  # noqa: E402
import valtools  # noqa: E402
from decklib import snapshots  # noqa: E402

GEAR = os.path.join(REPO, "examples", "falling", "meshes", "gear.stl")
DTS = [2e-6, 1e-6, 5e-7, 2.5e-7]
T_END = {2: 6e-3, 6: 15e-3}  # s: two meet after about 1.5 ms, six within 6 ms; all apart by then
DECK = {2: "in.gears", 6: "in.six"}
SEEDS = [1, 2, 3]
REDUCTIONS = ["clusters", "none"]
# Voxel shapes, cells of 1 (mm after the deck's scale 0.001): a jack (a cube with an arm on
# each face) and a U (three cubes wide, three deep).
VOXELS = {
    "jack": [(0, 0, 0)] + [tuple(s if k == a else 0 for k in range(3))
                           for a in range(3) for s in (-1, 1)],
    "u": [(0, 0, 0), (1, 0, 0), (2, 0, 0), (0, 1, 0), (0, 2, 0), (2, 1, 0), (2, 2, 0)],
}
NAMES = {"gear": "two gears (examples/falling/meshes/gear.stl, scale 0.001)",
         "rock": "two convex random rocks (in.gears: 40 triangles, 4 mm)",
         "jack": "two voxel jacks (7 cubes of 1 mm: a cube with an arm on each face)",
         "u": "two voxel U shapes (7 cubes of 1 mm, 3 x 3 mm)"}


def mesh_file(shape, work):
    if shape == "gear":
        return GEAR
    if shape == "rock":
        return None
    path = os.path.join(work, shape + ".stl")
    meshgen.write_stl(path, *meshgen.voxels(VOXELS[shape], 1.0), name=shape)
    return path


def energy(rows):
    e = 0.0
    for r in rows.values():
        m, vx, vy, vz, wx, wy, wz, lx, ly, lz = map(float, r)
        e += 0.5 * m * (vx * vx + vy * vy + vz * vz) + 0.5 * (wx * lx + wy * ly + wz * lz)
    return e


def run(exe, work, mesh, shape, red, seed, dt, reuse, bodies):
    out = "%s_%d_%s_s%d_dt%g.dump" % (shape, bodies, red, seed, dt)
    path = os.path.join(work, out)
    if not (reuse and os.path.exists(path)):
        variables = dict(seed=seed, red=red, dt=dt, steps=int(round(T_END[bodies] / dt)),
                         out=out)
        if mesh:
            variables["gear"] = mesh
        else:
            variables["kind"] = "rock"
        valtools.run_deck(exe, os.path.join(HERE, DECK[bodies]), variables, work,
                          path + ".screen")
    snaps = snapshots(path)
    with open(os.path.join(work, "touch_" + out + ".txt")) as f:
        touch = [int(float(l)) for l in f if not l.startswith("#")]
    if not any(touch) or touch[-1] != 0:
        sys.exit("%s: the bodies did not meet, or are still in contact at the end" % out)
    return energy(snaps[-1][1]) / energy(snaps[0][1]) - 1.0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", default=valtools.default_exe())
    ap.add_argument("--work", default="/tmp/liggghts-tri-validation/energy_nonconvex")
    ap.add_argument("--reuse", action="store_true")
    ap.add_argument("--shapes", nargs="+", default=None, choices=list(NAMES),
                    help="default: gear jack u rock (two bodies), jack u rock (six)")
    ap.add_argument("--bodies", type=int, default=2, choices=[2, 6])
    args = ap.parse_args()
    if args.shapes is None:
        args.shapes = ["gear", "jack", "u", "rock"] if args.bodies == 2 else ["jack", "u", "rock"]
    exe = os.path.abspath(args.exe)
    os.makedirs(args.work, exist_ok=True)
    err = {}
    for shape in args.shapes:
        mesh = mesh_file(shape, args.work)
        for red in REDUCTIONS:
            for seed in SEEDS:
                for dt in DTS:
                    err[(shape, red, seed, dt)] = run(exe, args.work, mesh, shape, red, seed, dt,
                                                      args.reuse, args.bodies)
    print(valtools.machine_line())
    print("density 2500, eps 0.1 mm, kn 2000 N/m, no damping, no friction, relative speed "
          "0.6 m/s, spinning; %d bodies of each: " % args.bodies +
          "; ".join(NAMES[s].replace("two ", "") for s in args.shapes))
    print()
    print("| bodies | reduction | orient seed | " +
          " | ".join("dE/E at dt %g s" % dt for dt in DTS) + " | ratio dt 2e-6 / dt 2.5e-7 |")
    print("|---|---|---|" + "---|" * len(DTS) + "---|")
    for shape in args.shapes:
        for red in REDUCTIONS:
            for seed in SEEDS:
                e = [err[(shape, red, seed, dt)] for dt in DTS]
                ratio = abs(e[0]) / abs(e[-1]) if e[-1] != 0 else float("inf")
                print("| %s | %s | %d | " % (shape, red, seed) +
                      " | ".join("%+.2e" % x for x in e) + " | %.1f |" % ratio)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(args.shapes), figsize=(4.2 * len(args.shapes), 4.2),
                             sharey=True, squeeze=False)
    for ax, shape in zip(axes[0], args.shapes):
        for red, style in zip(REDUCTIONS, ("-o", "--s")):
            for seed in SEEDS:
                ax.loglog(DTS, [max(1e-12, abs(err[(shape, red, seed, dt)])) for dt in DTS],
                          style, label="%s, seed %d" % (red, seed))
        ax.loglog(DTS, [1e-4 * dt / 1e-6 for dt in DTS], "k:",
                  label="first order through 1e-4 at 1e-6")
        ax.axhline(1e-4, color="gray", lw=0.8)
        ax.set_xlabel("dt (s)")
        ax.set_xticks(DTS)
        ax.set_xticklabels(["%g" % dt for dt in DTS])
        ax.minorticks_off()
        ax.set_title({"gear": "gears", "jack": "voxel jacks", "u": "voxel U shapes",
                      "rock": "convex rocks"}[shape])
        ax.grid(alpha=0.3, which="both")
    axes[0][0].set_ylabel("|E_after / E_before - 1|")
    axes[0][0].legend(fontsize=6)
    fig.suptitle("%s non-convex bodies (and convex rocks) colliding, no damping or friction"
                 % {2: "Two", 6: "Six"}[args.bodies])
    fig.tight_layout()
    out = os.path.join(HERE, "energy_nonconvex.png" if args.bodies == 2 else
                       "energy_nonconvex_six.png")
    fig.savefig(out, dpi=110)
    print("plot:", out)


if __name__ == "__main__":
    main()
