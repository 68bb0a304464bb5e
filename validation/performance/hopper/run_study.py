#!/usr/bin/env python3
"""Hopper performance study (issue 5, items 3 and 4): runs examples/hopper with liggghts-tri and
its sphere twin with plain liggghts, and tabulates

  * time per step (total, pair, tri/wall, neighbour, communication, other) of spheres, 20- and
    40-triangle rocks, all runs of equal simulated time (0 .. tend, discharge dominating), as
    ratios to the sphere twin;
  * the distance kernels (bf, penalty, hybrid, batched) and box culling (yes/no), 40 triangles;
  * OpenMP threads inside the collision checks (`parallel pairs`, `parallel triangles`), the
    paper's Fig. 3, and threads x MPI ranks (1x1, 1x2, 2x1), the paper's Fig. 4;
  * memory per particle against spheres: LIGGGHTS's "Memory usage per processor" at two lattice
    sizes, and the analytic count of the per-particle arrays, against the paper's ~9 Tmax doubles.

It prints machine, compiler, thread and rank counts, the load average before and after every
run and the exact commands; writes the raw outputs under --out (default /tmp/hopper_study, never
in the repository), results.json, tables.md, and the figures (--figures, default this folder).

  /usr/bin/python3 validation/performance/hopper/run_study.py [--n 7] [--tend 0.4] \
      [--n-cull 5] [--tend-cull 0.2] [--groups main,kernels,cull,threads,memory] \
      [--tri build-perf/src_plugin/driver/liggghts-tri] [--out /tmp/hopper_study]
  /usr/bin/python3 validation/performance/hopper/run_study.py --replot   # figures from results.json

Standard library only, plus Debian's matplotlib for the figures.
"""
import argparse
import json
import os
import re
import shlex
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
HOPPER = os.path.join(REPO, "examples", "hopper")
DT = 2e-5  # the decks' time step

sys.path.insert(0, os.path.join(REPO, "validation"))
import valtools  # noqa: E402


def sh(cmd):
    try:
        return subprocess.run(cmd, shell=True, capture_output=True, text=True).stdout.strip()
    except OSError:
        return ""


def loadavg():
    with open("/proc/loadavg") as f:
        return [float(v) for v in f.read().split()[:3]]


def machine():
    model = ""
    for line in sh("lscpu").splitlines():
        if line.startswith("Model name:"):
            model = line.split(":", 1)[1].strip()
    flags = sh("grep -m1 '^flags' /proc/cpuinfo")
    return {
        "cpu": model,
        "cores": os.cpu_count(),
        "avx512": "avx512f" in flags,
        "compiler": sh("g++ --version").splitlines()[0] if sh("g++ --version") else "?",
        "mpirun": (sh("mpirun --version").splitlines() or ["?"])[0],
        "liggghts": "Debian liggghts 3.8 (libliggghts.so.3)",
        "kernel": sh("uname -r"),
    }


# ---------------------------------------------------------------------------------------------
# Parsing LIGGGHTS output


def parse_output(text):
    r = {}
    m = re.search(r"Loop time of ([\d.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms", text)
    if m:
        r["loop"], r["procs"], r["steps"], r["atoms"] = float(m[1]), int(m[2]), int(m[3]), int(m[4])
    for key, name in (("Pair", "pair"), ("Neigh", "neigh"), ("Comm", "comm"), ("Outpt", "output"),
                      ("Other", "other")):
        m = re.search(key + r"\s+time \(%\) = ([\d.eE+-]+)", text)
        if m:
            r[name] = float(m[1])
    m = re.search(r"hopper timing: fix tri/wall ([\d.eE+-]+) s", text)
    r["wall"] = float(m[1]) if m else None
    m = re.search(r"Memory usage per processor = ([\d.eE+-]+) Mbytes", text)
    r["memory_mb"] = float(m[1]) if m else None
    m = re.search(r"^hopper summary: .*$", text, re.M)
    r["summary"] = m[0] if m else None
    m = re.search(r"(\d+) discharged", text)
    r["discharged"] = int(m[1]) if m else None
    # thermo: atoms column must stay at the initial count; no nan/inf anywhere in the output
    thermo_atoms = []
    in_thermo = False
    for line in text.splitlines():
        if line.strip().startswith("Step"):
            in_thermo = True
            continue
        if in_thermo:
            parts = line.split()
            if len(parts) >= 3 and parts[0].isdigit():
                thermo_atoms.append(int(parts[2]))
            else:
                in_thermo = False
    r["thermo_atoms"] = sorted(set(thermo_atoms))
    r["nan"] = bool(re.search(r"\b(nan|-nan|inf)\b", text, re.I))
    r["lost"] = bool(re.search(r"Lost atoms", text))
    r["error"] = bool(re.search(r"^ERROR", text, re.M))
    return r


