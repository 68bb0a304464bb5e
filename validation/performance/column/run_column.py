#!/usr/bin/env python3
"""The column benchmark: mesh rocks against LIGGGHTS spheres of equal mass, each side at its own
best neighbour skin. A program, not a test.

512 rocks of 40 triangles (in.column, liggghts-tri) and their sphere twin (in.column_spheres,
plain liggghts: spheres of the rock's volume, so equal mass) start spinning on a lattice 4.5 mm
apart and settle on a mesh floor in a column periodic in x and y. Two materials (--mat):
`stiffness` (hooke/stiffness: kn 2000 N/m, kt 1000, gamman 2000 1/s, gammat 1000, mu 0.5,
epsilon 0.1 mm) and `hooke` (LIGGGHTS hooke: Y 5e6, nu 0.45, e 0.5, mu 0.5, v_c 1 m/s, epsilon
auto). Phases (--phases):

  settled  from a restart of the settled bed (t = 0.4 s)
  free     the spinning lattice without gravity: free flight, no particle ever touches another
  gas      no floor, no gravity, periodic in z: velocities up to 0.5 m/s per component, from a
           restart at t = 0.01 s (short, fresh contacts)

Each phase is measured at every neighbour skin of --skins (mm): each side's restart is re-read
with `neighbor SKIN bin`, spheres and rocks back to back, --repeat times. A measured run is
--chunks runs of --steps (--free-steps, --gas-steps) steps, the spheres --sphere-factor times
as many (but in the gas, which cools: there both sides run the same steps, the same simulated
window), one after the other in one process; the fastest of them is its time per step (a shared
machine slows some of them down). The table gives, per
skin, each side's ms/step (LIGGGHTS's loop time; the best of the repetitions and their median) and
CPU ms/step (the process's CPU time minus that of a 1-step run of the same configuration), the
ratio at equal skins, each side's best skin (lowest best-of-repetitions ms/step) and the ratio
best / best (and the median of the back-to-back pairs' ratios at those skins).

--cubes: the settled bed of ~500 cubes (side 3.224 mm, the volume of a 4 mm sphere) poured into
a 32 mm column periodic in x and y (validation/bulk's Platonic deck, LIGGGHTS hooke Y 5e6), as
mesh cubes of 12 triangles (liggghts-tri, dt 3e-5 s) and as LIGGGHTS multisphere clumps of 8
and 27 spheres (plain liggghts, dt 1.1e-5 s and 7.5e-6 s): time per step and per simulated
second, each at every skin and then at its best.

  /usr/bin/python3 validation/performance/column/run_column.py [--repeat 3] [--mat stiffness hooke]
      [--phases settled free gas] [--skins 0.2 0.4 0.7 1.0 1.5] [--steps 100] [--chunks 5]
      [--n 8] [--nz N]   (n^2 nz rocks: a column n x 4.5 mm wide and nz layers deep)
      [--tri build/src_plugin/driver/liggghts-tri] [--liggghts /usr/bin/liggghts] [--work /tmp/column_bench]
      [--label NAME] [--prepare]
  /usr/bin/python3 validation/performance/column/run_column.py --cubes [--n-cubes 500] [--repeat 3]
  /usr/bin/python3 validation/performance/column/run_column.py --table RESULTS.json [...]
  /usr/bin/python3 validation/performance/column/run_column.py --plot column.png RESULTS.json

The restart files are written once (--prepare, or whenever missing) under --work, never in the
repository. Every run is checked (exit 0, no ERROR, no lost atoms, no nan), each run with
OMP_NUM_THREADS=1 and one MPI rank. Results go to WORK/column_LABEL.json (WORK/cubes_LABEL.json).
Standard library only, but for --plot (Debian's matplotlib).
"""
import argparse
import json
import math
import os
import platform
import re
import shlex
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", ".."))
import valtools  # noqa: E402
LATTICE_N, LATTICE_S = 8, 0.0045      # in.column's lattice: n^3 rocks, 4.5 mm apart
RHO = 2500.0
COUNTERS = ["pairs_checked", "pairs_in_contact", "triangle_pairs_tested", "triangle_contacts"]
DECK_KEYS = ["k_checked", "k_incontact", "k_tested", "k_tricontacts"]
# --cubes: validation/bulk's Platonic study (run_bulk.py, multisphere.py)
D = 0.004                                          # volume-equivalent diameter of the cube
SIDE = (math.pi / 6.0) ** (1.0 / 3.0) * D          # its side, 3.224 mm
MASS = RHO * math.pi / 6.0 * D ** 3
G = 9.81
CUBE_DT = {"mesh": 3e-5, "clump8": 1.1e-5, "clump27": 7.5e-6}   # validation/bulk's time steps
CUBE_SEED = 67867967                               # run_bulk.py's insertion seed 0


