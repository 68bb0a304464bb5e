#!/usr/bin/env python3
"""The pile benchmark: mesh particles against LIGGGHTS spheres of equal mass, where
granular material spends its time. A program, not a test.

n^3 spinning rocks (20 or 40 triangles, in.pile) fall from a lattice into an open box and
settle into a pile on its mesh floor; the sphere twin (in.pile_spheres, plain liggghts) does
the same with spheres of the rocks' mean volume. For each configuration the script runs the
spheres and the rocks back to back, phase by phase, and prints ms per step and the ratio:

  free     --free-steps steps from the lattice without gravity (free flight: the spinning
           particles never touch; the hopper: its first steps of free fall)
  forming  --steps steps from a restart at t = 0.06 s (the lower layers have landed, the upper
           ones are landing)
  settled  --steps steps from a restart at t = 0.3 s (the settled pile)

--geometry hopper measures the paper's hopper (phases free, formed: from t = 0.2 s);
--geometry gas a granular gas (in.gas, in.gas_spheres: n^3 spinning rocks in a periodic box,
no gravity, colliding; phase gas: --steps steps from a restart at t = 0.03 s, when every
contact is a short, fresh one).

The restart files are written once per binary (--prepare, or whenever missing: one run of the
whole settling per configuration, minutes) under --work, so a measured phase is short. Every
phase runs at each neighbour skin of --skins (mm), both sides, and the tables compare each side
at its fastest skin (a sphere deck runs at its own best settings, the rocks at theirs). The
spheres run --sphere-factor times the steps in the steady phases (free, settled); in the others
(a pile forming, a hopper discharging, a gas cooling) both sides run the same steps, the same
simulated window. For the
rocks it also prints the counters of compute tri/stats per step (averaged over the measured
steps, columns by name from tri-stats-columns): pairs checked / in contact, triangle pairs
tested / within the layers, fallbacks.

  /usr/bin/python3 validation/performance/pile/run_pile.py [--n 8] [--ntri 20 40] [--steps 300]
      [--repeat 2] [--skins 0.2 0.4 0.7 1.0 1.5] [--threads 1 2] [--ranks 1 2] [--phases free forming settled]
      [--tri build/src_plugin/driver/liggghts-tri] [--liggghts /usr/bin/liggghts]
      [--work /tmp/pile_bench] [--label NAME] [--prepare]
  /usr/bin/python3 validation/performance/pile/run_pile.py --plot pile.png --label main --label speed
  /usr/bin/python3 validation/performance/pile/run_pile.py --floors floors.png --label a --label b

Every run is checked (exit status 0, no ERROR, no lost atoms, no nan). Results are appended to
WORK/results_LABEL.json; --plot draws the PNG of one or more labels (Debian's matplotlib).
Standard library only otherwise.
"""
import argparse
import itertools
import json
import os
import platform
import re
import shlex
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", ".."))
import valtools  # noqa: E402
REPO = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
DT = 2e-5
T_FORM, T_SETTLE = 0.06, 0.3  # the pile: forming, settled
T_HOPPER = 0.2  # the hopper: the pile has formed in the funnel (the measurement)
T_GAS = 0.03  # the gas: its warm-up, long after the first collisions of the lattice
SKINS = [0.2, 0.4, 0.7, 1.0, 1.5]  # mm: each side is measured at each, and compared at its best
HOPPER = os.path.join(REPO, "examples", "hopper")
COUNTERS = ["pairs_checked", "pairs_in_contact", "triangle_pairs_tested", "contacts_before",
            "triangle_contacts", "fallbacks"]
DECK_KEYS = ["k_checked", "k_incontact", "k_tested", "k_before", "k_tricontacts", "k_fallbacks"]
MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1"}


def sh(cmd):
    try:
        return subprocess.run(cmd, shell=True, capture_output=True, text=True).stdout.strip()
    except OSError:
        return ""


def loadavg():
    return list(os.getloadavg())