# ---------------------------------------------------------------------------------------------
# Runs


class Runner:
    def __init__(self, args):
        self.args = args
        self.results = {}
        os.makedirs(args.out, exist_ok=True)

    def command(self, spec):
        a = self.args
        out = os.path.join(a.out, spec["name"])
        os.makedirs(out, exist_ok=True)
        ranks = spec.get("ranks", 1)
        if spec["kind"] == "spheres":
            exe, deck = a.liggghts, os.path.join(HOPPER, "in.hopper_spheres")
        else:
            exe, deck = a.tri, os.path.join(HOPPER, "in.hopper")
        var = {"dir": HOPPER, "n": spec["n"], "ntri": spec["ntri"], "tend": spec["tend"],
               "out": out}
        if spec["kind"] == "tri":
            var.update(kernel=spec.get("kernel", "hybrid"), parallel=spec.get("parallel", "pairs"),
                       cull=spec.get("cull", "yes"), vtk=0)
        if ranks > 1:
            var["px"] = ranks
        cmd = []
        if ranks > 1 or spec.get("mpirun"):
            cmd = ["mpirun", "-np", str(ranks)]
            if ranks * spec.get("threads", 1) > (os.cpu_count() or 1):
                cmd.append("--oversubscribe")
            cmd += ["-x", "OMP_NUM_THREADS"]
        cmd += valtools.deck_command(exe, deck, var, log=os.path.join(out, "log.liggghts"))
        return cmd, out

    def run(self, spec):
        name = spec["name"]
        if name in self.results:
            return self.results[name]
        cmd, out = self.command(spec)
        threads = spec.get("threads", 1)
        env = valtools.run_env(threads)
        env_str = f"OMP_NUM_THREADS={threads} "
        printable = env_str + " ".join(shlex.quote(c) for c in cmd)
        load0 = loadavg()
        t0 = time.time()
        with open(os.path.join(out, "stdout"), "w") as f:
            p = subprocess.Popen(cmd, stdout=f, stderr=subprocess.STDOUT, env=env, cwd=out,
                                 start_new_session=True)
            timed_out = False
            while True:
                pid, status, ru = os.wait4(p.pid, os.WNOHANG)
                if pid:
                    break
                if time.time() - t0 > self.args.run_timeout and not timed_out:
                    timed_out = True  # stop this run (its own process group) and go on
                    os.killpg(p.pid, 15)
                time.sleep(0.2)
        wall = time.time() - t0
        load1 = loadavg()
        with open(os.path.join(out, "stdout")) as f:
            text = f.read()
        r = parse_output(text)
        r.update(spec)
        r.update(command=printable, rc=os.waitstatus_to_exitcode(status), wallclock=wall,
                 timed_out=timed_out,
                 cpu=ru.ru_utime + ru.ru_stime, load_before=load0, load_after=load1,
                 discharge=valtools.read_discharge(os.path.join(out, "discharge.txt"),
                                                   missing_ok=True))
        ok = (r["rc"] == 0 and not r["nan"] and not r["lost"] and not r["error"]
              and r.get("atoms") == spec["n"] ** 3 and r["thermo_atoms"] == [spec["n"] ** 3])
        r["ok"] = ok
        if timed_out:
            reached = r["discharge"][-1][0] if r["discharge"] else 0.0
            r["reached"] = reached
            print(f"[{name}] stopped after {wall:.0f} s (--run-timeout) at t = {reached} s of "
                  f"{spec['tend']} s: {printable}", flush=True)
            self.save()
            return r
        self.results[name] = r
        steps = r.get("steps") or 1
        print(f"[{name}] {printable}", flush=True)
        print(f"    loop {r.get('loop', float('nan')):.3f} s ({1e3 * r.get('loop', 0) / steps:.3f} "
              f"ms/step), pair {r.get('pair', 0):.3f} s, wall {r['wall'] or 0:.3f} s, cpu "
              f"{r['cpu']:.1f} s, load {load0[0]:.2f} -> {load1[0]:.2f}, "
              f"{'ok' if ok else 'CHECK FAILED'}; {r['summary']}", flush=True)
        self.save()
        return r

    def save(self):
        with open(os.path.join(self.args.out, "results.json"), "w") as f:
            json.dump({"machine": self.machine, "args": vars(self.args), "runs": self.results,
                       "load_start": self.load_start, "load_end": loadavg(),
                       "waited_s": self.waited}, f, indent=1)


