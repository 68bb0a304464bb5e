#!/usr/bin/python3
"""Angle of repose (validation/bulk): a slumping quasi-2D column of cubes (and icospheres) against
LIGGGHTS spheres.

  python3 validation/bulk/repose.py [--cases spheres cube ico320] [--seeds 2] [--case-seeds ico320=1] [--n 420]
      [--work /tmp/repose] [--reuse] [--plot-only]

Protocol: a box periodic in y, Wy = 6 d deep (4 d, with a 3-batch insertion region, stops LIGGGHTS 3.8
in insert/pack: "assertion failed (./src/region_neighbor_list_I.h:165)") (d = 4 mm, the volume-equivalent diameter), between
mesh end walls at x = 0 and x = L = 40 d, on a sawtooth mesh floor (ridges along y, pitch d,
height d/4, so that spheres cannot roll away). N particles are placed at random (insert/pack,
overlap check; in 3 batches) in x [0, a], a = 6 d, behind a mesh gate at x = a, rain at 1 m/s (fix viscous) and
settle (translational kinetic energy below 1e-3 N m g d). The gate (its fix mesh/surface and its
wall fix) is then unfixed, the column slumps towards +x and settles again (at least 0.3 s, then
until the same kinetic-energy criterion, at most 1.5 s). Material as in the packing study: LIGGGHTS
hooke, Y 5e6 Pa, poissonsRatio 0.45, e 0.5, mu 0.5 (particle-particle and particle-wall),
characteristicVelocity 1 m/s; dt 3e-5 s (mesh particles) and 2e-5 s (spheres), run_bulk's.
Decks: repose_setup.in, repose_run.in, in.repose_tri (liggghts-tri: tri/particles epsilon auto,
tri/gran, tri/wall, tri/nve), in.repose_spheres (plain liggghts: gran, wall/gran, nve/sphere).

Angle: the final centres are binned in x (bins of width d); the free surface is the highest centre
in each bin; a straight line is fitted to the bins whose surface height lies between 20 % and 80 %
of the highest bin's (the middle of the slope, above the floor layer and below the top corner;
the bin against the end wall x = 0 is left out of both);
angle = atan(-slope). Reported per run with the fit's standard error, per case as the mean over
seeds +- their standard deviation. Writes results/repose.json and repose.png next to this script.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import run_bulk  # noqa: E402
from run_bulk import D, MASS, G, meshgen, valtools  # noqa: E402

WY, A, L = 6 * D, 6 * D, 40 * D
RIDGE = D / 4
SEEDS = [67867967, 86028121, 122949823, 141650939]
CASES = {"spheres": dict(kind="sphere"),
         "cube": dict(kind="tri", shape="cube", ntri=12),
         "tetrahedron": dict(kind="tri", shape="tetrahedron", ntri=4),
         "ico320": dict(kind="tri", shape="icosphere2", ntri=320)}
NBATCH = 3
REACH = 0.003          # cube bounding radius 2.79 mm + layer: sizes the insertion region for all


def rect(v, f, p0, p1, p2, p3):
    """Two triangles p0 p1 p2, p0 p2 p3 (counter-clockwise seen from the side the normal points to)."""
    i = len(v)
    v += [p0, p1, p2, p3]
    f += [(i, i + 1, i + 2), (i, i + 2, i + 3)]


def box_mesh(h):
    """Sawtooth floor over x [0, L] plus the end walls x = 0 and x = L up to h (normals inwards)."""
    v, f = [], []
    y0, y1 = -WY / 2, WY / 2
    n = int(round(L / D))
    for k in range(n):
        xs = [k * D, (k + 0.5) * D, (k + 1) * D]
        zs = [0.0, RIDGE, 0.0]
        for j in range(2):
            rect(v, f, (xs[j], y0, zs[j]), (xs[j + 1], y0, zs[j + 1]),
                 (xs[j + 1], y1, zs[j + 1]), (xs[j], y1, zs[j]))
    rect(v, f, (0, y0, 0), (0, y1, 0), (0, y1, h), (0, y0, h))          # normal +x
    rect(v, f, (L, y0, 0), (L, y0, h), (L, y1, h), (L, y1, 0))          # normal -x
    return v, f


def gate_mesh(h):
    v, f = [], []
    rect(v, f, (A, -WY / 2, 0), (A, -WY / 2, h), (A, WY / 2, h), (A, WY / 2, 0))   # normal -x
    return v, f


def geometry(n):
    """Insertion in NBATCH batches of n / NBATCH particles, TEVERY apart, in a region above the
    column, the particles' bounding spheres 25 % of its volume."""
    vol = math.pi / 6.0 * D ** 3
    bed = n * vol / (0.5 * A * WY)                       # a loose column
    zlo = bed + 2 * REACH + 0.005
    zhi = zlo + n / NBATCH * 4.0 / 3.0 * math.pi * REACH ** 3 / (0.25 * A * WY)
    tevery = 1.1 * (zhi - zlo) + 0.01                    # the region is empty again at 1 m/s
    return dict(zlo=zlo, zhi=zhi, H=zhi + 0.005, tevery=tevery,
                tpour=(NBATCH - 1) * tevery + 1.05 * zhi + 0.05)