def machine():
    model = "?"
    for line in sh("lscpu").splitlines():
        if line.startswith("Model name:"):
            model = line.split(":", 1)[1].strip()
    return {"host": platform.node(), "cpu": model, "cores": os.cpu_count(),
            "compiler": (sh("g++ --version").splitlines() or ["?"])[0],
            "mpirun": (sh("mpirun --version").splitlines() or ["?"])[0]}


def stats_columns(tri):
    """name -> 1-based column of compute tri/stats, from tri-stats-columns beside the driver."""
    tool = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(tri))), "tools",
                        "tri-stats-columns")
    return valtools.stats_columns(tool, COUNTERS)


def parse(text):
    r = {}
    m = re.search(r"Loop time of ([\d.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms", text)
    if m:
        r["loop"], r["procs"], r["steps"], r["atoms"] = float(m[1]), int(m[2]), int(m[3]), int(m[4])
    for key, name in (("Pair", "pair"), ("Neigh", "neigh"), ("Comm", "comm"), ("Other", "other")):
        m = re.search(key + r"\s+time \(%\) = ([\d.eE+-]+)", text)
        if m:
            r[name] = float(m[1])
    m = re.search(r"pile timing: fix tri/wall ([\d.eE+-]+) s", text)
    if m:
        r["wall"] = float(m[1])
    r["bad"] = valtools.run_problems(text)
    return r


def read_counters(path):
    rows = [l.split() for l in open(path) if l.strip() and not l.startswith("#")]
    return dict(zip(COUNTERS, [float(v) for v in rows[-1][1:]]))