def wait_for_quiet(threshold, max_wait):
    """Waits (up to max_wait s) for the 1-minute load average to fall below threshold."""
    t0 = time.time()
    while True:
        load = loadavg()
        if load[0] < threshold or time.time() - t0 >= max_wait:
            return load, time.time() - t0
        print(f"  load {load[0]:.2f} >= {threshold}: waiting for a quieter moment "
              f"({time.time() - t0:.0f} s of {max_wait} s)", flush=True)
        time.sleep(30)


# ---------------------------------------------------------------------------------------------
# The study


def specs(a):
    n, tend, nc, tc = a.n, a.tend, a.n_cull, a.tend_cull
    g = {}
    g["main"] = [
        dict(name="spheres20", kind="spheres", n=n, ntri=20, tend=tend),
        dict(name="spheres40", kind="spheres", n=n, ntri=40, tend=tend),
        dict(name="tri20", kind="tri", n=n, ntri=20, tend=tend),
        dict(name="tri40", kind="tri", n=n, ntri=40, tend=tend),
    ]
    g["kernels"] = [dict(name=f"tri40_{k}", kind="tri", n=n, ntri=40, tend=tend, kernel=k)
                    for k in ("bf", "penalty", "batched")]
    g["cull"] = [dict(name=f"cull{c}_{k}", kind="tri", n=nc, ntri=40, tend=tc, kernel=k, cull=c)
                 for c in ("yes", "no") for k in ("bf", "penalty", "hybrid", "batched")]
    g["threads"] = [
        dict(name="tri40_pairs_t2", kind="tri", n=n, ntri=40, tend=tend, threads=2),
        dict(name="tri40_triangles_t1", kind="tri", n=n, ntri=40, tend=tend, parallel="triangles"),
        dict(name="tri40_triangles_t2", kind="tri", n=n, ntri=40, tend=tend, parallel="triangles",
             threads=2),
        dict(name="tri40_r2", kind="tri", n=n, ntri=40, tend=tend, ranks=2),
        dict(name="spheres40_r2", kind="spheres", n=n, ntri=40, tend=tend, ranks=2),
    ]
    g["threads_small"] = [
        dict(name="small_pairs_t2", kind="tri", n=nc, ntri=40, tend=tc, threads=2),
        dict(name="small_triangles_t1", kind="tri", n=nc, ntri=40, tend=tc, parallel="triangles"),
        dict(name="small_triangles_t2", kind="tri", n=nc, ntri=40, tend=tc, parallel="triangles",
             threads=2),
        dict(name="small_r2", kind="tri", n=nc, ntri=40, tend=tc, ranks=2),
    ]
    tiny = 10 * DT  # 10 steps: setup (where LIGGGHTS prints its memory) and a few steps
    g["memory"] = [dict(name=f"mem_{kind}{t}_n{m}", kind=kind, n=m, ntri=t, tend=tiny)
                   for m in (a.mem_n[0], a.mem_n[1]) for kind, t in
                   (("spheres", 40), ("tri", 20), ("tri", 40))]
    return g


def thread_sets():
    """(label, [(parallel mode, threads, ranks, run, reference run)]) for the two sizes."""
    return [
        ("the main size", [("pairs", 1, 1, "tri40", "tri40"),
                           ("pairs", 2, 1, "tri40_pairs_t2", "tri40"),
                           ("triangles", 1, 1, "tri40_triangles_t1", "tri40_triangles_t1"),
                           ("triangles", 2, 1, "tri40_triangles_t2", "tri40_triangles_t1"),
                           ("pairs", 1, 2, "tri40_r2", "tri40")]),
        ("the small size", [("pairs", 1, 1, "cullyes_hybrid", "cullyes_hybrid"),
                            ("pairs", 2, 1, "small_pairs_t2", "cullyes_hybrid"),
                            ("triangles", 1, 1, "small_triangles_t1", "small_triangles_t1"),
                            ("triangles", 2, 1, "small_triangles_t2", "small_triangles_t1"),
                            ("pairs", 1, 2, "small_r2", "cullyes_hybrid")]),
    ]


