#!/usr/bin/env python3
"""The granular stress of a settled bed against statics.

A bed at rest on a flat floor: every particle's contact forces carry its weight, the pair forces
cancel in pairs, so the virial summed over the bed is sum_i z_i m_i g - sum_floor z_c F_c =
W (z_mean - z_floor), W the weight, z_mean the mass-weighted mean height of the centres, z_floor
the height of the floor contacts' points. compute stress/atom is minus the virial (N m), so its
zz sum must be -W (z_mean - z_floor). For mesh particles fix tri/wall tallies the floor contacts'
virial (z_floor = 0, the floor's mesh), and the floor's force (compute tri/contact/local wall,
fz summed) must be W. LIGGGHTS's fix wall/gran tallies none, so for its spheres the sum is the
pair contacts' alone: -W (z_mean - R), the floor contacts acting R below the centres of the
bottom layer.

Pours the beds of run_bulk.py (its geometry, material and settling; N particles of
volume-equivalent diameter 4 mm) and prints a table:
  /usr/bin/python3 stress.py [--n 150] [--Y 5e6] [--tsettle 0.3] [--work /tmp/bulk_stress]
"""
import argparse
import json
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, ".."))
import run_bulk  # noqa: E402  (geometry, deck variables, meshes)
import valtools  # noqa: E402

SHAPES = [("spheres", "sphere", None), ("icosphere320", "tri", "icosphere2"),
          ("cube", "tri", "cube"), ("tetrahedron", "tri", "tetrahedron")]
WIDTH_D = 5.0  # column width in diameters
LINE = re.compile(r"^stress: (.*)$", re.M)


def run(name, kind, shape, args, meshdir, floor):
    study = "ico" if kind == "sphere" or shape.startswith("icosphere") else "platonic"
    geo = run_bulk.geometry(study, args.n, WIDTH_D)
    case = dict(name=name, study=study, Y=args.Y, kind=kind, seed=0, shape=shape,
                layer="inside")
    out = os.path.join(args.work, name)
    os.makedirs(out, exist_ok=True)
    v = run_bulk.deck_vars(case, geo, args.n, out, meshdir, floor, False, 0)
    v["tsettle"] = args.tsettle
    v["dt"] *= args.dt_scale
    exe = args.exe if kind == "tri" else args.liggghts
    deck = os.path.join(HERE, "in.stress_tri" if kind == "tri" else "in.stress_spheres")
    cmd = ["nice", "-n", "10"] + valtools.deck_command(exe, deck, v, os.path.join(out, "log"))
    r = subprocess.run(cmd, cwd=HERE, env=valtools.run_env(1), capture_output=True, text=True,
                       errors="replace")
    m = LINE.search(r.stdout)
    if r.returncode != 0 or not m:
        print(f"{name}: FAILED (exit {r.returncode})\n{r.stdout[-2000:]}")
        return None
    words = m.group(1).split()
    vals = {words[k]: float(words[k + 1]) for k in range(0, len(words), 2)}
    z_floor = 0.0 if kind == "tri" else run_bulk.D / 2
    expected = -vals["weight"] * (vals["zcm"] - z_floor)
    return dict(name=name, **vals, expected=expected, rel=vals["zz"] / expected - 1.0,
                floor_rel=(vals["floor"] / vals["weight"] - 1.0) if kind == "tri" else None)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, default=150)
    ap.add_argument("--Y", type=float, default=5e6)
    ap.add_argument("--tsettle", type=float, default=0.3, help="settling after run.in (s)")
    ap.add_argument("--dt-scale", type=float, default=1.0, help="time step x this (default 1)")
    ap.add_argument("--only", nargs="*", help="these of " + " ".join(n for n, _, _ in SHAPES))
    ap.add_argument("--work", default="/tmp/bulk_stress")
    ap.add_argument("--exe", default=valtools.default_exe())
    ap.add_argument("--liggghts", default="liggghts")
    args = ap.parse_args()
    meshdir = os.path.join(args.work, "meshes")
    os.makedirs(meshdir, exist_ok=True)
    floor = os.path.join(meshdir, "floor.stl")
    run_bulk.meshgen.write_stl(floor, *run_bulk.meshgen.plane(WIDTH_D * run_bulk.D / 2), "floor")
    print(valtools.machine_line())
    rows = []
    for name, kind, shape in SHAPES:
        if args.only and name not in args.only:
            continue
        res = run(name, kind, shape, args, meshdir, floor)
        if res:
            rows.append(res)
            fl = "" if res["floor_rel"] is None else f"{100 * res['floor_rel']:+.3f} %"
            print(f"{name:14s} sum szz {res['zz']:.5g} N m, -W (z_mean - z_floor) "
                  f"{res['expected']:.5g}: {100 * res['rel']:+.3f} %; floor force / W {fl}; "
                  f"sum sxz {res['xz']:.2g}, syz {res['yz']:.2g}", flush=True)
    if args.only or args.dt_scale != 1.0:
        return
    with open(os.path.join(HERE, "results", "stress.json"), "w") as f:
        json.dump(dict(machine=valtools.machine_line(), n=args.n, Y=args.Y, rows=rows), f,
                  indent=1)


if __name__ == "__main__":
    main()