class Bench:
    def __init__(self, a):
        self.a = a
        os.makedirs(a.work, exist_ok=True)
        self.cols = stats_columns(a.tri)
        self.results_path = os.path.join(a.work, f"results_{a.label}.json")
        self.results = json.load(open(self.results_path)) if os.path.exists(self.results_path) else []
        self.prepared = set()
        self.setup_cpu = {}

    def command(self, kind, n, ntri, mode, ranks, out, restart=None, steps=None, phase=None,
                skin=None):
        a = self.a
        stem = {"pile": "in.pile", "hopper": "in.hopper_phase", "gas": "in.gas"}[a.geometry]
        deck = os.path.join(HERE, stem if kind == "rocks" else stem + "_spheres")
        exe = a.tri if kind == "rocks" else a.liggghts
        var = {"dir": HOPPER if a.geometry == "hopper" else HERE, "n": n, "ntri": ntri, "mode": mode,
               "out": out, "px": ranks}
        if steps:
            var["steps"] = steps
        if skin is not None:
            var["skin"] = skin * 1e-3  # mm -> m; the settling keeps the decks' 1 mm
        if phase == "free" and a.geometry == "pile":
            var["g"] = 0  # the spinning lattice floats: free flight for as many steps as asked
        if restart:
            var["restart"] = restart
        if mode == "settle":
            var.update({"pile": {"tform": T_FORM, "tsettle": T_SETTLE},
                        "hopper": {"tform": T_HOPPER},
                        "gas": {"tgas": T_GAS}}[a.geometry], every=2500)
        if kind == "rocks":
            for key, name in zip(DECK_KEYS, COUNTERS):
                var[key] = self.cols[name]
        cmd = (["mpirun", "-np", str(ranks)] if ranks > 1 else []) + [exe, "-in", deck, "-log", "none"]
        for k, v in var.items():
            cmd += ["-var", k, str(v)]
        return cmd

    def run(self, cmd, cwd, threads, timeout):
        env = dict(os.environ, OMP_NUM_THREADS=str(threads), **MPI_ENV)
        code, text, cpu = valtools.run_measured(cmd, cwd, env, timeout)
        r = parse(text)
        r["cpu"] = cpu
        if code != 0 or r["bad"] or "loop" not in r:
            sys.exit(f"run failed ({code}, {r['bad']}): {shlex.join(cmd)}\n"
                     f"see {cwd}/screen.txt:\n{text[-1500:]}")
        return r

    def restarts(self, kind, n, ntri):
        """The folder holding forming.restart and settled.restart of (kind, n, ntri)."""
        d = os.path.join(self.a.work, f"restart_{self.a.label}", f"{self.a.geometry}_{kind}_n{n}_t{ntri}")
        last = {"pile": "settled.restart", "hopper": "formed.restart", "gas": "gas.restart"}[self.a.geometry]
        if (self.a.prepare and d not in self.prepared) or not os.path.exists(os.path.join(d, last)):
            self.prepared.add(d)
            os.makedirs(d, exist_ok=True)
            cmd = self.command(kind, n, ntri, "settle", 1, d)
            print(f"  settling {kind} n={n} ntri={ntri}: {shlex.join(cmd)}", flush=True)
            t0 = time.time()
            self.run(cmd, d, 1, self.a.settle_timeout)
            print(f"  settled in {time.time() - t0:.0f} s", flush=True)
        return d

    def measure(self, kind, n, ntri, phase, threads, ranks, rep, skin):
        a = self.a
        out = os.path.join(a.work, "runs", f"{a.label}_{a.geometry}_{kind}_n{n}_t{ntri}_{phase}_"
                                           f"{threads}x{ranks}_skin{skin:g}_{rep}")
        os.makedirs(out, exist_ok=True)
        restart = None
        if phase != "free":
            restart = os.path.join(self.restarts(kind, n, ntri), phase + ".restart")
        mode = "free" if phase == "free" else "restart"
        # CPU time of the process(es) per step: the run's minus that of a 1-step run (start-up,
        # reading, setup), which a loaded machine distorts less than the wall-clock loop time.
        key = (kind, n, ntri, phase, threads, ranks, skin)
        if key not in self.setup_cpu:
            setup_dir = out + "_setup"
            os.makedirs(setup_dir, exist_ok=True)
            self.setup_cpu[key] = self.run(self.command(kind, n, ntri, mode, ranks, setup_dir,
                                                        restart, 1, phase, skin), setup_dir,
                                           threads, a.run_timeout)["cpu"]
        steps = a.free_steps if phase == "free" else a.steps
        if kind == "spheres" and phase in valtools.STEADY_PHASES:
            steps *= a.sphere_factor  # cheap: more steps, for a CPU time well above the noise
        cmd = self.command(kind, n, ntri, mode, ranks, out, restart, steps, phase, skin)
        before = loadavg()
        r = self.run(cmd, out, threads, a.run_timeout)
        r["cpu_ms_per_step"] = 1000.0 * (r["cpu"] - self.setup_cpu[key]) / (r["steps"] - 1)
        r.update({"kind": kind, "geometry": a.geometry, "n": n, "ntri": ntri, "phase": phase,
                  "threads": threads, "skin": skin,
                  "ranks": ranks, "rep": rep, "load_before": before, "load_after": loadavg(),
                  "command": ("OMP_NUM_THREADS=%d " % threads) + shlex.join(cmd),
                  "ms_per_step": 1000.0 * r["loop"] / r["steps"], "label": a.label,
                  "time": time.strftime("%Y-%m-%d %H:%M:%S")})
        if kind == "rocks":
            r["counters"] = read_counters(os.path.join(out, "counters.txt"))
        self.results.append(r)
        json.dump(self.results, open(self.results_path, "w"), indent=1)
        return r

    def go(self):
        a = self.a
        m = machine()
        print(f"machine: {m['host']}, {m['cpu']}, {m['cores']} cores; {m['compiler']}; {m['mpirun']}")
        print(f"liggghts-tri: {a.tri}\nliggghts: {a.liggghts}\nlabel: {a.label}, load {loadavg()}")
        configs = [(t, r) for t in a.threads for r in a.ranks if t == 1 or r == 1]
        for n in a.n:
            for ntri in a.ntri:
                for kind in ("spheres", "rocks"):
                    if any(p != "free" for p in a.phases):
                        self.restarts(kind, n, ntri)
                for phase in a.phases:
                    for threads, ranks in configs:
                        for rep, skin in itertools.product(range(a.repeat), a.skins):
                            s = (self.measure("spheres", n, ntri, phase, 1, ranks, rep, skin)
                                 if threads == 1 else None)
                            r = self.measure("rocks", n, ntri, phase, threads, ranks, rep, skin)
                            c = r["counters"]
                            ratio = f"{r['ms_per_step'] / s['ms_per_step']:7.1f}x" if s else "      -"
                            sph = f"{s['ms_per_step']:8.3f}" if s else "       -"
                            cpu = (f" (CPU {s['cpu_ms_per_step']:.3f} / {r['cpu_ms_per_step']:.3f} ms "
                                   f"{r['cpu_ms_per_step'] / max(s['cpu_ms_per_step'], 1e-9):.1f}x)"
                                   if s else f" (CPU {r['cpu_ms_per_step']:.3f} ms)")
                            print(f"{a.geometry} n={n:2d} ntri={ntri} {phase:8s} {threads}x{ranks} "
                                  f"skin {skin:g} mm rep {rep}: "
                                  f"spheres {sph} ms, rocks {r['ms_per_step']:8.3f} ms {ratio}{cpu} | "
                                  f"checked {c['pairs_checked']:.0f} in contact "
                                  f"{c['pairs_in_contact']:.0f} tested {c['triangle_pairs_tested']:.0f} "
                                  f"within {c['triangle_contacts']:.0f} fallbacks {c['fallbacks']:.0f}"
                                  f" | load {r['load_after'][0]:.1f}", flush=True)
        print(f"results: {self.results_path}")