def machine():
    return {"host": platform.node(), "cpu": valtools.cpu_model(), "cores": os.cpu_count(),
            "threads": "OMP_NUM_THREADS=1, 1 MPI rank"}


def loadavg():
    return round(os.getloadavg()[0], 2)


def median(v):
    return statistics.median(v) if v else float("nan")


# ---------------------------------------------------------------------------------------------
# Geometry files


def write_stl(path, tris, name):
    def normal(a, b, c):
        u = [b[i] - a[i] for i in range(3)]
        v = [c[i] - a[i] for i in range(3)]
        n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        ln = math.sqrt(sum(x * x for x in n)) or 1.0
        return [x / ln for x in n]
    with open(path, "w") as f:
        f.write(f"solid {name}\n")
        for a, b, c in tris:
            f.write("facet normal %.9e %.9e %.9e\nouter loop\n" % tuple(normal(a, b, c)))
            for p in (a, b, c):
                f.write("vertex %.9e %.9e %.9e\n" % tuple(p))
            f.write("endloop\nendfacet\n")
        f.write(f"endsolid {name}\n")


def write_floor(path, half):
    """The square [-half, half]^2 at z = 0, normal +z: 2 triangles."""
    a, b, c, d = (-half, -half, 0.0), (half, -half, 0.0), (half, half, 0.0), (-half, half, 0.0)
    write_stl(path, [(a, b, c), (a, c, d)], "floor")


def write_cube(path, side):
    """A cube of the given side centred at the origin, 12 triangles, outward normals."""
    h = side / 2
    v = [(x, y, z) for x in (-h, h) for y in (-h, h) for z in (-h, h)]   # index = 4x + 2y + z
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    tris = []
    for q in quads:
        tris += [(v[q[0]], v[q[1]], v[q[2]]), (v[q[0]], v[q[2]], v[q[3]])]
    # outward: the normal points away from the centre
    out = []
    for a, b, c in tris:
        u = [b[i] - a[i] for i in range(3)]
        w = [c[i] - a[i] for i in range(3)]
        n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
        centre = [(a[i] + b[i] + c[i]) / 3 for i in range(3)]
        out.append((a, b, c) if sum(n[i] * centre[i] for i in range(3)) > 0 else (a, c, b))
    write_stl(path, out, "cube")


def write_clump(path, k, side):
    """k^3 spheres of radius side/(2k) at the cell centres of the cube (validation/bulk)."""
    r = side / (2 * k)
    c = [(-side / 2 + (2 * i + 1) * r) for i in range(k)]
    with open(path, "w") as f:
        f.write(f"# {k}x{k}x{k} spheres of radius s/{2 * k} filling a cube of side {side:.6e} m\n")
        for x in c:
            for y in c:
                for z in c:
                    f.write(f"{x:.9e} {y:.9e} {z:.9e} {r:.9e}\n")


# ---------------------------------------------------------------------------------------------
# Running LIGGGHTS


def parse(text):
    r = {}
    loops = re.findall(r"Loop time of ([\d.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms", text)
    if loops:
        # a measured run may be several runs of the same length (chunks): the fastest one counts
        r["loops"] = [float(m[0]) for m in loops]
        r["loop"] = min(r["loops"])
        r["procs"], r["steps"], r["atoms"] = int(loops[-1][1]), int(loops[-1][2]), int(loops[-1][3])
        r["total_steps"] = sum(int(m[2]) for m in loops)
    for key, name in (("Pair", "pair"), ("Neigh", "neigh"), ("Comm", "comm"), ("Modify", "modify"),
                      ("Other", "other")):
        m = re.search(key + r"\s+time \(%\) = [\d.eE+-]+ \(([\d.eE+-]+)\)", text)
        if m:
            r[name + "_pct"] = float(m[1])
    m = re.findall(r"Neighbor list builds = (\d+)", text)
    if m:
        r["neigh_builds"] = sum(int(x) for x in m)
    m = re.findall(r"Total # of neighbors = (\d+)", text)
    if m:
        r["neighbours"] = int(m[-1])
    for line in re.findall(r"^(?:column|cubes): .*$", text, re.M):
        for k, v in re.findall(r"(\w+) ([-\d.eE+]+)", line.split(":", 1)[1]):
            try:
                r["out_" + k] = float(v)
            except ValueError:
                pass
    r["bad"] = valtools.run_problems(text)
    r["warnings"] = sorted(set(re.findall(r"^WARNING.*$", text, re.M)))
    return r


def run(cmd, cwd, timeout):
    code, text, cpu = valtools.run_measured(cmd, cwd, dict(os.environ, OMP_NUM_THREADS="1"), timeout)
    r = parse(text)
    r["cpu"] = cpu
    if code != 0 or r["bad"] or "loop" not in r:
        sys.exit(f"run failed ({code}, {r['bad']}): {shlex.join(cmd)}\n"
                 f"see {cwd}/screen.txt:\n{text[-1500:]}")
    return r


