#!/usr/bin/env python3
"""Speed-up of 2 OpenMP threads (and 2 MPI ranks) over one on the settled column, for one or more
builds side by side. A program, not a test.

Each round runs every build once per configuration (1 thread, 2 threads, and with --ranks 2
MPI ranks), in turn, from the settled column's restart file that run_column.py writes (its
`--work` folder; run `run_column.py --phases settled --mat stiffness` first). A run is --chunks
runs of --steps steps in one process; its time per step is the fastest chunk's. On a shared
machine, whose neighbours slow some seconds and not others, the fastest of many short chunks is
the figure least disturbed, and the builds, measured in turn within each round, see the same
machine. Printed per build: each configuration's best and median ms/step over the rounds, the
speed-up best / best and the median of the rounds' own speed-ups.

  /usr/bin/python3 validation/performance/column/run_threads.py [--rounds 6] [--steps 100]
      [--chunks 15] [--skin 0.2] [--ranks] [--work /tmp/column_bench] [--exe A --exe B ...]
"""
import argparse
import os
import platform
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(os.path.dirname(HERE)))
import valtools  # noqa: E402


def loop_times(text):
    """ms per step of each `run` in a LIGGGHTS screen output."""
    out = []
    for line in text.splitlines():
        if line.startswith("Loop time of"):
            f = line.split()
            out.append(1000.0 * float(f[3]) / float(f[8]))
    return out


def measure(exe, config, a, out):
    threads, ranks = config
    restart = os.path.join(a.work, "prepare", "rocks_stiffness_settle", "settled.restart")
    if not os.path.exists(restart):
        sys.exit(f"no {restart}: run run_column.py --phases settled --mat stiffness first")
    v = {"floor": os.path.join(a.work, "floor.stl"), "mat": "stiffness", "mode": "restart",
         "restart": restart, "skin": a.skin * 1e-3, "steps": a.steps, "chunks": a.chunks,
         "out": out}
    cmd = valtools.deck_command(exe, os.path.join(HERE, "in.column"), v)
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks)] + cmd
    os.makedirs(out, exist_ok=True)
    r = subprocess.run(cmd, cwd=out, env=valtools.run_env(threads), capture_output=True,
                       text=True)
    problems = valtools.run_problems(r.stdout)
    times = loop_times(r.stdout)
    if r.returncode != 0 or problems or not times:
        sys.exit(f"{' '.join(cmd)} failed ({r.returncode}, {problems}):\n{r.stdout[-1500:]}")
    return min(times)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", action="append", help="a liggghts-tri build (repeatable)")
    ap.add_argument("--work", default="/tmp/column_bench")
    ap.add_argument("--rounds", type=int, default=6)
    ap.add_argument("--steps", type=int, default=100)
    ap.add_argument("--chunks", type=int, default=15)
    ap.add_argument("--skin", type=float, default=0.2, help="mm")
    ap.add_argument("--ranks", action="store_true", help="also 2 MPI ranks of 1 thread")
    a = ap.parse_args()
    exes = [os.path.abspath(e) for e in (a.exe or [valtools.default_exe()])]
    configs = [(1, 1), (2, 1)] + ([(1, 2)] if a.ranks else [])
    print(f"machine: {platform.node()}, {valtools.cpu_model()}, {os.cpu_count()} cores; skin "
          f"{a.skin} mm, fastest of {a.chunks} x {a.steps} steps per run, {a.rounds} rounds")
    times = {(e, c): [] for e in exes for c in configs}
    for r in range(a.rounds):
        for e in exes:
            for c in configs:
                t = measure(e, c, a, os.path.join(a.work, "threads", f"{len(times[(e, c)])}"))
                times[(e, c)].append(t)
                print(f"round {r + 1} {e} {c[0]} thread(s) x {c[1]} rank(s): {t:.3f} ms/step",
                      flush=True)
    print("\n| build | configuration | ms/step best (median) | speed-up best / best | "
          "median of the rounds' speed-ups |\n|---|---|---|---:|---:|")
    for e in exes:
        one = times[(e, (1, 1))]
        for c in configs:
            t = times[(e, c)]
            name = f"{c[0]} thread(s) x {c[1]} rank(s)"
            if c == (1, 1):
                print(f"| {e} | {name} | {min(t):.3f} ({statistics.median(t):.3f}) | | |")
                continue
            rounds = [x / y for x, y in zip(one, t)]
            print(f"| {e} | {name} | {min(t):.3f} ({statistics.median(t):.3f}) | "
                  f"{min(one) / min(t):.2f}x | {statistics.median(rounds):.2f}x |")


if __name__ == "__main__":
    main()