# ---------------------------------------------------------------------------------------------
# Summary table and figure


def summarise(results):
    """(label, geometry, n, ntri, phase, threads, ranks) -> each side at its best skin (the
    lowest best-of-repetitions ms/step over the skins; results without a skin ran at 1 mm):
    their ms/step per repetition, the per-repetition ratios rocks / spheres at those skins,
    the CPU figures likewise, the rocks' counters, and per skin the best of each side."""
    by_rep = {}
    for r in results:
        key = (r["label"], r.get("geometry", "pile"), r["n"], r["ntri"], r["phase"], r["threads"],
               r["ranks"], r.get("skin", 1.0), r["rep"])
        by_rep.setdefault(key, {})[r["kind"]] = r
    per_skin = {}  # config -> skin -> rep -> kinds
    for key, kinds in by_rep.items():
        if "rocks" in kinds:
            per_skin.setdefault(key[:7], {}).setdefault(key[7], {})[key[8]] = kinds

    def best_skin(skins, kind):
        times = {k: min(v[kind]["ms_per_step"] for v in reps.values() if kind in v)
                 for k, reps in skins.items() if any(kind in v for v in reps.values())}
        return min(times, key=times.get) if times else None

    rows = {}
    for k, skins in per_skin.items():
        bs, br = best_skin(skins, "spheres"), best_skin(skins, "rocks")
        e = {"rocks": [], "spheres": [], "ratios": [], "loads": [], "cpu_ratios": [],
             "rocks_cpu": [], "spheres_cpu": [], "best_skins": (bs, br),
             "skins": {sk: {kind: min((v[kind]["ms_per_step"] for v in reps.values() if kind in v),
                                      default=None) for kind in ("spheres", "rocks")}
                       for sk, reps in sorted(skins.items())}}
        for rep, kinds in sorted(skins[br].items()):
            rock = kinds["rocks"]
            e["rocks"].append(rock["ms_per_step"])
            e["counters"] = rock["counters"]
            e["loads"] += [rock["load_before"][0], rock["load_after"][0]]
            if "cpu_ms_per_step" in rock:
                e["rocks_cpu"].append(rock["cpu_ms_per_step"])
            sphere = skins.get(bs, {}).get(rep, {}).get("spheres") if bs is not None else None
            if sphere:
                e["spheres"].append(sphere["ms_per_step"])
                e["ratios"].append(rock["ms_per_step"] / sphere["ms_per_step"])
                if ("cpu_ms_per_step" in rock and "cpu_ms_per_step" in sphere and
                        valtools.cpu_measurable(rock) and valtools.cpu_measurable(sphere)):
                    e["spheres_cpu"].append(sphere["cpu_ms_per_step"])
                    e["cpu_ratios"].append(rock["cpu_ms_per_step"] /
                                           max(sphere["cpu_ms_per_step"], 1e-9))
        rows[k] = e
    # Threads and ranks: each repetition's speed-up over the 1x1 run of the same repetition at
    # the same skin (run just before it: a paired ratio, less exposed to the host's load than
    # best against best), at this configuration's best skin.
    for k, e in rows.items():
        if (k[5], k[6]) == (1, 1):
            continue
        br = e["best_skins"][1]
        for rep, kinds in per_skin[k][br].items():
            one = per_skin.get(k[:5] + (1, 1), {}).get(br, {}).get(rep, {}).get("rocks")
            if one:
                e.setdefault("speedups", []).append(one["ms_per_step"] / kinds["rocks"]["ms_per_step"])
    return rows


