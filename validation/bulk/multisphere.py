#!/usr/bin/python3
"""Cubes as LIGGGHTS multisphere clumps (validation/bulk): the Platonic study's cube bed, poured
with plain `liggghts` 3.8 as rigid clumps of 2x2x2 or 3x3x3 spheres (fix particletemplate/
multisphere + fix multisphere), on the deck of run_bulk.py (common.in, the same insertion region
and pour, run.in's settling), against the mesh cubes of results/bulk_b5a1724_platonic.json.

  python3 validation/bulk/multisphere.py [--clumps 8 27] [--seeds 1] [--n 200] [--quick]
      [--work /tmp/bulk/work_ms] [--dt8 DT] [--dt27 DT] [--ntry 1000000] [--label multisphere]
      [--mesh-cube-seeds 2 --exe liggghts-tri]    # also the mesh cube of run_bulk.py, untapped

The clump of k^3 spheres (k = 2, 3) fills the cube of side s = 3.224 mm (volume-equivalent
diameter D = 4 mm): spheres of radius s/(2k) on the k x k x k grid of cell centres, so that its
envelope touches the cube's six faces (its edges and corners are rounded off). Its true volume
is k^3 (4/3) pi (s/2k)^3 = (pi/6) s^3 = 52.4 % of the cube's, for every k. Its density is set to
2500 / (pi/6) so that the Monte Carlo mass (ntry) is the cube's, m = 8.38e-5 kg; the inertia is
the clump's own (Monte Carlo). phi counts every body as the cube's volume (mass / 2500, as
run_bulk.py does for the mesh cubes); phi_true = phi x pi/6 is the spheres' own volume fraction.
The body's centre is the mean of its spheres' centres (atoms are numbered body by body; checked).
"""
import argparse
import json
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import run_bulk as rb  # noqa: E402

SIDE = (math.pi / 6.0) ** (1.0 / 3.0) * rb.D     # cube side of volume-equivalent diameter D
CUBE_JSON = os.path.join(HERE, "results", "bulk_b5a1724_platonic.json")
# time steps (s), about 8 % of the Rayleigh time of the clump's sphere (radius s/4, s/6) at
# density 2500 / (pi/6), as the spheres' 2e-5 s is 7.9 % of theirs (check/timestep/gran prints it)
DT = {8: 1.1e-5, 27: 7.5e-6}


def clump(k):
    """[(x, y, z, r)] of k^3 spheres of radius s/(2k) at the cell centres of the cube."""
    r = SIDE / (2 * k)
    c = [(-SIDE / 2 + (2 * i + 1) * r) for i in range(k)]
    return [(x, y, z, r) for x in c for y in c for z in c]


def write_clump(path, k):
    with open(path, "w") as f:
        f.write(f"# {k}x{k}x{k} spheres of radius s/{2 * k} filling a cube of side {SIDE:.6e} m\n")
        for x, y, z, r in clump(k):
            f.write(f"{x:.9e} {y:.9e} {z:.9e} {r:.9e}\n")