class Bench:
    """Runs and records; subclasses say what a configuration's command is."""

    def __init__(self, a, name):
        self.a = a
        os.makedirs(a.work, exist_ok=True)
        self.path = os.path.join(a.work, f"{name}_{a.label}.json")
        self.results = []
        self.setup_cpu = {}
        self.m = machine()
        self.runner = run

    def header(self):
        print(f"machine: {self.m['host']}, {self.m['cpu']}, {self.m['cores']} cores; "
              f"{self.m['threads']}; load average {loadavg()}; {time.strftime('%Y-%m-%d %H:%M:%S %Z')}",
              flush=True)

    def timed(self, key, cmd_of, out, timeout):
        """Runs cmd_of(steps) for the measured steps, and once per key a 1-step run for the CPU
        time of start-up, reading and setup."""
        if key not in self.setup_cpu:
            self.setup_cpu[key] = self.runner(cmd_of(1), out + "_setup", timeout)["cpu"]
        cmd, steps = cmd_of(None)
        before = loadavg()
        r = self.runner(cmd, out, timeout)
        r["cpu_ms_per_step"] = 1000.0 * (r["cpu"] - self.setup_cpu[key]) / (r["total_steps"] - 1)
        r["ms_per_step"] = 1000.0 * r["loop"] / r["steps"]
        r.update(load_before=before, load_after=loadavg(), command="OMP_NUM_THREADS=1 " + shlex.join(cmd),
                 time=time.strftime("%Y-%m-%d %H:%M:%S"), label=self.a.label)
        return r

    def save(self):
        json.dump({"machine": self.m, "results": self.results}, open(self.path, "w"), indent=1)


# ---------------------------------------------------------------------------------------------
# The column