def read_centres(path):
    """[(x, y, z)] of a write_dump custom file: id type mass x y z."""
    return [(r[3], r[4], r[5]) for r in run_bulk.dump_rows(path)]


def surface(rows, width=D):
    """[(bin centre x, highest centre z)] for the occupied x-bins of the given width from x = 0."""
    top = {}
    for x, _, z in rows:
        k = int(math.floor(x / width))
        top[k] = max(top.get(k, -1.0), z)
    return [((k + 0.5) * width, top[k]) for k in sorted(top)]


def fit_angle(rows, lo=0.2, hi=0.8):
    s = surface(rows)
    # the first bin (against the end wall x = 0) left out: the wall holds particles up there
    htop = max(z for x, z in s if x > D)
    pts = [(x, z) for x, z in s if x > D and lo * htop <= z <= hi * htop]
    n = len(pts)
    if n < 3:
        return dict(angle=float("nan"), err=float("nan"), npts=n, surface=s)
    mx = sum(x for x, _ in pts) / n
    mz = sum(z for _, z in pts) / n
    sxx = sum((x - mx) ** 2 for x, _ in pts)
    b = sum((x - mx) * (z - mz) for x, z in pts) / sxx
    c = mz - b * mx
    res = sum((z - c - b * x) ** 2 for x, z in pts)
    sb = math.sqrt(res / (n - 2) / sxx)
    ang = math.degrees(math.atan(-b))
    err = math.degrees(sb / (1 + b * b))
    return dict(angle=ang, err=err, slope=b, intercept=c, npts=n, htop=htop,
                xfit=[min(x for x, _ in pts), max(x for x, _ in pts)], surface=s,
                toe=max(x for x, _, z in rows))