def per_step(r):
    s = r["steps"]
    wall = r["wall"] or 0.0
    return {"total": r["loop"] / s, "pair": r["pair"] / s, "wall": wall / s,
            "neigh": r["neigh"] / s, "comm": r["comm"] / s,
            "other": (r["other"] - wall) / s, "other_all": r["other"] / s}


def fmt_ms(x):
    return f"{1e3 * x:.3f}"


def tables(data):
    runs, M = data["runs"], data["machine"]
    out = []
    p = out.append
    p(f"Machine: {M['cpu']}, {M['cores']} cores{' (AVX-512)' if M['avx512'] else ''}; "
      f"{M['compiler']}; {M['mpirun']}; {M['liggghts']}.")
    p(f"Load average (1, 5, 15 min) at start {data['load_start']}, at end {data['load_end']}"
      f" (waited {data['waited_s']:.0f} s for a quieter moment).")
    p("")
    if "tri40" in runs and "spheres40" in runs:
        base = runs["spheres40"]
        p(f"### Time per step, lattice n = {base['n']} ({base['n'] ** 3} particles), "
          f"0 .. {base['tend']} s simulated ({base['steps']} steps) in every run, 1 thread, 1 rank")
        p("")
        p("ms per step (whole run; the discharge starts at ~0.11 s and carries nearly all of the "
          "rocks' cost); ratio to the sphere twin of the same volume in brackets")
        p("")
        p("| run | total | pair | neighbour | comm | other incl. walls | of which tri/wall "
          "| discharged | process CPU s | load before/after |")
        p("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
        for name, twin in (("spheres20", None), ("spheres40", None), ("tri20", "spheres20"),
                           ("tri40", "spheres40")):
            if name not in runs:
                continue
            r = runs[name]
            ps = per_step(r)
            b = per_step(runs[twin]) if twin else None
            cells = []
            for k in ("total", "pair", "neigh", "comm", "other_all", "wall"):
                c = "–" if (k == "wall" and r["kind"] == "spheres") else fmt_ms(ps[k])
                if b and b[k] > 0 and k != "wall":
                    c += f" ({ps[k] / b[k]:.1f}x)"
                cells.append(c)
            label = {"spheres20": "spheres (20-tri volume)", "spheres40": "spheres (40-tri volume)",
                     "tri20": "rocks, 20 triangles", "tri40": "rocks, 40 triangles"}[name]
            p(f"| {label} | " + " | ".join(cells) +
              f" | {r['discharged']}/{r['atoms']} | {r['cpu']:.1f} | "
              f"{r['load_before'][0]:.1f}/{r['load_after'][0]:.1f} |")
        p("")
    kern = [("hybrid", "tri40")] + [(k, f"tri40_{k}") for k in ("bf", "penalty", "batched")]
    if all(n in runs for _, n in kern):
        r0 = runs["tri40"]
        p(f"### Distance kernels, 40 triangles, n = {r0['n']}, 0 .. {r0['tend']} s, culling on, "
          "1 thread")
        p("")
        p("| kernel | ms/step total | pair | tri/wall | pair vs hybrid | process CPU s | loop s "
          "| discharged |")
        p("|---|---:|---:|---:|---:|---:|---:|---:|")
        h = per_step(r0)
        for k, n in kern:
            ps = per_step(runs[n])
            p(f"| {k} | {fmt_ms(ps['total'])} | {fmt_ms(ps['pair'])} | {fmt_ms(ps['wall'])} | "
              f"{ps['pair'] / h['pair']:.2f} | {runs[n]['cpu']:.1f} | {runs[n]['loop']:.1f} | "
              f"{runs[n]['discharged']}/{runs[n]['atoms']} |")
        p("")
    cull = [n for n in runs if n.startswith("cull")]
    if cull:
        r0 = runs[cull[0]]
        p(f"### Culling, 40 triangles, n = {r0['n']} ({r0['n'] ** 3} particles), "
          f"0 .. {r0['tend']} s, 1 thread")
        p("")
        p("| kernel | pair ms/step, cull yes | cull no | no/yes | tri/wall ms/step, yes | no "
          "| process CPU s, yes | no |")
        p("|---|---:|---:|---:|---:|---:|---:|---:|")
        for k in ("bf", "penalty", "hybrid", "batched"):
            y, n = runs.get(f"cullyes_{k}"), runs.get(f"cullno_{k}")
            if not y or not n:
                continue
            a, b = per_step(y), per_step(n)
            p(f"| {k} | {fmt_ms(a['pair'])} | {fmt_ms(b['pair'])} | {b['pair'] / a['pair']:.1f}x | "
              f"{fmt_ms(a['wall'])} | {fmt_ms(b['wall'])} | {y['cpu']:.1f} | {n['cpu']:.1f} |")
        p("")
    for label, sets in thread_sets():
        have = [x for x in sets if x[3] in runs]
        if len(have) < 2:
            continue
        r0 = runs[sets[0][3]]
        p(f"### Threads and ranks, 40 triangles, n = {r0['n']} ({r0['n'] ** 3} particles), "
          f"0 .. {r0['tend']} s ({label})")
        p("")
        p("Speed-up = time of the 1-thread 1-rank run of the same `parallel` mode / time. "
          "\"collision checks\" = pair + tri/wall time.")
        p("")
        p("| parallel | threads x ranks | loop s | pair s | tri/wall s | speed-up loop | "
          "speed-up collision checks | process CPU s | load before/after |")
        p("|---|---|---:|---:|---:|---:|---:|---:|---:|")
        for mode, t, rk, n, refname in have:
            r, ref = runs[n], runs.get(refname)
            if r.get("timed_out"):
                p(f"| {mode} | {t}x{rk} | stopped after {r['wallclock']:.0f} s at t = "
                  f"{r.get('reached', 0)} s of {r['tend']} s | | | | | | "
                  f"{r['load_before'][0]:.1f}/{r['load_after'][0]:.1f} |")
                continue
            cc = r["pair"] + (r["wall"] or 0)
            cc0 = ref["pair"] + (ref["wall"] or 0) if ref and not ref.get("timed_out") else None
            sl = f"{ref['loop'] / r['loop']:.2f}" if cc0 else "–"
            sc = f"{cc0 / cc:.2f}" if cc0 else "–"
            p(f"| {mode} | {t}x{rk} | {r['loop']:.1f} | {r['pair']:.1f} | {r['wall'] or 0:.1f} | "
              f"{sl} | {sc} | {r['cpu']:.1f} | "
              f"{r['load_before'][0]:.1f}/{r['load_after'][0]:.1f} |")
        if label.startswith("n =") is False and "spheres40_r2" in runs and "spheres40" in runs \
                and sets[0][3] == "tri40":
            s1, s2 = runs["spheres40"], runs["spheres40_r2"]
            p(f"| spheres (plain liggghts) | 1x1 -> 1x2 | {s1['loop']:.2f} -> {s2['loop']:.2f} | | | "
              f"{s1['loop'] / s2['loop']:.2f} | | | |")
        p("")
    p("Under MPI the pair time is LIGGGHTS's average over ranks and tri/wall is rank 0's.")
    p("")
    mem = memory_table(data)
    if mem:
        out += mem
    return "\n".join(out)


def memory_table(data):
    runs = data["runs"]
    a = data["args"]
    lo, hi = a["mem_n"]
    out = []
    p = out.append
    rows = []
    for kind, t in (("spheres", 40), ("tri", 20), ("tri", 40)):
        r0, r1 = runs.get(f"mem_{kind}{t}_n{lo}"), runs.get(f"mem_{kind}{t}_n{hi}")
        if not r0 or not r1 or r0["memory_mb"] is None or r1["memory_mb"] is None:
            continue
        dn = hi ** 3 - lo ** 3
        per = (r1["memory_mb"] - r0["memory_mb"]) * 1024 * 1024 / dn
        rows.append((kind, t, r0["memory_mb"], r1["memory_mb"], per))
    if not rows:
        return out
    p(f"### Memory per particle (LIGGGHTS \"Memory usage per processor\", n = {lo} and {hi}: "
      f"{lo ** 3} and {hi ** 3} particles, 1 rank)")
    p("")
    p(f"| particles | MB at n = {lo} | MB at n = {hi} | measured bytes/particle | "
      "analytic bytes/particle (no contacts / 6 partners) | paper 9 T doubles |")
    p("|---|---:|---:|---:|---:|---:|")
    for kind, t, m0, m1, per in rows:
        an = analytic_bytes(kind, t)
        label = "spheres" if kind == "spheres" else f"rocks, {t} triangles"
        paper = f"{9 * t * 8}" if kind == "tri" else "–"
        p(f"| {label} | {m0:.3f} | {m1:.3f} | {per:.0f} | {an[0]} / {an[1]} | {paper} |")
    p("")
    return out


# Analytic per-particle bytes (see README.md): LIGGGHTS atom_style sphere per-atom arrays
# (x v f omega torque: 15 doubles; radius rmass density: 3; tag type mask image molecule: ints)
# plus each style's own arrays.
SPHERE_ATOM_DOUBLES = 18
SPHERE_ATOM_INTS = 5


def analytic_bytes(kind, t, partners=6):
    """(bytes with no contacts, bytes with `partners` touching neighbours and both meshes)."""
    base = SPHERE_ATOM_DOUBLES * 8 + SPHERE_ATOM_INTS * 4
    if kind == "spheres":
        # pair gran tangential history: 3 doubles per partner (stored on both atoms, newton off);
        # wall/gran mesh history: 3 doubles per touching wall triangle (assume 2)
        return base, base + (3 * partners + 3 * 2) * 8
    own = 8 + 2 * 36 + 9 * t  # tri/particles, tri/wall (36 per mesh, 2 meshes), world SoA
    return base + own * 8, base + (own + 36 * partners) * 8


# ---------------------------------------------------------------------------------------------
# Figures


def figures(data, folder):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not found: no figures (use Debian's /usr/bin/python3)")
        return []
    runs, M = data["runs"], data["machine"]
    caption = (f"{M['cpu']}, {M['cores']} cores, {M['compiler'].split(' (')[0]} "
               f"{M['compiler'].split()[-1]}; load {data['load_start'][0]:.1f} -> "
               f"{data['load_end'][0]:.1f}")
    made = []
    if all(n in runs for n in ("spheres20", "spheres40", "tri20", "tri40")):
        fig, ax = plt.subplots(figsize=(8, 4.8))
        names = ["spheres20", "spheres40", "tri20", "tri40"]
        labels = ["spheres\n(20-tri vol.)", "spheres\n(40-tri vol.)", "rocks\n20 tri", "rocks\n40 tri"]
        parts = ["pair", "wall", "neigh", "comm", "other"]
        colours = ["C0", "C1", "C2", "C3", "C7"]
        bottom = [0.0] * 4
        for part, c in zip(parts, colours):
            vals = [1e3 * per_step(runs[n])[part] for n in names]
            ax.bar(labels, vals, bottom=bottom, color=c,
                   label={"wall": "tri/wall (spheres: wall/gran is in other)"}.get(part, part))
            bottom = [b + v for b, v in zip(bottom, vals)]
        for i, n in enumerate(names):
            ratio = ""
            if n.startswith("tri"):
                twin = "spheres" + n[3:]
                ratio = f"\n{runs[n]['loop'] / runs[twin]['loop']:.0f}x spheres"
            ax.text(i, bottom[i], f"{bottom[i]:.3g} ms{ratio}", ha="center", va="bottom", fontsize=8)
        ax.set_yscale("log")
        ax.set_ylabel("ms per time step (log)")
        r = runs["tri40"]
        ax.set_title(f"Hopper, {r['n'] ** 3} particles, 0..{r['tend']} s ({r['steps']} steps), "
                     "1 thread x 1 rank", fontsize=10)
        ax.legend(fontsize=8, loc="upper left")
        fig.text(0.01, 0.01, caption, fontsize=7)
        fig.tight_layout(rect=(0, 0.03, 1, 1))
        path = os.path.join(folder, "time_per_step.png")
        fig.savefig(path, dpi=110)
        made.append(path)
    if "tri40" in runs and "tri40_pairs_t2" in runs and "tri40_r2" in runs:
        fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4.4))
        for (label, sets), marker in zip(thread_sets(), ("o", "s")):
            d = {(m, t, rk): (n, ref) for m, t, rk, n, ref in sets}
            for mode in ("pairs", "triangles"):
                n1, n2 = d[(mode, 1, 1)][0], d[(mode, 2, 1)][0]
                if n1 not in runs or n2 not in runs:
                    continue
                size = f"{runs[n1]['n'] ** 3} particles"
                if runs[n2].get("timed_out"):
                    a1.annotate(f"parallel {mode}, {size}, 2 threads:\nstopped after "
                                f"{runs[n2]['wallclock']:.0f} s at t = {runs[n2]['reached']:.2f} s "
                                f"(1 thread: {runs[n1]['loop']:.0f} s to t = {runs[n1]['tend']} s)",
                                (1.05, 0.35), fontsize=7, color="C3")
                    continue
                for part, ls in (("loop", "-"), ("cc", "--")):
                    def val(r):
                        return r["loop"] if part == "loop" else r["pair"] + (r["wall"] or 0)
                    a1.plot([1, 2], [1.0, val(runs[n1]) / val(runs[n2])], ls, marker=marker,
                            label=f"{mode}, {size}, "
                                  f"{'whole step' if part == 'loop' else 'collision checks'}")
        a1.plot([1, 2], [1, 2], ":", color="grey", label="ideal")
        a1.set_ylim(0, 2.6)
        a1.set_xticks([1, 2])
        a1.set_xlabel("OpenMP threads (1 rank)")
        a1.set_ylabel("speed-up against 1 thread, same mode")
        a1.set_title("Fig. 3 analogue: threads in the collision checks", fontsize=10)
        a1.legend(fontsize=6, loc="upper left")
        combos = [("1x1", "tri40"), ("2 threads x 1 rank", "tri40_pairs_t2"),
                  ("1 thread x 2 ranks", "tri40_r2")]
        vals = [runs[n]["loop"] for _, n in combos]
        bars = a2.bar([c for c, _ in combos], vals, color=["C7", "C0", "C1"])
        for b, v in zip(bars, vals):
            a2.text(b.get_x() + b.get_width() / 2, v, f"{v:.0f} s\n({vals[0] / v:.2f}x)",
                    ha="center", va="bottom", fontsize=8)
        a2.set_ylabel("loop time (s)")
        a2.set_ylim(0, max(vals) * 1.25)
        a2.set_title("Fig. 4 analogue: threads x MPI ranks (parallel pairs)", fontsize=10)
        r = runs["tri40"]
        fig.suptitle(f"Hopper, 40-triangle rocks, {r['n'] ** 3} particles, 0..{r['tend']} s",
                     fontsize=10)
        fig.text(0.01, 0.01, caption, fontsize=7)
        fig.tight_layout(rect=(0, 0.03, 1, 0.96))
        path = os.path.join(folder, "threads_ranks.png")
        fig.savefig(path, dpi=110)
        made.append(path)
    kern = [("hybrid", "tri40")] + [(k, f"tri40_{k}") for k in ("bf", "penalty", "batched")]
    cull = [f"cull{c}_{k}" for c in ("yes", "no") for k in ("bf", "penalty", "hybrid", "batched")]
    if all(n in runs for _, n in kern) or all(n in runs for n in cull):
        fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
        if all(n in runs for _, n in kern):
            ks = ["bf", "penalty", "hybrid", "batched"]
            d = dict(kern)
            vals = [1e3 * per_step(runs[d[k]])["pair"] for k in ks]
            wv = [1e3 * per_step(runs[d[k]])["wall"] for k in ks]
            axes[0].bar(ks, vals, label="pair")
            axes[0].bar(ks, wv, bottom=vals, label="tri/wall")
            axes[0].set_ylabel("ms per step")
            axes[0].set_title(f"kernels, cull yes, {runs['tri40']['n'] ** 3} particles", fontsize=10)
            axes[0].legend(fontsize=8)
        if all(n in runs for n in cull):
            ks = ["bf", "penalty", "hybrid", "batched"]
            x = range(len(ks))
            y = [1e3 * per_step(runs[f"cullyes_{k}"])["pair"] for k in ks]
            nn = [1e3 * per_step(runs[f"cullno_{k}"])["pair"] for k in ks]
            axes[1].bar([i - 0.2 for i in x], y, 0.4, label="cull yes")
            axes[1].bar([i + 0.2 for i in x], nn, 0.4, label="cull no")
            axes[1].set_xticks(list(x))
            axes[1].set_xticklabels(ks)
            axes[1].set_ylabel("pair ms per step")
            axes[1].set_title(f"box culling, {runs['cullyes_bf']['n'] ** 3} particles, "
                              f"0..{runs['cullyes_bf']['tend']} s", fontsize=10)
            axes[1].legend(fontsize=8)
        fig.suptitle("Hopper, 40-triangle rocks, 1 thread x 1 rank", fontsize=10)
        fig.text(0.01, 0.01, caption, fontsize=7)
        fig.tight_layout(rect=(0, 0.03, 1, 0.96))
        path = os.path.join(folder, "kernels_cull.png")
        fig.savefig(path, dpi=110)
        made.append(path)
    return made