class Column(Bench):
    def __init__(self, a):
        super().__init__(a, "column")
        self.cols = valtools.stats_columns(a.stats_tool, COUNTERS)
        # --n other than the lattice's 8: n^2 nz rocks in a column n x 4.5 mm wide, on its own
        # floor (nz: --nz, by default n)
        a.nz = a.nz or a.n
        self.suffix = ("" if a.n == LATTICE_N else f"_n{a.n}") + ("" if a.nz == a.n else f"x{a.nz}")
        self.floor = os.path.join(a.work, f"floor{self.suffix}.stl")
        write_floor(self.floor, a.n * LATTICE_S / 2)
        self.prepared = set()
        self.d = None

    def var(self, kind, mat, mode, out, skin, steps=None, restart=None, g=None):
        v = {"floor": self.floor, "mat": mat, "mode": mode, "out": out, "skin": skin * 1e-3,
             "n": self.a.n, "nz": self.a.nz}
        if steps:
            v["steps"] = steps
            v["chunks"] = self.a.chunks if steps > 1 else 1
        if restart:
            v["restart"] = restart
        if g is not None:
            v["g"] = g
        if kind == "rocks":
            for key, name in zip(DECK_KEYS, COUNTERS):
                v[key] = self.cols[name]
        else:
            v["d"] = "%.9g" % self.sphere_diameter(mat)
        return v

    def command(self, kind, v):
        if kind == "rocks":
            return valtools.deck_command(self.a.tri, os.path.join(HERE, "in.column"), v)
        return valtools.deck_command(self.a.liggghts, os.path.join(HERE, "in.column_spheres"), v)

    def restart(self, kind, mat, phase):
        """The restart file of phase settled (mode settle) or gas (mode gas); made if missing."""
        mode, name = {"settled": ("settle", "settled.restart"), "gas": ("gas", "gas.restart")}[phase]
        d = os.path.join(self.a.work, "prepare", f"{kind}_{mat}_{mode}{self.suffix}")
        path = os.path.join(d, name)
        if (self.a.prepare and d not in self.prepared) or not os.path.exists(path):
            self.prepared.add(d)
            cmd = self.command(kind, dict(self.var(kind, mat, mode, d, 1.0), every=2500))
            print(f"  preparing {kind} {mat} {phase}: {shlex.join(cmd)}", flush=True)
            t0 = time.time()
            r = run(cmd, d, self.a.prepare_timeout)
            json.dump(r, open(os.path.join(d, "prepare.json"), "w"), indent=1)
            print(f"  done in {time.time() - t0:.0f} s: atoms {r.get('out_atoms')}, mass "
                  f"{r.get('out_mass')} kg, kinetic energy {r.get('out_ke'):.3g} J"
                  + (f", bed top {1e3 * r['out_zmax']:.1f} mm" if "out_zmax" in r else "")
                  + "".join("\n    " + w for w in r["warnings"]), flush=True)
        return path

    def sphere_diameter(self, mat):
        """The volume-equivalent diameter of the rock, from the rocks' mass (a 1-step run)."""
        if self.d is None:
            out = os.path.join(self.a.work, "mass")
            v = {"floor": self.floor, "mat": mat, "mode": "free", "out": out, "steps": 1, "skin": 0.001,
                 "n": self.a.n, "nz": self.a.nz}
            r = run(self.command("rocks", v), out, 600)
            m = r["out_mass"] / r["out_atoms"]
            self.d = (6.0 * m / (math.pi * RHO)) ** (1.0 / 3.0)
            self.rock_mass = m
            print(f"rock mass {m:.6e} kg: sphere diameter {1e3 * self.d:.6f} mm", flush=True)
        return self.d

    def measure(self, kind, mat, phase, skin, rep):
        a = self.a
        out = os.path.join(a.work, "runs", f"{a.label}_{kind}_{mat}_{phase}_skin{skin}_{rep}{self.suffix}")
        factor = a.sphere_factor if kind == "spheres" and phase in valtools.STEADY_PHASES else 1
        steps = {"settled": a.steps, "free": a.free_steps, "gas": a.gas_steps}[phase] * factor

        def cmd_of(n):
            if phase == "free":
                v = self.var(kind, mat, "free", out if n is None else out + "_setup", skin, n or steps, g=0)
            else:
                v = self.var(kind, mat, "restart" if phase == "settled" else "gasrestart",
                             out if n is None else out + "_setup", skin, n or steps,
                             restart=self.restart(kind, mat, phase))
            cmd = self.command(kind, v)
            return cmd if n else (cmd, steps)

        r = self.timed((kind, mat, phase, skin), cmd_of, out, a.run_timeout)
        r.update(kind=kind, mat=mat, phase=phase, skin=skin, rep=rep, n=a.n, nz=a.nz)
        if kind == "rocks":
            rows = [l.split() for l in open(os.path.join(out, "counters.txt"))
                    if l.strip() and not l.startswith("#")]
            r["counters"] = dict(zip(COUNTERS, [float(x) for x in rows[-1][1:]]))
        elif "out_mass" in r and abs(r["out_mass"] / r["out_atoms"] / self.rock_mass - 1) > 1e-6:
            sys.exit(f"a sphere's mass {r['out_mass'] / r['out_atoms']} kg is not a rock's "
                     f"{self.rock_mass} kg")
        self.results.append(r)
        self.save()
        return r

    def go(self):
        a = self.a
        self.header()
        print(f"liggghts-tri: {a.tri}\nliggghts: {a.liggghts}\nlabel: {a.label}", flush=True)
        for mat in a.mat:
            self.sphere_diameter(mat)
            for phase in a.phases:
                if phase != "free":
                    for kind in ("rocks", "spheres"):
                        self.restart(kind, mat, phase)
        for rep in range(a.repeat):
            for mat in a.mat:
                for phase in a.phases:
                    for skin in a.skins:
                        s = self.measure("spheres", mat, phase, skin, rep)
                        r = self.measure("rocks", mat, phase, skin, rep)
                        c = r["counters"]
                        print(f"rep {rep} {mat:9s} {phase:7s} skin {skin:3.1f} mm: spheres "
                              f"{s['ms_per_step']:7.4f} ms (CPU {s['cpu_ms_per_step']:7.4f}, "
                              f"{s['neigh_builds']:4d} builds), rocks {r['ms_per_step']:7.3f} ms (CPU "
                              f"{r['cpu_ms_per_step']:7.3f}, {r['neigh_builds']:3d} builds) "
                              f"{r['ms_per_step'] / s['ms_per_step']:6.1f}x | checked "
                              f"{c['pairs_checked']:.0f} in contact {c['pairs_in_contact']:.0f} | load "
                              f"{r['load_after']:.1f}", flush=True)
        print(f"results: {self.path}\n")
        print(column_table(self.results))