def run_case(name, seed, args, geo, meshdir, box, gate):
    c = CASES[name]
    tag = f"{name}_s{seed}"
    out = os.path.join(args.work, tag)
    os.makedirs(out, exist_ok=True)
    screen = os.path.join(out, "screen.txt")
    dump = os.path.join(out, "final.dump")
    v = dict(L=L, Wy=WY, H=geo["H"], box=box, gate=gate, Y=5e6, xi0=0, xi1=A, nbatch=args.n // NBATCH,
             nbatches=NBATCH, tevery=geo["tevery"], zlo=geo["zlo"],
             zhi=geo["zhi"], seed=SEEDS[seed], gamma=MASS * G / 1.0, tpour=geo["tpour"],
             tchunk=0.02, nsettle=15, nslump=60, tmin=0.3, kemin=1e-3 * args.n * MASS * G * D,
             out=out)
    if c["kind"] == "tri":
        v.update(dt=run_bulk.DT_TRI[5e6], shape=run_bulk.shape_file(c["shape"], meshdir),
                 oseed=99 + seed)
        exe, deck = args.exe, "in.repose_tri"
    else:
        v.update(dt=run_bulk.DT_SPHERE[5e6])
        exe, deck = args.liggghts, "in.repose_spheres"
    cmd = ["nice", "-n", "10"] + valtools.deck_command(exe, os.path.join(HERE, deck), v,
                                                         os.path.join(out, "log.lammps"))
    wall_file = os.path.join(out, "wall_s.txt")
    if not (args.reuse and os.path.exists(dump)):
        if os.path.exists(dump):
            os.remove(dump)
        r, wall = run_bulk.run_logged(cmd, screen, tag)
        with open(wall_file, "w") as f:
            f.write(f"{wall:.3f}\n")
        if r.returncode != 0 or not os.path.exists(dump):
            info = run_bulk.parse_screen(screen)
            print(f"  {tag}: FAILED (exit {r.returncode}), see {screen}", flush=True)
            return dict(name=name, seed=seed, tag=tag, failed=True, exit=r.returncode,
                        wall_s=wall, warnings=info["warnings"], command=" ".join(cmd))
    wall = float(open(wall_file).read()) if os.path.exists(wall_file) else None
    info = run_bulk.parse_screen(screen)
    text = open(screen, errors="replace").read()
    res = dict(name=name, seed=seed, tag=tag, failed=False, ntri=c.get("ntri"), dt=v["dt"],
               wall_s=wall, steps=info["steps"], loop_s=info["loop_s"],
               ms_per_step=1e3 * info["loop_s"] / info["steps"], warnings=info["warnings"],
               command=" ".join(cmd))
    for key in ("epsilon", "dt_check"):
        if key in info:
            res[key] = info[key]
    for line in text.splitlines():
        for key in ("poured", "column", "gate removed", "final", "sphere time step"):
            if line.startswith("repose: " + key):
                res["log_" + key.replace(" ", "_")] = line
    rows = read_centres(dump)
    res["N"] = len(rows)
    res.update(fit_angle(rows))
    res["column_height"] = max(z for _, _, z in read_centres(os.path.join(out, "column.dump")))
    res["final_dump"] = dump
    return res


def stats(xs):
    m = sum(xs) / len(xs)
    sd = (sum((x - m) ** 2 for x in xs) / (len(xs) - 1)) ** 0.5 if len(xs) > 1 else float("nan")
    return m, sd


def table(results):
    lines = ["| case | triangles | N | seeds | angle (deg), per seed +- fit error | angle (deg), mean +- sd | "
             "dt (s) | steps | ms/step | wall (s) |", "| " + " | ".join(["---"] * 10) + " |"]
    for name in CASES:
        rs = [r for r in results if r["name"] == name]
        ok = [r for r in rs if not r["failed"]]
        if not rs:
            continue
        if not ok:
            lines.append(f"| {name} | | | {len(rs)} | FAILED |" + " |" * 5)
            continue
        m, sd = stats([r["angle"] for r in ok])
        per = ", ".join(f"{r['angle']:.1f} +- {r['err']:.1f}" for r in ok)
        lines.append(f"| {name} | {ok[0]['ntri'] or 'sphere'} | {ok[0]['N']} | {len(ok)} | {per} | "
                     f"{m:.1f} +- {sd:.1f} | {ok[0]['dt']:g} | "
                     f"{sum(r['steps'] for r in ok) / len(ok):.0f} | "
                     f"{sum(r['ms_per_step'] for r in ok) / len(ok):.3f} | "
                     f"{sum(r['wall_s'] for r in ok) / len(ok):.0f} |")
    return "\n".join(lines)


