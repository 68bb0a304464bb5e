#!/usr/bin/python3
"""Bulk packing (validation/bulk): poured beds of triangulated particles against LIGGGHTS spheres.

  python3 validation/bulk/run_bulk.py [--quick] [--study ico platonic] [--Y 5e6 5e7]
      [--n 200] [--width-d 5] [--sphere-seeds 5] [--tri-seeds 1] [--cases NAME ...] [--exe liggghts-tri] [--liggghts liggghts]
      [--work /tmp/bulk/work] [--label NAME] [--tap CYCLES] [--dt-tri DT] [--reuse]
  /usr/bin/python3 validation/bulk/plot_bulk.py results/bulk_NAME.json

N particles of volume-equivalent diameter d = 4 mm (density 2500) are placed at once at random
(fix insert/pack, overlap check) in a tall region of a column periodic in x and y, W = 5 d wide
(--width-d),
and rain at 1 m/s (fix viscous, gamma = m g / 1 m/s) onto a mesh floor (fix mesh/surface of a
plane STL). After the pour the drag is taken off and the bed settles until its translational
kinetic energy is below 1e-3 N m g d (at most 0.3 s). Material: LIGGGHTS hooke (youngsModulus Y,
poissonsRatio 0.45, coefficientRestitution 0.5, coefficientFriction 0.5, characteristicVelocity
1 m/s), particle-particle and particle-wall. Decks: common.in, insert.in, run.in, in.spheres
(plain liggghts: pair gran model hooke, wall/gran, nve/sphere), in.tri (liggghts-tri: fix
tri/particles with epsilon auto, pair tri/gran model hooke, tri/wall, tri/nve).

Studies:
  ico       at each Y: spheres (--sphere-seeds seeds), icospheres of 80, 320, 1280 triangles
            with `layer inside` (the default), 320 triangles with `layer outside`;
  platonic  at the first Y: tetrahedron, cube, octahedron, dodecahedron, icosahedron (`layer
            inside`, orient random) and spheres, in a taller insertion region (the tetrahedron's
            bounding sphere is 8 times its volume), against Baker & Kudrolli, PRE 82, 061304 (2010).

Solid fraction: phi = (sum of the volumes, mass / density, of the particles whose centres lie in
the slab) / (W^2 x slab height), the slab from 1.5 d above the floor to 1.5 d below the top of
the bed; the top is the mean centre height of the highest W^2/d^2 particles (one layer) plus
d/2. `lo`/`hi` give phi for the slab's two ends moved by +-d/4 (the estimator's boundary noise);
`phi_cut` counts instead the part of each particle's volume-equivalent sphere inside the slab (a
smoother estimator: exact for spheres, an approximation for the other shapes).

Every run is one process (nice -n 10, OMP_NUM_THREADS=1), one after the other. Prints the table
(case, N, phi, ratio to the spheres of the same study and Y, wall time per step) and writes
results/bulk_LABEL.json next to this script (--quick: WORK/bulk_quick.json).
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(REPO, "validation", "meshes"))
sys.path.insert(0, os.path.join(REPO, "validation"))
import meshgen  # noqa: E402
import valtools  # noqa: E402

D = 0.004                   # volume-equivalent diameter (m)
RHO = 2500.0
MASS = RHO * math.pi / 6.0 * D ** 3
G = 9.81
V_FALL = 1.0                # terminal speed while raining (m/s)
# time steps (s): spheres about 8-10 % of LIGGGHTS's Rayleigh time, mesh particles about 6.5 %
# of their contact time (fix tri/particles' check prints it)
DT_SPHERE = {5e6: 2e-5, 5e7: 8e-6}
DT_TRI = {5e6: 3e-5, 5e7: 1.2e-5}
PLATONIC = ["tetrahedron", "cube", "octahedron", "dodecahedron", "icosahedron"]
# Baker & Kudrolli, PRE 82, 061304 (2010), plastic dice: loose, dense (+-0.01)
BAKER = {"tetrahedron": (0.51, 0.64), "cube": (0.54, 0.67), "octahedron": (0.52, 0.64),
         "dodecahedron": (0.51, 0.63), "icosahedron": (0.50, 0.59)}
# reach (bounding radius + layer) that sizes a study's insertion region, the same for all its cases
REACH = {"ico": 0.0023, "platonic": 0.0042}
# insertion seeds (primes; not the decks' template seeds 15485863 and 32452843: LIGGGHTS stops
# on a repeated seed)
SEEDS = [67867967, 86028121, 122949823, 141650939, 49979687, 104395301, 160481183, 179424673]
# --tap N: the floor shaken sinusoidally for N cycles of 20 ms, peak acceleration 1.5 g
TAP_PERIOD, TAP_GAMMA = 0.02, 1.5


def cases(study, ys, sphere_seeds, tri_seeds):
    out = []
    if study == "ico":
        for y in ys:
            for s in range(sphere_seeds):
                out.append(dict(name="spheres", study=study, Y=y, kind="sphere", seed=s))
            for level, layer in ((1, "inside"), (2, "inside"), (3, "inside"), (2, "outside")):
                for s in range(tri_seeds):
                    out.append(dict(name=f"ico{20 * 4 ** level}_{layer}", study=study, Y=y,
                                    kind="tri", shape=f"icosphere{level}", ntri=20 * 4 ** level,
                                    layer=layer, seed=s))
    else:
        y = ys[0]
        for s in range(sphere_seeds):
            out.append(dict(name="spheres", study=study, Y=y, kind="sphere", seed=s))
        for p in PLATONIC:
            v, f = meshgen.platonic(p)
            for s in range(tri_seeds):
                out.append(dict(name=p, study=study, Y=y, kind="tri", shape=p, ntri=len(f),
                                layer="inside", seed=s))
    return out


def shape_file(shape, meshdir):
    path = os.path.join(meshdir, shape + ".stl")
    if not os.path.exists(path):
        if shape.startswith("icosphere"):
            v, f = meshgen.icosphere(int(shape[len("icosphere"):]), 1.0)
        else:
            v, f = meshgen.platonic(shape)
        meshgen.write_stl(path, *meshgen.volume_equivalent(v, f, D), shape)
    return path


def geometry(study, n, width_d, reach=None):
    """Box width and height, insertion region, pour time: the same for every case of a study."""
    w = width_d * D
    reach = reach or REACH[study]
    vol = math.pi / 6.0 * D ** 3
    bed = n * vol / (0.45 * w * w)                       # the loosest bed expected
    zlo = bed + 2 * reach + 0.003
    zhi = zlo + n * 4.0 / 3.0 * math.pi * reach ** 3 / (0.2 * w * w)  # bounding spheres 20 %
    return dict(W=w, H=zhi + 0.005, zlo=zlo, zhi=zhi, tpour=1.05 * zhi / V_FALL + 0.05)


def deck_vars(case, geo, n, out, meshdir, floor, quick, tap, dt_tri=None):
    y = case["Y"]
    v = dict(W=geo["W"], H=geo["H"], floor=floor, Y=y, N=n, zlo=geo["zlo"], zhi=geo["zhi"],
             seed=SEEDS[case["seed"] % len(SEEDS)],
             gamma=MASS * G / V_FALL, vfall=V_FALL, out=out, tpour=geo["tpour"], tchunk=0.02,
             nsettle=3 if quick else 15, kemin=1e-3 * n * MASS * G * D,
             ncycles=tap if case["study"] == "platonic" else 0, tapperiod=TAP_PERIOD,
             tapamp=TAP_GAMMA * G * (TAP_PERIOD / (2 * math.pi)) ** 2)
    if case["kind"] == "tri":
        v.update(dt=dt_tri or DT_TRI[y], shape=shape_file(case["shape"], meshdir), layer=case["layer"],
                 oseed=99 + case["seed"])
    else:
        v.update(dt=DT_SPHERE[y])
    return v


def dump_rows(path, section="ATOMS"):
    """The rows of a dump file's `section` (ATOMS of dump custom, ENTRIES of dump local), all
    frames, as lists of floats."""
    rows, inside = [], False
    with open(path) as f:
        for line in f:
            if line.startswith("ITEM:"):
                inside = line.startswith("ITEM: " + section)
            elif inside and line.strip():
                rows.append([float(x) for x in line.split()])
    return rows


def read_dump(path):
    """[(mass, z)] of a write_dump custom file: id type mass x y z."""
    return [(r[2], r[5]) for r in dump_rows(path)]


def solid_fraction(rows, w):
    """phi in the slab [1.5 d, top - 1.5 d] and the same with the slab's ends moved by +-d/4."""
    zs = sorted((z for _, z in rows), reverse=True)
    ntop = max(1, round(w * w / (D * D)))
    top = sum(zs[:ntop]) / ntop + 0.5 * D

    def phi(lo, hi):
        if hi <= lo:
            return float("nan"), 0
        inside = [m for m, z in rows if lo <= z < hi]
        return sum(m / RHO for m in inside) / (w * w * (hi - lo)), len(inside)

    def below(zc, h, r):
        """Volume of a sphere of radius r centred at height zc below the plane z = h."""
        t = min(max(h - (zc - r), 0.0), 2 * r)
        return math.pi * t * t * (3 * r - t) / 3.0

    def phi_cut(lo, hi):
        if hi <= lo:
            return float("nan")
        tot = 0.0
        for m, z in rows:
            r = (3.0 * m / RHO / (4.0 * math.pi)) ** (1.0 / 3.0)
            tot += below(z, hi, r) - below(z, lo, r)
        return tot / (w * w * (hi - lo))

    z0, z1 = 1.5 * D, top - 1.5 * D
    val, count = phi(z0, z1)
    shifted = [phi(z0 + a, z1 + b)[0] for a in (-D / 4, D / 4) for b in (-D / 4, D / 4)]
    shifted = [s for s in shifted if s == s]
    return dict(phi=val, n_slab=count, slab_d=(z1 - z0) / D, top_d=top / D,
                lo=min(shifted) if shifted else val, hi=max(shifted) if shifted else val,
                phi_cut=phi_cut(z0, z1))