def pyplot():
    """Debian's matplotlib, drawing to files (imported only when a plot is asked for)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def plot_setup(doc, select, empty):
    """The plotting scripts' start: their command line (RESULTS.json [...] --png PNG [--title
    TITLE]), the results of every file, in order, passed through select(results) -> lines (the
    script ends with `empty` when there are none), and pyplot. Returns (args, lines, plt)."""
    ap = argparse.ArgumentParser(description=doc.splitlines()[0])
    ap.add_argument("results", nargs="+")
    ap.add_argument("--png", required=True)
    ap.add_argument("--title", default="")
    a = ap.parse_args()
    results = []
    for path in a.results:
        with open(path) as f:
            results += json.load(f)
    lines = select(results)
    if not lines:
        sys.exit(empty)
    return a, lines, pyplot()


def median(v):
    v = sorted(v)
    return v[len(v) // 2] if len(v) % 2 else 0.5 * (v[len(v) // 2 - 1] + v[len(v) // 2])


def labels_in_order(results):
    """The results' labels, in the order they first appear (the order they were given)."""
    return list(dict.fromkeys(r["label"] for r in results))


def table(results):
    rows = summarise(results)
    print("| build | deck | rocks | phase | threads x ranks | best skin spheres / rocks (mm) | "
          "spheres ms/step | rocks ms/step | ratio best / best (median of pairs) | CPU ratio (median) | "
          "pairs checked | in contact | triangle pairs tested | within layer | tested/within | "
          "fallbacks | load | speed-up over 1x1 (median) |")
    print("|---|---|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|")
    order = {"free": 0, "forming": 1, "settled": 2, "formed": 3, "gas": 4}
    labels = labels_in_order(results)
    keys = sorted(rows, key=lambda k: (labels.index(k[0]), k[1], k[2], k[3], order.get(k[4], 9),
                                       k[5], k[6]))
    for k in keys:
        e = rows[k]
        c = e["counters"]
        bs, br = e["best_skins"]
        sph = f"{min(e['spheres']):.3f}" if e["spheres"] else "–"
        ratio = (f"{min(e['rocks']) / min(e['spheres']):.1f}x ({median(e['ratios']):.1f}x)"
                 if e["ratios"] else "–")
        cpu_ratio = f"{median(e['cpu_ratios']):.1f}x" if e["cpu_ratios"] else "–"
        tw = (f"{c['triangle_pairs_tested'] / c['triangle_contacts']:.1f}"
              if c["triangle_contacts"] else "–")
        skins = f"{bs:g} / {br:g}" if bs is not None else f"– / {br:g}"
        print(f"| {k[0]} | {k[1]} | {k[2]**3} x {k[3]} | {k[4]} | {k[5]}x{k[6]} | {skins} | {sph} | "
              f"{min(e['rocks']):.3f} | {ratio} | {cpu_ratio} | {c['pairs_checked']:.0f} | "
              f"{c['pairs_in_contact']:.0f} | {c['triangle_pairs_tested']:.0f} | "
              f"{c['triangle_contacts']:.0f} | {tw} | {c['fallbacks']:.0f} | "
              f"{min(e['loads']):.1f}-{max(e['loads']):.1f} | "
              + (f"{median(e['speedups']):.2f}x ({', '.join(f'{v:.2f}' for v in e['speedups'])}) |"
                 if e.get("speedups") else "– |"))
    if not any(len(rows[k]["skins"]) > 1 for k in keys):
        return
    print("\nPer skin (best of the repetitions, ms/step; * = the side's best skin):\n")
    print("| build | deck | rocks | phase | threads x ranks | skin (mm) | spheres | rocks | ratio |")
    print("|---|---|---|---|---|---:|---:|---:|---:|")
    for k in keys:
        e = rows[k]
        bs, br = e["best_skins"]
        for sk, t in e["skins"].items():
            sph, rock = t["spheres"], t["rocks"]
            print(f"| {k[0]} | {k[1]} | {k[2]**3} x {k[3]} | {k[4]} | {k[5]}x{k[6]} | {sk:g} | "
                  + (f"{sph:.4f}{' *' if sk == bs else ''}" if sph is not None else "–") + " | "
                  + (f"{rock:.3f}{' *' if sk == br else ''}" if rock is not None else "–") + " | "
                  + (f"{rock / sph:.1f}x |" if sph and rock else "– |"))


