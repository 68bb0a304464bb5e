#!/usr/bin/env python3
"""The contact network of poured beds: mean contact number and the shares of face, edge and
vertex contacts (compute tri/contact/local, tri/contact/atom) of the Platonic solids and an
icosphere, in run_bulk.py's pour (its geometry, material, settling, time steps).

  /usr/bin/python3 network.py [--n 200] [--seeds 1] [--work /tmp/bulk_network]

Contact number Z: the mean number of particles a particle touches, over the particles whose
centres lie in the bulk slab of the solid-fraction estimate (1.5 d above the floor to 1.5 d
below the top). Shares: of the particle-pair contact points of the whole bed, by the kind the
reduction gives them (face: a flat region on a flat region; edge: tied closest points along a
line longer than the layer; vertex: otherwise; deep: the soft layer overrun).
"""
import argparse
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, ".."))
import run_bulk  # noqa: E402
import valtools  # noqa: E402

SHAPES = run_bulk.PLATONIC + ["icosphere2"]
KINDS = {1: "face", 2: "edge", 3: "vertex", 4: "deep"}


def run(shape, seed, args, meshdir, floor):
    study = "ico" if shape.startswith("icosphere") else "platonic"
    geo = run_bulk.geometry(study, args.n, 5.0)
    case = dict(name=shape, study=study, Y=5e6, kind="tri", seed=seed, shape=shape,
                layer="inside")
    out = os.path.join(args.work, f"{shape}_s{seed}")
    os.makedirs(out, exist_ok=True)
    v = run_bulk.deck_vars(case, geo, args.n, out, meshdir, floor, False, 0, None)
    cmd = ["nice", "-n", "10"] + valtools.deck_command(
        args.exe, os.path.join(HERE, "in.network_tri"), v, os.path.join(out, "log.lammps"))
    r, wall = run_bulk.run_logged(cmd, os.path.join(out, "screen.txt"), shape)
    if r.returncode != 0:
        print(f"{shape}: FAILED (exit {r.returncode}), see {out}")
        return None
    atoms = run_bulk.dump_rows(os.path.join(out, "z.dump"))  # id mass x y z touching
    top = max(a[4] for a in atoms)
    lo, hi = 1.5 * run_bulk.D, top - 1.5 * run_bulk.D
    bulk = [a[5] for a in atoms if lo <= a[4] <= hi]
    network = run_bulk.dump_rows(os.path.join(out, "network.dump"), "ENTRIES")  # id1 id2 flag kind
    kinds = [int(row[3]) for row in network]
    shares = {name: kinds.count(k) / max(1, len(kinds)) for k, name in KINDS.items()}
    pairs = len({(int(row[0]), int(row[1])) for row in network})
    return dict(shape=shape, seed=seed, N=len(atoms), n_bulk=len(bulk),
                z_bulk=sum(bulk) / max(1, len(bulk)), z_all=2.0 * pairs / len(atoms),
                points=len(kinds), points_per_pair=len(kinds) / max(1, pairs), wall_s=wall,
                **{f"share_{k}": v for k, v in shares.items()})


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, default=200)
    ap.add_argument("--seeds", type=int, default=1)
    ap.add_argument("--only", nargs="*", choices=SHAPES)
    ap.add_argument("--work", default="/tmp/bulk_network")
    ap.add_argument("--exe", default=valtools.default_exe())
    args = ap.parse_args()
    meshdir = os.path.join(args.work, "meshes")
    os.makedirs(meshdir, exist_ok=True)
    floor = os.path.join(meshdir, "floor.stl")
    run_bulk.meshgen.write_stl(floor, *run_bulk.meshgen.plane(5.0 * run_bulk.D / 2), "floor")
    print(valtools.machine_line())
    print("| particles | seed | N (bulk) | Z bulk | Z all (2 pairs / N) | contact points per pair "
          "| face | edge | vertex | deep | wall (s) |\n|---|---|---|---|---|---|---|---|---|---|---|")
    rows = []
    for shape in args.only or SHAPES:
        for seed in range(args.seeds):
            r = run(shape, seed, args, meshdir, floor)
            if not r:
                continue
            rows.append(r)
            print(f"| {shape} | {seed} | {r['N']} ({r['n_bulk']}) | {r['z_bulk']:.2f} | "
                  f"{r['z_all']:.2f} | {r['points_per_pair']:.2f} | {100 * r['share_face']:.0f} % | "
                  f"{100 * r['share_edge']:.0f} % | {100 * r['share_vertex']:.0f} % | "
                  f"{100 * r['share_deep']:.1f} % | {r['wall_s']:.0f} |", flush=True)
    # Kept across runs of a few shapes at a time: rows of the same shape and seed are replaced.
    path = os.path.join(HERE, "results", "network.json")
    old = json.load(open(path))["rows"] if os.path.exists(path) else []
    fresh = {(r["shape"], r["seed"]) for r in rows}
    rows = [r for r in old if (r["shape"], r["seed"]) not in fresh] + rows
    with open(path, "w") as f:
        json.dump(dict(machine=valtools.machine_line(), n=args.n, rows=rows), f, indent=1)


if __name__ == "__main__":
    main()