def parse_screen(path):
    text = open(path, errors="replace").read()
    loop = [(float(a), int(b)) for a, b in
            re.findall(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps", text)]
    info = dict(loop_s=sum(a for a, _ in loop), steps=sum(b for _, b in loop))
    m = re.findall(r"bulk: settled atoms (\d+) t ([0-9.eE+-]+) ke ([0-9.eE+-]+)", text)
    if m:
        info.update(atoms=int(m[-1][0]), t_end=float(m[-1][1]), ke_end=float(m[-1][2]))
    m = re.findall(r"bulk: tapped atoms (\d+) t ([0-9.eE+-]+) ke ([0-9.eE+-]+)", text)
    if m:
        info.update(t_tapped=float(m[-1][1]), ke_tapped=float(m[-1][2]))
    m = re.findall(r"bulk: poured atoms (\d+) t ([0-9.eE+-]+) ke ([0-9.eE+-]+)", text)
    if m:
        info.update(t_pour=float(m[-1][1]), ke_pour=float(m[-1][2]))
    for key, pat in (("epsilon", r"(tri/particles: epsilon auto[^\n]*)"),
                     ("dt_check", r"(tri/particles: time-step check[^\n]*)"),
                     ("dt_sphere", r"(bulk: sphere time step[^\n]*)")):
        m = re.findall(pat, text)
        if m:
            info[key] = m[0].strip()
    warn = []
    for line in text.splitlines():
        if ("WARNING" in line or "ERROR" in line) and line.strip() not in warn:
            warn.append(line.strip())
    info["warnings"] = warn[:20]
    return info


def run_logged(cmd, screen, tag):
    """Runs cmd in this folder, its output in `screen`: (CompletedProcess, wall seconds). Open
    MPI's singleton start-up now and then fails before LIGGGHTS starts ("ORTE_ERROR_LOG: Data
    unpack would read past end of buffer"): then once more."""
    for attempt in range(2):
        if attempt:
            print(f"  {tag}: no LIGGGHTS output (an Open MPI start-up failure?), once more",
                  flush=True)
            time.sleep(2.0)
        t0 = time.time()
        with open(screen, "w") as f:
            r = subprocess.run(cmd, cwd=HERE, env=valtools.run_env(1), stdout=f,
                               stderr=subprocess.STDOUT)
        wall = time.time() - t0
        if r.returncode == 0 or "LIGGGHTS (Version" in open(screen, errors="replace").read():
            break
    return r, wall


def run_case(case, args, geo, meshdir, floor):
    tag = f"{case['study']}_Y{case['Y']:g}_{case['name']}_s{case['seed']}"
    out = os.path.join(args.work, tag)
    os.makedirs(out, exist_ok=True)
    screen = os.path.join(out, "screen.txt")
    dump = os.path.join(out, "final.dump")
    exe = args.exe if case["kind"] == "tri" else args.liggghts
    deck = os.path.join(HERE, "in.tri" if case["kind"] == "tri" else "in.spheres")
    v = deck_vars(case, geo, args.n, out, meshdir, floor, args.quick, args.tap, args.dt_tri)
    # the log keeps the commands up to an ERROR whose screen line Open MPI's abort may swallow
    cmd = ["nice", "-n", "10"] + valtools.deck_command(exe, deck, v, os.path.join(out, "log.lammps"))
    wall = None
    if not (args.reuse and os.path.exists(dump)):
        if os.path.exists(dump):
            os.remove(dump)
        r, wall = run_logged(cmd, screen, tag)
        if r.returncode != 0 or not os.path.exists(dump):
            print(f"  {tag}: FAILED (exit {r.returncode}), see {screen}", flush=True)
            res = dict(case, tag=tag, failed=True, exit=r.returncode, wall_s=wall,
                       command=" ".join(cmd))
            res.update(parse_screen(screen))
            return res
    wall_file = os.path.join(out, "wall_s.txt")
    if wall is not None:
        with open(wall_file, "w") as f:
            f.write(f"{wall:.3f}\n")
    elif os.path.exists(wall_file):
        wall = float(open(wall_file).read())
    res = dict(case, tag=tag, failed=False, wall_s=wall, dt=v["dt"], N=args.n,
               command=" ".join(cmd))
    res.update(parse_screen(screen))
    res["ms_per_step"] = 1e3 * res["loop_s"] / res["steps"] if res.get("steps") else None
    res.update(solid_fraction(read_dump(dump), geo["W"]))
    tapped = os.path.join(out, "tapped.dump")
    if v["ncycles"] > 0 and os.path.exists(tapped):
        res["tapped"] = solid_fraction(read_dump(tapped), geo["W"])
    return res


def table(results):
    """The Markdown table: one row per (study, Y, case), means over seeds."""
    def stats(xs):
        m = sum(xs) / len(xs)
        sd = (sum((x - m) ** 2 for x in xs) / (len(xs) - 1)) ** 0.5 if len(xs) > 1 else 0.0
        return m, sd

    ref = {}
    for r in results:
        if r["name"] == "spheres" and not r["failed"]:
            ref.setdefault((r["study"], r["Y"]), []).append(r)
    lines = ["| study | Y (Pa) | case | triangles | N | seeds | dt (s) | phi (centres) | "
             "ratio to spheres | phi range, slab ends +-d/4 | phi_cut | ratio (phi_cut) | "
             "settled at (s) | ms/step | wall (s) |",
             "| " + " | ".join(["---"] * 15) + " |"]
    groups = {}
    for r in results:
        groups.setdefault((r["study"], r["Y"], r["name"]), []).append(r)
    for (study, y, name), rs in groups.items():
        ok = [r for r in rs if not r["failed"]]
        if not ok:
            lines.append(f"| {study} | {y:g} | {name} | | | {len(rs)} | | FAILED |" + " |" * 7)
            continue
        m, sd = stats([r["phi"] for r in ok])
        mc, sdc = stats([r["phi_cut"] for r in ok])
        sref = ref.get((study, y))
        sm = stats([r["phi"] for r in sref])[0] if sref else None
        smc = stats([r["phi_cut"] for r in sref])[0] if sref else None
        pm = f"{m:.4f}" + (f" +- {sd:.4f}" if len(ok) > 1 else "")
        pc = f"{mc:.4f}" + (f" +- {sdc:.4f}" if len(ok) > 1 else "")
        rng = f"{min(r['lo'] for r in ok):.3f}-{max(r['hi'] for r in ok):.3f}"
        ratio = f"{m / sm:.3f}" if sm else ""
        ratioc = f"{mc / smc:.3f}" if smc else ""
        ms = sum(r["ms_per_step"] for r in ok) / len(ok)
        wall = [r["wall_s"] for r in ok if r["wall_s"]]
        walls = f"{sum(wall) / len(wall):.0f}" if wall else ""
        tend = f"{sum(r.get('t_end', float('nan')) for r in ok) / len(ok):.3f}"
        fails = len(rs) - len(ok)
        seeds = f"{len(ok)}" + (f" (+{fails} failed)" if fails else "")
        lines.append(f"| {study} | {y:g} | {name} | {ok[0].get('ntri', '')} | {ok[0]['N']} | "
                     f"{seeds} | {ok[0]['dt']:g} | {pm} | {ratio} | {rng} | {pc} | {ratioc} | "
                     f"{tend} | {ms:.3f} | {walls} |")
    tapped = [r for r in results if not r["failed"] and "tapped" in r]
    if tapped:
        lines += ["", "| study | Y (Pa) | case | seeds | phi poured | phi tapped | phi_cut poured | "
                  "phi_cut tapped | settled at (s) |", "| " + " | ".join(["---"] * 9) + " |"]
        tg = {}
        for r in tapped:
            tg.setdefault((r["study"], r["Y"], r["name"]), []).append(r)
        for (study, y, name), rs in tg.items():
            def mm(f):
                return sum(f(r) for r in rs) / len(rs)
            lines.append(f"| {study} | {y:g} | {name} | {len(rs)} | {mm(lambda r: r['phi']):.4f} | "
                         f"{mm(lambda r: r['tapped']['phi']):.4f} | {mm(lambda r: r['phi_cut']):.4f} | "
                         f"{mm(lambda r: r['tapped']['phi_cut']):.4f} | "
                         f"{mm(lambda r: r.get('t_tapped', float('nan'))):.3f} |")
    return "\n".join(lines)


def main():
    global V_FALL
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true",
                    help="smoke run: 120 particles, Y 5e6, one sphere seed, 4 shapes, short settling")
    ap.add_argument("--study", nargs="+", default=["ico", "platonic"], choices=["ico", "platonic"])
    ap.add_argument("--Y", nargs="+", type=float, default=[5e6, 5e7])
    ap.add_argument("--n", type=int, default=200)
    ap.add_argument("--width-d", type=float, default=5.0, help="box width in d (default 5)")
    ap.add_argument("--sphere-seeds", type=int, default=5)
    ap.add_argument("--tri-seeds", type=int, default=1, help="seeds (insertion, orientation) per mesh case")
    ap.add_argument("--cases", nargs="+", help="only these case names (e.g. spheres ico320_inside cube)")
    ap.add_argument("--exe", default=valtools.default_exe())
    ap.add_argument("--liggghts", default="liggghts")
    ap.add_argument("--work", default="/tmp/bulk/work")
    ap.add_argument("--label", default="run")
    ap.add_argument("--reach", type=float,
                    help="size the insertion region for this reach (m) instead of the study's")
    ap.add_argument("--dt-tri", type=float, help="time step of the mesh particles (s) instead of DT_TRI")
    ap.add_argument("--tap", type=int, default=0,
                    help="platonic study: shake the settled bed for this many floor cycles (tap.in)")
    ap.add_argument("--v-fall", type=float, default=V_FALL,
                    help="terminal speed of the rain (m/s, default 1): a gentler pour")
    ap.add_argument("--reuse", action="store_true", help="reuse final.dump files of earlier runs")
    args = ap.parse_args()
    V_FALL = args.v_fall
    if args.quick:
        args.n, args.Y, args.sphere_seeds = 120, [5e6], 1
        args.cases = args.cases or ["spheres", "ico80_inside", "ico320_outside", "cube"]
        args.work = os.path.join(args.work, "quick")
    os.makedirs(args.work, exist_ok=True)
    meshdir = os.path.join(args.work, "meshes")
    os.makedirs(meshdir, exist_ok=True)
    w = args.width_d * D
    floor = os.path.join(meshdir, "floor.stl")
    meshgen.write_stl(floor, *meshgen.plane(w / 2), "floor")
    print(valtools.machine_line(), flush=True)
    print(f"liggghts-tri: {args.exe}\nliggghts: {args.liggghts}", flush=True)
    results = []
    for study in args.study:
        geo = geometry(study, args.n, args.width_d, args.reach)
        print(f"study {study}: box {geo['W'] * 1e3:.0f} mm wide, insertion z {geo['zlo'] * 1e3:.0f}"
              f"-{geo['zhi'] * 1e3:.0f} mm, pour {geo['tpour']:.3f} s", flush=True)
        for case in cases(study, args.Y, args.sphere_seeds, args.tri_seeds):
            if args.cases and case["name"] not in args.cases:
                continue
            r = run_case(case, args, geo, meshdir, floor)
            r["geometry"] = geo
            results.append(r)
            if not r["failed"]:
                print(f"  {r['tag']}: phi {r['phi']:.4f}, phi_cut {r['phi_cut']:.4f} ({r['n_slab']} in a slab of "
                      f"{r['slab_d']:.2f} d, top {r['top_d']:.2f} d), settled at "
                      f"{r.get('t_end', float('nan')):.3f} s, {r['ms_per_step']:.3f} ms/step, "
                      f"wall {r['wall_s'] or 0:.0f} s", flush=True)
                for key in ("epsilon", "dt_check", "dt_sphere"):
                    if key in r:
                        print("    " + r[key], flush=True)
                for wl in r["warnings"]:
                    print("    " + wl, flush=True)
                if "tapped" in r:
                    t = r["tapped"]
                    print(f"    tapped ({args.tap} cycles): phi {t['phi']:.4f}, phi_cut "
                          f"{t['phi_cut']:.4f}, settled at {r.get('t_tapped', float('nan')):.3f} s",
                          flush=True)
            else:
                for wl in r["warnings"]:
                    print("    " + wl, flush=True)
    print()
    print(valtools.machine_line())
    print(table(results))
    path = (os.path.join(args.work, "bulk_quick.json") if args.quick else
            os.path.join(HERE, "results", f"bulk_{args.label}.json"))
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        json.dump(dict(machine=valtools.machine_line(), exe=args.exe, liggghts=args.liggghts,
                       n=args.n, results=results, baker_kudrolli=BAKER), f, indent=1)
    print("results:", path)


if __name__ == "__main__":
    main()