def plot(results, path):
    plt = pyplot()
    rows = summarise(results)
    labels = [l for l in labels_in_order(results) if any(k[0] == l for k in rows)]
    phases = ["free", "forming", "settled", "gas"]  # gas: --geometry gas

    def geometry(phase):
        return "gas" if phase == "gas" else "pile"

    fig, axes = plt.subplots(1, 2, figsize=(12, 4.2))
    width = 0.8 / max(1, 2 * len(labels))
    keys = [(ntri, p) for ntri in (20, 40) for p in phases]
    for li, label in enumerate(labels):
        for ti, ntri in enumerate((20, 40)):
            vals = []
            for p in phases:
                e = next((rows[k] for k in rows if k[0] == label and k[1] == geometry(p)
                          and k[3] == ntri and k[4] == p and k[5] == 1 and k[6] == 1), None)
                vals.append(median(e["ratios"]) if e and e["ratios"] else 0.0)
            xs = [i + (2 * li + ti) * width for i in range(len(phases))]
            axes[0].bar(xs, vals, width, label=f"{label}, {ntri} triangles")
    axes[0].set_xticks([i + 0.4 - width / 2 for i in range(len(phases))])
    axes[0].set_xticklabels(phases)
    axes[0].set_yscale("log")
    axes[0].set_ylabel("rocks / spheres of equal mass (time per step)")
    axes[0].axhline(RATIO_FLOORS["pile", "settled"], color="k", ls="--", lw=0.8)
    axes[0].axhline(3, color="k", ls=":", lw=0.8)
    axes[0].text(2.6, RATIO_FLOORS["pile", "settled"] * 1.05,
                 f"settled floor {RATIO_FLOORS['pile', 'settled']:g}x", fontsize=8, ha="right")
    axes[0].text(0.9, 3.2, "free-flight floor 3x", fontsize=8, ha="right")
    axes[0].legend(fontsize=8)
    axes[0].set_title("1 thread, 1 rank")
    for li, label in enumerate(labels):
        for ti, ntri in enumerate((20, 40)):
            vals = []
            for p in phases:
                e = next((rows[k] for k in rows if k[0] == label and k[1] == geometry(p)
                          and k[3] == ntri and k[4] == p and k[5] == 1 and k[6] == 1), None)
                c = e["counters"] if e else None
                vals.append(c["triangle_pairs_tested"] / c["triangle_contacts"]
                            if c and c["triangle_contacts"] else 0.0)
            xs = [i + (2 * li + ti) * width for i in range(len(phases))]
            axes[1].bar(xs, vals, width, label=f"{label}, {ntri} triangles")
    axes[1].set_xticks([i + 0.4 - width / 2 for i in range(len(phases))])
    axes[1].set_xticklabels(phases)
    axes[1].set_ylabel("triangle pairs tested / within the layers")
    axes[1].legend(fontsize=8)
    axes[1].set_title("distance-kernel work per contact")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    print(f"wrote {path}")