def bodies(dump, nsph):
    """[(mass, z)] per body: atoms id 1..nsph are body 1, and so on (checked: every group's spheres
    must lie within the clump's diameter of their mean, x and y unwrapped), with the cube's mass."""
    rows = sorted(rb.dump_rows(dump), key=lambda r: r[0])
    if len(rows) % nsph:
        raise SystemExit(f"{dump}: {len(rows)} atoms, not a multiple of {nsph}")
    out, worst = [], 0.0
    w = None
    for b in range(len(rows) // nsph):
        g = rows[b * nsph:(b + 1) * nsph]
        zc = sum(r[5] for r in g) / nsph
        spread = max(abs(r[5] - zc) for r in g)
        worst = max(worst, spread)
        out.append((rb.MASS, zc))
    if worst > SIDE:
        raise SystemExit(f"{dump}: atoms are not numbered body by body (z spread {worst:.2e} m)")
    return out, worst


def parse_ms(screen):
    """The template's Monte Carlo mass, equivalent-sphere radius and first principal moment."""
    text = open(screen, errors="replace").read()
    info = {}
    for key, pat in (("mc_mass", r"mass\s*=\s*([0-9.eE+-]+)"),
                     ("mc_r_equiv", r"radius of equivalent sphere\s*=\s*([0-9.eE+-]+)"),
                     ("mc_inertia", r"Principal moments of inertia_:\s*([0-9.eE+-]+)")):
        m = re.findall(pat, text)
        if m:
            info[key] = float(m[0])
    return info


def table(paths):
    """Markdown table: means +- sd over seeds per case; the stored mesh cubes (poured, tapped runs)."""
    def ms(xs):
        m = sum(xs) / len(xs)
        sd = (sum((x - m) ** 2 for x in xs) / (len(xs) - 1)) ** 0.5 if len(xs) > 1 else 0.0
        return f"{m:.4f}" + (f" +- {sd:.4f}" if len(xs) > 1 else "")

    groups = {}
    stored = json.load(open(CUBE_JSON))["results"]
    for r in stored:
        if r["name"] == "cube" and not r["failed"]:
            r = dict(r, steps_per_sim_s=1 / r["dt"], s_per_sim_s=r["loop_s"] / (r["steps"] * r["dt"]))
            groups.setdefault("mesh cube, stored (2d6093e, pour + 40 taps)", []).append(r)
    for p in paths:
        for r in json.load(open(p))["results"]:
            if r.get("failed"):
                continue
            name = ("mesh cube, rerun (pour only)" if r["name"] == "cube" else
                    f"multisphere {r['nsph']} spheres")
            groups.setdefault(name, []).append(r)
    lines = ["| case | bodies (atoms) | seeds | dt (s) | phi (centres) | phi_cut | "
             "phi true volume | settled at (s) | ms/step | steps per sim. s | "
             "wall s per sim. s | wall (s) |", "| " + " | ".join(["---"] * 12) + " |"]
    for name, rs in groups.items():
        nsph = rs[0].get("nsph", 1)
        true = (ms([r["phi"] * math.pi / 6 for r in rs]) if nsph > 1 else "= phi")
        lines.append(
            f"| {name} | {rs[0]['N']} ({rs[0]['N'] * nsph}) | {len(rs)} | {rs[0]['dt']:g} | "
            f"{ms([r['phi'] for r in rs])} | {ms([r['phi_cut'] for r in rs])} | {true} | "
            f"{sum(r['t_end'] for r in rs) / len(rs):.3f} | "
            f"{sum(r['ms_per_step'] for r in rs) / len(rs):.3f} | {1 / rs[0]['dt']:.0f} | "
            f"{sum(r['s_per_sim_s'] for r in rs) / len(rs):.1f} | "
            f"{sum(r['wall_s'] for r in rs) / len(rs):.0f} |")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--clumps", nargs="*", type=int, default=[8, 27], choices=[8, 27])
    ap.add_argument("--seeds", type=int, default=1)
    ap.add_argument("--first-seed", type=int, default=0)
    ap.add_argument("--n", type=int, default=200)
    ap.add_argument("--quick", action="store_true", help="smoke run: 40 clumps, short column")
    ap.add_argument("--work", default="/tmp/bulk/work_ms")
    ap.add_argument("--dt8", type=float, default=DT[8])
    ap.add_argument("--dt27", type=float, default=DT[27])
    ap.add_argument("--ntry", type=int, default=1000000)
    ap.add_argument("--liggghts", default="liggghts")
    ap.add_argument("--label", default="multisphere")
    ap.add_argument("--mesh-cube-seeds", type=int, default=0,
                    help="also rerun this many seeds of run_bulk.py's mesh cube (no tapping) "
                         "with the liggghts-tri of --exe, for the timings")
    ap.add_argument("--exe", default=rb.valtools.default_exe())
    ap.add_argument("--table", nargs="+", metavar="JSON",
                    help="only print the table of these results files (and the stored mesh cubes)")
    args = ap.parse_args()
    if args.table:
        print(table(args.table))
        return
    if args.quick:
        args.n = 40
    os.makedirs(args.work, exist_ok=True)
    geo = rb.geometry("platonic", args.n, 5.0)
    floor = os.path.join(args.work, "floor.stl")
    rb.meshgen.write_stl(floor, *rb.meshgen.plane(geo["W"] / 2), "floor")
    print(rb.valtools.machine_line(), flush=True)
    print(f"cube side {SIDE * 1e3:.4f} mm; box {geo['W'] * 1e3:.0f} mm, insertion z "
          f"{geo['zlo'] * 1e3:.0f}-{geo['zhi'] * 1e3:.0f} mm, pour {geo['tpour']:.3f} s", flush=True)
    results = []
    for k3 in args.clumps:
        k = round(k3 ** (1 / 3))
        spheres = os.path.join(args.work, f"clump{k3}.txt")
        write_clump(spheres, k)
        dt = args.dt8 if k3 == 8 else args.dt27
        for s in range(args.first_seed, args.first_seed + args.seeds):
            tag = f"ms{k3}_s{s}"
            out = os.path.join(args.work, tag)
            os.makedirs(out, exist_ok=True)
            dump = os.path.join(out, "final.dump")
            if os.path.exists(dump):
                os.remove(dump)
            v = dict(W=geo["W"], H=geo["H"], floor=floor, Y=5e6, N=args.n, zlo=geo["zlo"],
                     zhi=geo["zhi"], seed=rb.SEEDS[s % len(rb.SEEDS)], out=out,
                     tpour=geo["tpour"], tchunk=0.02, nsettle=3 if args.quick else 15,
                     kemin=1e-3 * args.n * rb.MASS * rb.G * rb.D, dt=dt, spheres=spheres,
                     nsph=k3, rho=rb.RHO * 6.0 / math.pi, ntry=args.ntry,
                     gamma=rb.MASS * rb.G / rb.V_FALL / k3)
            if args.quick:
                v["tpour"] = 0.3
            cmd = ["nice", "-n", "10"] + rb.valtools.deck_command(
                args.liggghts, os.path.join(HERE, "in.multisphere"), v, os.path.join(out, "log.lammps"))
            screen = os.path.join(out, "screen.txt")
            r, wall = rb.run_logged(cmd, screen, tag)
            res = dict(name=f"multisphere{k3}", nsph=k3, seed=s, tag=tag, dt=dt, N=args.n,
                       wall_s=wall, exit=r.returncode, command=" ".join(cmd), geometry=geo,
                       r_sphere=SIDE / (2 * k), side=SIDE, v_clump=math.pi / 6 * SIDE ** 3,
                       density=v["rho"])
            res.update(rb.parse_screen(screen))
            res.update(parse_ms(os.path.join(out, "log.lammps")))
            if r.returncode != 0 or not os.path.exists(dump):
                res["failed"] = True
                print(f"  {tag}: FAILED (exit {r.returncode}), see {screen}", flush=True)
                for wl in res["warnings"]:
                    print("    " + wl, flush=True)
                results.append(res)
                continue
            res["failed"] = False
            body, spread = bodies(dump, k3)
            res["bodies"] = len(body)
            res["body_z_spread"] = spread
            res.update(rb.solid_fraction(body, geo["W"]))
            res["phi_true"] = res["phi"] * math.pi / 6
            res["phi_cut_true"] = res["phi_cut"] * math.pi / 6
            res["ms_per_step"] = 1e3 * res["loop_s"] / res["steps"]
            res["steps_per_sim_s"] = 1.0 / dt
            res["s_per_sim_s"] = res["loop_s"] / (res["steps"] * dt)
            results.append(res)
            print(f"  {tag}: {len(body)} bodies ({res.get('atoms')} atoms), phi {res['phi']:.4f}, "
                  f"phi_cut {res['phi_cut']:.4f} ({res['n_slab']} in {res['slab_d']:.2f} d, top "
                  f"{res['top_d']:.2f} d), settled at {res.get('t_end', float('nan')):.3f} s, "
                  f"{res['ms_per_step']:.3f} ms/step, {res['s_per_sim_s']:.1f} s per simulated s, "
                  f"wall {wall:.0f} s, MC mass {res.get('mc_mass')}", flush=True)
            for key in ("dt_sphere",):
                if key in res:
                    print("    " + res[key], flush=True)
            for wl in res["warnings"]:
                print("    " + wl, flush=True)
    if args.mesh_cube_seeds:
        margs = argparse.Namespace(exe=args.exe, liggghts=args.liggghts, work=args.work,
                                   quick=args.quick, n=args.n, tap=0, dt_tri=None, reuse=False)
        meshdir = os.path.join(args.work, "meshes")
        os.makedirs(meshdir, exist_ok=True)
        for case in rb.cases("platonic", [5e6], 0, args.mesh_cube_seeds):
            if case["name"] != "cube":
                continue
            r = rb.run_case(case, margs, geo, meshdir, floor)
            r["geometry"] = geo
            if not r["failed"]:
                r["steps_per_sim_s"] = 1.0 / r["dt"]
                r["s_per_sim_s"] = r["loop_s"] / (r["steps"] * r["dt"])
                print(f"  {r['tag']} (mesh, no tapping): phi {r['phi']:.4f}, phi_cut "
                      f"{r['phi_cut']:.4f} ({r['n_slab']} in {r['slab_d']:.2f} d, top "
                      f"{r['top_d']:.2f} d), settled at {r.get('t_end', float('nan')):.3f} s, "
                      f"{r['ms_per_step']:.3f} ms/step, {r['s_per_sim_s']:.1f} s per simulated s, "
                      f"wall {r['wall_s'] or 0:.0f} s", flush=True)
            else:
                print(f"  {r['tag']}: FAILED", r["warnings"], flush=True)
            results.append(r)
    path = (os.path.join(args.work, "multisphere_quick.json") if args.quick else
            os.path.join(HERE, "results", f"{args.label}.json"))
    with open(path, "w") as f:
        json.dump(dict(machine=rb.valtools.machine_line(), liggghts=args.liggghts, n=args.n,
                       side=SIDE, results=results), f, indent=1)
    print("results:", path)


if __name__ == "__main__":
    main()