def column_summary(results):
    """(mat, phase) -> per skin: each side's best (lowest) and median ms/step and CPU ms/step
    over the repetitions, the median of the per-repetition ratios of the back-to-back pairs; each
    side's best skin (the lowest best-of-repetitions ms/step; for CPU time, of CPU ms/step) and
    the ratios at those skins: best / best, and the median of the per-repetition ratios."""
    runs = {}
    for r in results:
        n = r.get("n", LATTICE_N)
        nz = r.get("nz", n)
        mat = r["mat"] if n == LATTICE_N and nz == n else f"{r['mat']}, {n * n * nz} rocks"
        runs.setdefault((mat, r["phase"]), {}).setdefault(r["skin"], {}).setdefault(
            (r["label"], r["rep"]), {})[r["kind"]] = r
    out = {}
    for key, skins in runs.items():
        rows = {}
        for skin, reps in sorted(skins.items()):
            pairs = [v for v in reps.values() if "rocks" in v and "spheres" in v]
            e = {"reps": len(pairs), "counters": pairs[-1]["rocks"].get("counters", {}),
                 "spheres_steps": pairs[0]["spheres"].get("total_steps", pairs[0]["spheres"]["steps"]),
                 "rocks_steps": pairs[0]["rocks"].get("total_steps", pairs[0]["rocks"]["steps"]),
                 "loads": [p["rocks"]["load_after"] for p in pairs] + [p["spheres"]["load_before"] for p in pairs]}
            for kind in ("spheres", "rocks"):
                ms = [p[kind]["ms_per_step"] for p in pairs]
                cpu = [p[kind]["cpu_ms_per_step"] for p in pairs]
                e.update({kind: min(ms), kind + "_median": median(ms), kind + "_cpu": min(cpu),
                          kind + "_cpu_median": median(cpu),
                          kind + "_builds": median([p[kind]["neigh_builds"] for p in pairs])})
            e["ratio"] = e["rocks"] / e["spheres"]
            e["ratio_median"] = median([p["rocks"]["ms_per_step"] / p["spheres"]["ms_per_step"] for p in pairs])
            e["cpu_ratio"] = e["rocks_cpu"] / max(e["spheres_cpu"], 1e-9)
            e["cpu_short"] = not all(valtools.cpu_measurable(p[k]) for p in pairs
                                     for k in ("spheres", "rocks"))
            rows[skin] = e
        bs = min(rows, key=lambda s: rows[s]["spheres"])
        br = min(rows, key=lambda s: rows[s]["rocks"])
        bs_cpu = min(rows, key=lambda s: rows[s]["spheres_cpu"])
        br_cpu = min(rows, key=lambda s: rows[s]["rocks_cpu"])
        cpu_short = any(e["cpu_short"] for e in rows.values())
        reps = set(skins[bs]) & set(skins[br])
        paired = median([skins[br][i]["rocks"]["ms_per_step"] / skins[bs][i]["spheres"]["ms_per_step"]
                         for i in reps])
        out[key] = {"rows": rows, "best_spheres": bs, "best_rocks": br,
                    "best_ratio": rows[br]["rocks"] / rows[bs]["spheres"], "best_ratio_paired": paired,
                    "best_spheres_cpu": bs_cpu, "best_rocks_cpu": br_cpu,
                    "best_cpu_ratio": None if cpu_short else
                    rows[br_cpu]["rocks_cpu"] / max(rows[bs_cpu]["spheres_cpu"], 1e-9)}
    return out


def column_table(results):
    lines = ["| material | phase | skin (mm) | spheres ms/step best (median) | rocks ms/step best (median) "
             "| ratio best (median of pairs) | spheres CPU ms/step | rocks CPU ms/step | CPU ratio "
             "| neighbour builds spheres / rocks | pairs checked / in contact | load |",
             "|---|---|---:|---:|---:|---:|---:|---:|---:|---|---|---|"]
    best = ["| material | phase | spheres' best skin (mm) | rocks' best skin (mm) | spheres ms/step | rocks ms/step "
            "| **ratio best / best** | median of the pairs at those skins | ratio at equal skins | "
            "CPU: best skins spheres / rocks | CPU ratio best / best |",
            "|---|---|---:|---:|---:|---:|---:|---:|---|---|---:|"]
    for (mat, phase), s in column_summary(results).items():
        rows = s["rows"]
        for skin, e in rows.items():
            mark_s = " *" if skin == s["best_spheres"] else ""
            mark_r = " *" if skin == s["best_rocks"] else ""
            c = e["counters"]
            lines.append(
                f"| {mat} | {phase} | {skin:g} | {e['spheres']:.4f}{mark_s} ({e['spheres_median']:.4f}) | "
                f"{e['rocks']:.3f}{mark_r} ({e['rocks_median']:.3f}) | {e['ratio']:.1f}x ({e['ratio_median']:.1f}x) | "
                + (f"– | – | – | " if e["cpu_short"] else
                   f"{e['spheres_cpu']:.4f} | {e['rocks_cpu']:.3f} | {e['cpu_ratio']:.1f}x | ") +
                f"{e['spheres_builds']:g} in {e['spheres_steps']} / {e['rocks_builds']:g} in {e['rocks_steps']} | "
                f"{c.get('pairs_checked', 0):.0f} / {c.get('pairs_in_contact', 0):.0f} | "
                f"{min(e['loads']):.1f}-{max(e['loads']):.1f} |")
        eq = [e["ratio"] for e in rows.values()]
        bs, br = s["best_spheres"], s["best_rocks"]
        best.append(f"| {mat} | {phase} | {bs:g} | {br:g} | {rows[bs]['spheres']:.4f} | {rows[br]['rocks']:.3f} | "
                    f"**{s['best_ratio']:.1f}x** | {s['best_ratio_paired']:.1f}x | {min(eq):.1f}x-{max(eq):.1f}x | "
                    + ("– | – |" if s["best_cpu_ratio"] is None else
                       f"{s['best_spheres_cpu']:g} / {s['best_rocks_cpu']:g} | {s['best_cpu_ratio']:.1f}x |"))
    return ("Per skin (best of the repetitions, median in brackets; CPU: best; * = the side's best skin):\n\n"
            + "\n".join(lines) + "\n\nEach side at its best skin:\n\n" + "\n".join(best))