# The floors the benchmark is held to: ratio to spheres (each side at its best skin) at 1 thread
# and 1 rank, speed-up over 1x1.
RATIO_FLOORS = {("hopper", "formed"): 15.0, ("pile", "settled"): 25.0, ("pile", "free"): 3.0,
                ("gas", "gas"): 15.0}
SPEEDUP_FLOORS = {"threads": 1.8, "ranks": 1.7}


def plot_floors(results, path):
    """Every repetition against the floors: each run's ratios to spheres (1x1) per deck and
    phase, and the speed-ups of threads and ranks over the 1x1 run of the same repetition."""
    plt = pyplot()
    rows = summarise(results)
    labels = labels_in_order(results)
    cases = sorted({(k[1], k[3], k[4]) for k in rows if k[5] == 1 and k[6] == 1 and rows[k]["ratios"]},
                   key=lambda c: (c[0] != "hopper", c[2], c[1]))
    par = sorted({(k[1], k[3], k[4], k[5], k[6]) for k in rows if rows[k].get("speedups")})
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.4), gridspec_kw={"width_ratios": [max(1, len(cases)), max(1, len(par))]})
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]

    named = set()  # (axes, label) pairs already in a legend

    def dots(ax, x, values, li):
        n = len(values)
        xs = [x + (li - (len(labels) - 1) / 2) * 0.18 + (j - (n - 1) / 2) * 0.03 for j in range(n)]
        first = (id(ax), li) not in named
        named.add((id(ax), li))
        ax.plot(xs, values, "o", ms=4, color=colours[li % len(colours)],
                label=labels[li] if first else None)
        ax.plot([min(xs) - 0.03, max(xs) + 0.03], [median(values)] * 2, "-", lw=2,
                color=colours[li % len(colours)])

    for ci, (geometry, ntri, phase) in enumerate(cases):
        for li, label in enumerate(labels):
            e = next((rows[k] for k in rows if k[0] == label and k[1] == geometry and
                      k[3:] == (ntri, phase, 1, 1)), None)
            if e and e["ratios"]:
                dots(axes[0], ci, e["ratios"], li)
        floor = RATIO_FLOORS.get((geometry, phase))
        if floor:
            axes[0].plot([ci - 0.45, ci + 0.45], [floor] * 2, "k--", lw=1)
            axes[0].text(ci + 0.45, floor * 1.04, f"floor {floor:g}x", fontsize=8, ha="right")
    axes[0].set_xticks(range(len(cases)))
    axes[0].set_xticklabels([f"{g} x {t}\n{p}" for g, t, p in cases], fontsize=8)
    axes[0].set_yscale("log")
    axes[0].set_ylabel("rocks / spheres of equal mass (time per step)")
    axes[0].set_title("1 thread, 1 rank: each repetition (bar: median)")
    axes[0].legend(fontsize=8)
    for pi, (geometry, ntri, phase, threads, ranks) in enumerate(par):
        for li, label in enumerate(labels):
            e = next((rows[k] for k in rows if k[0] == label and k[1] == geometry and
                      k[3:] == (ntri, phase, threads, ranks)), None)
            if e and e.get("speedups"):
                dots(axes[1], pi, e["speedups"], li)
        floor = SPEEDUP_FLOORS["threads" if threads > 1 else "ranks"]
        axes[1].plot([pi - 0.45, pi + 0.45], [floor] * 2, "k--", lw=1)
        axes[1].text(pi + 0.45, floor + 0.02, f"floor {floor:g}x", fontsize=8, ha="right")
        axes[1].plot([pi - 0.45, pi + 0.45], [max(threads, ranks)] * 2, "k:", lw=0.8)
    axes[1].set_xticks(range(len(par)))
    axes[1].set_xticklabels([f"{g} x {t} {p}\n{th} threads x {r} ranks" for g, t, p, th, r in par],
                            fontsize=8)
    axes[1].set_ylabel("speed-up over 1 thread, 1 rank (same repetition)")
    axes[1].set_title("threads and ranks (dotted: ideal)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    print(f"wrote {path}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tri", default=os.environ.get(
        "LIGGGHTS_TRI", os.path.join(REPO, "build", "src_plugin", "driver", "liggghts-tri")))
    ap.add_argument("--liggghts", default="/usr/bin/liggghts")
    ap.add_argument("--work", default="/tmp/pile_bench")
    ap.add_argument("--label", action="append",
                    help="name of this build's results (default speed); with --table or --plot "
                         "also NAME=LABEL or NAME=FILE.json, to show other results as NAME, or "
                         "FILE.json, to show its results under their own labels")
    ap.add_argument("--geometry", choices=["pile", "hopper", "gas"], default="pile",
                    help="pile: in.pile (phases free forming settled); hopper: the paper's hopper, "
                         "in.hopper_phase (phases free formed: from t = 0.2 s); gas: in.gas, a "
                         "granular gas in a periodic box (phase gas: from t = 0.03 s)")
    ap.add_argument("--n", type=int, nargs="+")
    ap.add_argument("--ntri", type=int, nargs="+", default=[20, 40])
    ap.add_argument("--phases", nargs="+")
    ap.add_argument("--steps", type=int, default=300, help="steps of a measured phase")
    ap.add_argument("--sphere-factor", type=int, default=5,
                    help="the spheres run this many times more steps (ms per step is compared)")
    ap.add_argument("--free-steps", type=int, default=3000,
                    help="steps of the free phase (the pile: without gravity, so it stays free)")
    ap.add_argument("--repeat", type=int, default=2)
    ap.add_argument("--skins", type=float, nargs="+", default=SKINS,
                    help="neighbour skins, mm: each side runs at each, the tables compare each "
                         "side at its fastest (the ratio best / best)")
    ap.add_argument("--threads", type=int, nargs="+", default=[1])
    ap.add_argument("--ranks", type=int, nargs="+", default=[1])
    ap.add_argument("--prepare", action="store_true", help="write the restart files again")
    ap.add_argument("--run-timeout", type=float, default=900)
    ap.add_argument("--settle-timeout", type=float, default=7200)
    ap.add_argument("--table", action="store_true", help="print the table of the labels' results")
    ap.add_argument("--plot", metavar="PNG", help="draw the labels' results")
    ap.add_argument("--floors", metavar="PNG",
                    help="draw every repetition of the labels against the issue's floors")
    a = ap.parse_args()
    labels = a.label or ["speed"]
    if a.table or a.plot or a.floors:
        results = []
        for label in labels:
            # NAME=SOURCE: the results of label SOURCE (or of the file SOURCE.json) shown as
            # NAME; several sources with one NAME are merged (a gas run beside a pile run).
            # A FILE.json alone: its results under their own labels.
            name, _, source = label.partition("=")
            if not source and name.endswith(".json"):
                results += json.load(open(name))
                continue
            path = source if source.endswith(".json") else os.path.join(
                a.work, f"results_{source or name}.json")
            for r in json.load(open(path)):
                r["label"] = name
                results.append(r)
        if a.table:
            table(results)
        if a.plot:
            plot(results, a.plot)
        if a.floors:
            plot_floors(results, a.floors)
        return
    a.label = labels[0]
    a.n = a.n or ([10] if a.geometry == "hopper" else [8])
    a.phases = a.phases or {"pile": ["free", "forming", "settled"], "hopper": ["free", "formed"],
                            "gas": ["gas"]}[a.geometry]
    Bench(a).go()
    table(Bench(a).results)


if __name__ == "__main__":
    main()