def plot(results, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    names = [n for n in CASES if any(r["name"] == n and not r["failed"] for r in results)]
    fig, axes = plt.subplots(len(names), 1, figsize=(10, 2.6 * len(names)), squeeze=False)
    for ax, name in zip(axes[:, 0], names):
        r = [r for r in results if r["name"] == name and not r["failed"]][0]
        rows = read_centres(r["final_dump"])
        xs = [x * 1e3 for x, _, _ in rows]
        zs = [z * 1e3 for _, _, z in rows]
        ax.scatter(xs, zs, s=9, c=[y for _, y, _ in rows], cmap="viridis", lw=0)
        sx = [x * 1e3 for x, _ in r["surface"]]
        sz = [z * 1e3 for _, z in r["surface"]]
        ax.plot(sx, sz, "k.", ms=4, label="highest centre per bin")
        x0, x1 = r["xfit"]
        ax.plot([x0 * 1e3, x1 * 1e3], [(r["intercept"] + r["slope"] * x) * 1e3 for x in (x0, x1)],
                "r-", lw=2, label=f"fit: {r['angle']:.1f} deg")
        ax.axvline(A * 1e3, color="0.6", ls=":", lw=1)
        ax.set_aspect("equal")
        ax.set_xlim(-2, L * 1e3 + 2)
        ax.set_ylim(-2, max(zs) + 8)
        ax.set_ylabel("z (mm)")
        ms = [q["angle"] for q in results if q["name"] == name and not q["failed"]]
        ax.set_title(f"{name} (N {r['N']}, seed {r['seed']}): {r['angle']:.1f} deg; "
                     f"seeds: {', '.join(f'{a:.1f}' for a in ms)}", fontsize=10)
        ax.legend(loc="upper right", fontsize=8)
    axes[-1, 0].set_xlabel("x (mm); dotted: the gate before it was removed; colour: y")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cases", nargs="+", default=["spheres", "cube"], choices=list(CASES))
    ap.add_argument("--seeds", type=int, default=2)
    ap.add_argument("--case-seeds", nargs="+", default=[], metavar="CASE=K",
                    help="fewer seeds for some cases, e.g. ico320=1")
    ap.add_argument("--n", type=int, default=420)
    ap.add_argument("--exe", default=valtools.default_exe())
    ap.add_argument("--liggghts", default="liggghts")
    ap.add_argument("--work", default="/tmp/repose")
    ap.add_argument("--reuse", action="store_true", help="reuse final.dump files of earlier runs")
    ap.add_argument("--json", default=os.path.join(HERE, "results", "repose.json"))
    ap.add_argument("--png", default=os.path.join(HERE, "repose.png"))
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    meshdir = os.path.join(args.work, "meshes")
    os.makedirs(meshdir, exist_ok=True)
    geo = geometry(args.n)
    box = os.path.join(meshdir, "repose_box.stl")
    gate = os.path.join(meshdir, "repose_gate.stl")
    meshgen.write_stl(box, *box_mesh(geo["H"]), "box")
    meshgen.write_stl(gate, *gate_mesh(geo["H"]), "gate")
    print(valtools.machine_line(), flush=True)
    print(f"box L {L * 1e3:.0f} mm x Wy {WY * 1e3:.0f} mm, column a {A * 1e3:.0f} mm, insertion z "
          f"{geo['zlo'] * 1e3:.0f}-{geo['zhi'] * 1e3:.0f} mm, pour {geo['tpour']:.3f} s", flush=True)
    results = []
    nseeds = {name: args.seeds for name in args.cases}
    nseeds.update({kv.split("=")[0]: int(kv.split("=")[1]) for kv in args.case_seeds})
    for s in range(args.seeds):
        for name in args.cases:
            if s >= nseeds[name]:
                continue
            r = run_case(name, s, args, geo, meshdir, box, gate)
            results.append(r)
            if not r["failed"]:
                print(f"  {r['tag']}: N {r['N']}, angle {r['angle']:.1f} +- {r['err']:.1f} deg "
                      f"({r['npts']} bins), column top {r['column_height'] * 1e3:.1f} mm, toe "
                      f"{r['toe'] * 1e3:.1f} mm, {r['steps']} steps, {r['ms_per_step']:.3f} ms/step, "
                      f"wall {r['wall_s']:.0f} s", flush=True)
            for wl in r["warnings"]:
                print("    " + wl, flush=True)
    print()
    print(valtools.machine_line())
    print(table(results))
    os.makedirs(os.path.dirname(args.json), exist_ok=True)
    with open(args.json, "w") as f:
        json.dump(dict(machine=valtools.machine_line(), exe=args.exe, liggghts=args.liggghts,
                       geometry=dict(geo, L=L, Wy=WY, a=A, ridge=RIDGE, d=D), n=args.n,
                       results=results), f, indent=1)
    print("results:", args.json)
    plot(results, args.png)
    print("picture:", args.png)


if __name__ == "__main__":
    main()