# ---------------------------------------------------------------------------------------------


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--n", type=int, default=7, help="lattice per side for the main runs (7)")
    ap.add_argument("--tend", type=float, default=0.4, help="simulated time of the main runs (0.4 s)")
    ap.add_argument("--n-cull", type=int, default=5, help="lattice for the cull yes/no runs (5)")
    ap.add_argument("--tend-cull", type=float, default=0.2, help="simulated time, cull runs (0.2 s)")
    ap.add_argument("--mem-n", type=int, nargs=2, default=[5, 10], help="lattices for memory")
    ap.add_argument("--groups", default="main,kernels,cull,threads,threads_small,memory")
    ap.add_argument("--tri", default=os.path.join(REPO, "build-perf", "src_plugin", "driver",
                                                  "liggghts-tri"))
    ap.add_argument("--liggghts", default="/usr/bin/liggghts")
    ap.add_argument("--out", default="/tmp/hopper_study", help="raw outputs (not in the repo)")
    ap.add_argument("--figures", default=HERE)
    ap.add_argument("--quiet-load", type=float, default=2.5,
                    help="wait for the 1-min load average to fall below this (2.5)")
    ap.add_argument("--max-wait", type=float, default=600, help="longest wait for it (600 s)")
    ap.add_argument("--run-timeout", type=float, default=420,
                    help="stop a run after this many seconds and report it as too slow (420)")
    ap.add_argument("--resume", action="store_true",
                    help="keep the runs already in results.json; run only the missing ones")
    ap.add_argument("--rerun", default="", help="with --resume: runs to do again (a,b,...)")
    ap.add_argument("--replot", action="store_true", help="tables and figures from results.json")
    a = ap.parse_args()

    if a.replot:
        with open(os.path.join(a.out, "results.json")) as f:
            data = json.load(f)
        print(tables(data))
        for path in figures(data, a.figures):
            print("wrote", path)
        return

    runner = Runner(a)
    runner.machine = machine()
    previous = os.path.join(a.out, "results.json")
    if a.resume and os.path.exists(previous):
        with open(previous) as f:
            old = json.load(f)
        runner.results = {k: v for k, v in old["runs"].items() if k not in a.rerun.split(",")}
        print(f"resuming: {len(runner.results)} runs kept from {previous}")
    M = runner.machine
    print(f"machine: {M['cpu']}, {M['cores']} cores, AVX-512 {M['avx512']}, kernel {M['kernel']}")
    print(f"compiler: {M['compiler']}; {M['mpirun']}")
    print(f"liggghts-tri: {a.tri}\nliggghts: {a.liggghts}")
    print(f"threads x ranks: 1x1 unless a run says otherwise; OMP_NUM_THREADS is set per run")
    print(f"load average at start: {loadavg()}")
    load, waited = wait_for_quiet(a.quiet_load, a.max_wait)
    runner.load_start, runner.waited = load, waited
    if a.resume and os.path.exists(previous):
        runner.load_start, runner.waited = old["load_start"], old["waited_s"] + waited
    print(f"measuring with load average {load} (waited {waited:.0f} s)", flush=True)
    g = specs(a)
    t0 = time.time()
    for group in a.groups.split(","):
        print(f"== {group}", flush=True)
        for spec in g[group]:
            runner.run(spec)
    print(f"machine time of the study: {time.time() - t0:.0f} s; load average at end: {loadavg()}")
    runner.save()
    with open(os.path.join(a.out, "results.json")) as f:
        data = json.load(f)
    text = tables(data)
    print()
    print(text)
    with open(os.path.join(a.out, "tables.md"), "w") as f:
        f.write(text + "\n")
    bad = [n for n, r in data["runs"].items() if not r["ok"]]
    print("checks (rc 0, no ERROR, no lost atoms, atom count constant, no nan):",
          "all runs pass" if not bad else f"FAILED in {bad}")
    for path in figures(data, a.figures):
        print("wrote", path)


if __name__ == "__main__":
    sys.exit(main())