# ---------------------------------------------------------------------------------------------
# Cubes: mesh cubes against multisphere clumps


class Cubes(Bench):
    KINDS = ["mesh", "clump8", "clump27"]

    def __init__(self, a):
        super().__init__(a, "cubes")
        self.runner = run_in
        w = a.cube_width_d * D
        n = a.n_cubes
        reach = 0.0029                     # the cube's bounding radius 2.79 mm and a margin
        bed = n * MASS / RHO / (0.45 * w * w)
        zlo = bed + 2 * reach + 0.003
        zhi = zlo + n * 4.0 / 3.0 * math.pi * reach ** 3 / (0.2 * w * w)   # bounding spheres 20 %
        self.geo = dict(W=w, H=zhi + 0.005, zlo=zlo, zhi=zhi, tpour=1.05 * zhi / 1.0 + 0.05)
        self.floor = os.path.join(a.work, "cube_floor.stl")
        write_floor(self.floor, w / 2)
        self.shape = os.path.join(a.work, "cube.stl")
        write_cube(self.shape, SIDE)
        for k in (2, 3):
            write_clump(os.path.join(a.work, f"clump{k ** 3}.txt"), k, SIDE)
        self.prepared = set()

    def var(self, kind, mode, out, skin, steps=None, restart=None):
        g = self.geo
        v = dict(W=g["W"], H=g["H"], floor=self.floor, Y=5e6, dt=CUBE_DT[kind], skin=skin * 1e-3,
                 mode=mode, out=out, N=self.a.n_cubes, zlo=g["zlo"], zhi=g["zhi"], seed=CUBE_SEED,
                 tpour=g["tpour"], tchunk=0.02, nsettle=15, kemin=1e-3 * self.a.n_cubes * MASS * G * D)
        if steps:
            v["steps"] = steps
            v["chunks"] = self.a.chunks if steps > 1 else 1
        if restart:
            v["restart"] = restart
        if kind == "mesh":
            v.update(shape=self.shape, oseed=99, gamma=MASS * G / 1.0)
        else:
            k3 = int(kind[len("clump"):])
            v.update(spheres=os.path.join(self.a.work, f"{kind}.txt"), nsph=k3, rho=RHO * 6.0 / math.pi,
                     ntry=1000000, gamma=MASS * G / 1.0 / k3)
        return v

    def command(self, kind, v):
        if kind == "mesh":
            return valtools.deck_command(self.a.tri, os.path.join(HERE, "in.cubes_mesh"), v)
        return valtools.deck_command(self.a.liggghts, os.path.join(HERE, "in.cubes_clumps"), v)

    def restart(self, kind):
        d = os.path.join(self.a.work, "prepare", f"cubes_{kind}_n{self.a.n_cubes}")
        path = os.path.join(d, "settled.restart")
        if (self.a.prepare and d not in self.prepared) or not os.path.exists(path):
            self.prepared.add(d)
            cmd = self.command(kind, self.var(kind, "pour", d, 1.0))
            print(f"  preparing {kind}: {shlex.join(cmd)}", flush=True)
            t0 = time.time()
            r = run_in(cmd, d, self.a.prepare_timeout)
            json.dump(r, open(os.path.join(d, "prepare.json"), "w"), indent=1)
            print(f"  done in {time.time() - t0:.0f} s: atoms {r.get('out_atoms')}, settled at t = "
                  f"{r.get('out_t')} s, kinetic energy {r.get('out_ke'):.3g} J"
                  + "".join("\n    " + w for w in r["warnings"]), flush=True)
        return path

    def measure(self, kind, skin, rep):
        a = self.a
        out = os.path.join(a.work, "runs", f"{a.label}_cubes_{kind}_skin{skin}_{rep}")
        steps = a.cube_steps[self.KINDS.index(kind)]

        def cmd_of(n):
            o = out if n is None else out + "_setup"
            cmd = self.command(kind, self.var(kind, "restart", o, skin, n or steps, self.restart(kind)))
            return cmd if n else (cmd, steps)

        r = self.timed((kind, skin), cmd_of, out, a.run_timeout)
        r.update(kind=kind, skin=skin, rep=rep, dt=CUBE_DT[kind], n_cubes=a.n_cubes)
        self.results.append(r)
        self.save()
        return r

    def go(self):
        a = self.a
        self.header()
        g = self.geo
        print(f"liggghts-tri: {a.tri}\nliggghts: {a.liggghts}\nlabel: {a.label}\n{a.n_cubes} cubes of "
              f"side {SIDE * 1e3:.4f} mm, column {g['W'] * 1e3:.0f} mm, insertion z {g['zlo'] * 1e3:.0f}-"
              f"{g['zhi'] * 1e3:.0f} mm, pour {g['tpour']:.3f} s", flush=True)
        for kind in self.KINDS:
            self.restart(kind)
        for rep in range(a.repeat):
            for skin in a.cube_skins:
                line = []
                for kind in self.KINDS:
                    r = self.measure(kind, skin, rep)
                    line.append(f"{kind} {r['ms_per_step']:.3f} ms (CPU {r['cpu_ms_per_step']:.3f})")
                print(f"rep {rep} skin {skin:3.1f} mm: " + ", ".join(line) + f" | load {loadavg():.1f}",
                      flush=True)
        print(f"results: {self.path}\n")
        print(cubes_table(self.results))


def run_in(cmd, cwd, timeout):
    """run() with the decks' include files found: LIGGGHTS reads include paths from its working
    folder, so the cube decks run in a folder that links them."""
    os.makedirs(cwd, exist_ok=True)
    for f in ("cubes_common.in", "cubes_insert.in", "cubes_run.in"):
        link = os.path.join(cwd, f)
        if not os.path.exists(link):
            os.symlink(os.path.join(HERE, f), link)
    return run(cmd, cwd, timeout)


def cubes_table(results):
    runs = {}
    for r in results:
        runs.setdefault(r["kind"], {}).setdefault(r["skin"], []).append(r)
    lines = ["| cubes as | bodies (atoms) | dt (s) | skin (mm) | ms/step | CPU ms/step | neighbour builds "
             "| wall s per simulated s | CPU s per simulated s | load |",
             "|---|---|---:|---:|---:|---:|---|---:|---:|---|"]
    best = {}
    for kind, skins in runs.items():
        meds = {s: min(r["ms_per_step"] for r in rs) for s, rs in skins.items()}
        bs = min(meds, key=meds.get)
        for skin, rs in sorted(skins.items()):
            ms = meds[skin]
            cpu = min(r["cpu_ms_per_step"] for r in rs)
            dt = rs[0]["dt"]
            loads = [r["load_after"] for r in rs]
            lines.append(f"| {kind} | {rs[0]['n_cubes']} ({rs[0]['atoms']}) | {dt:g} | {skin:g}"
                         f"{' *' if skin == bs else ''} | {ms:.3f} | {cpu:.3f} | "
                         f"{median([r['neigh_builds'] for r in rs]):g} in {rs[0].get('total_steps', rs[0]['steps'])} | "
                         f"{ms * 1e-3 / dt:.1f} | {cpu * 1e-3 / dt:.1f} | {min(loads):.1f}-{max(loads):.1f} |")
        best[kind] = (bs, meds[bs], skins[bs][0]["dt"], min(r["cpu_ms_per_step"] for r in skins[bs]))
    out = ["| cubes as | best skin (mm) | ms/step | steps per simulated s | wall s per simulated s "
           "| per step / mesh | per simulated s / mesh | CPU per simulated s / mesh |", "|---|---:|---:|---:|---:|---:|---:|---:|"]
    if "mesh" in best:
        m = best["mesh"]
        for kind, (bs, ms, dt, cpu) in best.items():
            out.append(f"| {kind} | {bs:g} | {ms:.3f} | {1 / dt:.0f} | {ms * 1e-3 / dt:.1f} | {ms / m[1]:.2f} | "
                       f"{(ms / dt) / (m[1] / m[2]):.2f} | {(cpu / dt) / (m[3] / m[2]):.2f} |")
    return ("Per skin (best of the repetitions; * = the best skin):\n\n" + "\n".join(lines) +
            "\n\nEach at its best skin:\n\n" + "\n".join(out))


# ---------------------------------------------------------------------------------------------
# Figure


def plot(png, paths):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    results = []
    for p in paths:
        results += json.load(open(p))["results"]
    summ = column_summary(results)
    mats = list(dict.fromkeys(k[0] for k in summ))
    phases = list(dict.fromkeys(k[1] for k in summ))
    fig, axes = plt.subplots(len(phases), len(mats), figsize=(5.2 * len(mats), 3.6 * len(phases)),
                             squeeze=False)
    for i, phase in enumerate(phases):
        for j, mat in enumerate(mats):
            ax = axes[i][j]
            s = summ.get((mat, phase))
            if not s:
                ax.axis("off")
                continue
            rows = s["rows"]
            skins = sorted(rows)
            for kind, colour, best in (("spheres", "tab:blue", s["best_spheres"]),
                                       ("rocks", "tab:red", s["best_rocks"])):
                ax.plot(skins, [rows[k][kind] for k in skins], "o-", color=colour,
                        label=f"{kind} (loop time)")
                if s["best_cpu_ratio"] is not None: # else too short a CPU time to mean anything
                    ax.plot(skins, [rows[k][kind + "_cpu"] for k in skins], "x--", color=colour,
                            alpha=0.6, label=f"{kind} (CPU time)")
                ax.plot([best], [rows[best][kind]], "*", color=colour, markersize=16,
                        markeredgecolor="k", label=f"{kind}' best: {best:g} mm" if kind == "rocks"
                        else f"spheres' best: {best:g} mm")
            ax.set_yscale("log")
            ax.set_xlabel("neighbour skin (mm)")
            ax.set_ylabel("ms per step")
            ax.set_title(f"{phase}, {mat}: best / best {s['best_ratio']:.1f}x", fontsize=10)
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=7)
    fig.suptitle("512 rocks of 40 triangles vs 512 spheres of equal mass, 1 thread", fontsize=11)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print(f"wrote {png}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--tri", default=valtools.default_exe())
    ap.add_argument("--liggghts", default="/usr/bin/liggghts")
    ap.add_argument("--stats-tool", default=None, help="tri-stats-columns (default: beside --tri)")
    ap.add_argument("--work", default="/tmp/column_bench")
    ap.add_argument("--label", default="column")
    ap.add_argument("--mat", nargs="+", default=["stiffness", "hooke"], choices=["stiffness", "hooke"])
    ap.add_argument("--phases", nargs="+", default=["settled", "free", "gas"],
                    choices=["settled", "free", "gas"])
    ap.add_argument("--skins", nargs="+", type=float, default=[0.2, 0.4, 0.7, 1.0, 1.5])
    ap.add_argument("--n", type=int, default=LATTICE_N,
                    help="n^3 rocks (and spheres) on an n x n x n lattice, the column n x 4.5 mm wide")
    ap.add_argument("--nz", type=int, help="lattice layers (default n): n^2 nz rocks, a bed nz deep")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--steps", type=int, default=100, help="rocks' steps per chunk in the settled phase")
    ap.add_argument("--free-steps", type=int, default=1000)
    ap.add_argument("--gas-steps", type=int, default=100)
    ap.add_argument("--chunks", type=int, default=5,
                    help="each measured run is this many runs of the steps, one after the other: the fastest counts")
    ap.add_argument("--sphere-factor", type=int, default=20, help="the spheres run this many times the steps (not in the gas: the same window)")
    ap.add_argument("--prepare", action="store_true", help="rewrite the restart files")
    ap.add_argument("--prepare-timeout", type=int, default=1800)
    ap.add_argument("--run-timeout", type=int, default=600)
    ap.add_argument("--cubes", action="store_true", help="mesh cubes against multisphere clumps")
    ap.add_argument("--n-cubes", type=int, default=500)
    ap.add_argument("--cube-width-d", type=float, default=8.0, help="column width in d = 4 mm")
    ap.add_argument("--cube-skins", nargs="+", type=float, default=[0.2, 0.4, 0.7, 1.0, 1.5])
    ap.add_argument("--cube-steps", nargs=3, type=int, default=[100, 300, 150],
                    metavar=("MESH", "CLUMP8", "CLUMP27"))
    ap.add_argument("--table", nargs="+", metavar="JSON", help="only print the tables of these results")
    ap.add_argument("--plot", metavar="PNG", help="draw the column figure from the JSON files of --table")
    a = ap.parse_args()
    if a.plot:
        plot(a.plot, a.table or [])
        return
    if a.table:
        results = []
        for p in a.table:
            results += json.load(open(p))["results"]
        col = [r for r in results if "mat" in r]
        cub = [r for r in results if "n_cubes" in r]
        if col:
            print(column_table(col))
        if cub:
            print(cubes_table(cub))
        return
    if not a.stats_tool:
        a.stats_tool = os.path.join(os.path.dirname(os.path.abspath(a.tri)), "tri-stats-columns")
        if not os.path.exists(a.stats_tool):
            a.stats_tool = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(a.tri))),
                                        "tools", "tri-stats-columns")
    (Cubes(a) if a.cubes else Column(a)).go()


if __name__ == "__main__":
    main()
