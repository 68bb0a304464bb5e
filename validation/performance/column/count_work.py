#!/usr/bin/env python3
"""Counts what one step of a settled column costs per particle, in instructions and cache misses.

Timings on a shared machine swing by a third from one run to the next, and a small bed that
fits in the last-level cache is slowed most by a neighbour's load. Counts do not swing:
valgrind's cachegrind runs the deck from a restart file twice, `--short` and `--long` steps,
and the difference is `--long - --short` steps of the measured phase alone (the setup and the
first step's searches cancel). Printed per particle-step: instructions (Ir), data reads and
writes (Dr, Dw), first-level misses (D1mr, D1mw) and last-level misses (DLmr, DLmw) for each
`--ll` size (cachegrind models one level of 64 kB and one last level; a last level smaller than
the chip's stands for a cache shared with other processes), then the functions that differ most.

valgrind does not decode every AVX-512 instruction: build without -march=native first,
  cmake -S . -B build-count -DTRI_NATIVE=OFF -DTRI_BUILD_TESTS=OFF && cmake --build build-count -j2

  validation/performance/column/count_work.py --exe build-count/src_plugin/driver/liggghts-tri \\
      --bed 8:D8/settled.restart:F8.stl --bed 16:D16/settled.restart:F16.stl --ll 32 8

Each --bed is n:restart:floor (the restart and floor of in.column's settle mode for that n;
nz as settled, `n:restart:floor:nz`). Two valgrind processes run at once.
"""
import argparse
import collections
import os
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
EVENTS = ["Ir", "Dr", "Dw", "D1mr", "D1mw", "DLmr", "DLmw"]


def read_counts(path):
    """Per function: the cachegrind events summed over its lines; and the totals."""
    per_fn = collections.defaultdict(lambda: collections.Counter())
    events, fn = None, "?"
    with open(path) as f:
        for line in f:
            if line.startswith("events:"):
                events = line.split()[1:]
            elif line.startswith("fn="):
                fn = line[3:].strip()
            elif line[:1].isdigit() and events:
                parts = line.split()
                for name, value in zip(events, parts[1:]):
                    per_fn[fn][name] += int(value)
    total = collections.Counter()
    for c in per_fn.values():
        total.update(c)
    return per_fn, total


def run_one(a, bed, steps, ll_mb, out):
    n, restart, floor, nz = bed
    cmd = ["valgrind", "--tool=cachegrind", "--cache-sim=yes",
           f"--LL={ll_mb * 1024 * 1024},16,64", f"--cachegrind-out-file={out}", a.exe,
           "-in", os.path.join(HERE, "in.column"), "-log", "none", "-var", "floor", floor,
           "-var", "mat", a.mat, "-var", "mode", "restart", "-var", "restart", restart,
           "-var", "skin", str(a.skin), "-var", "n", str(n), "-var", "nz", str(nz),
           "-var", "steps", str(steps), "-var", "chunks", "1", "-var", "out", os.path.dirname(out)]
    env = dict(os.environ, OMP_NUM_THREADS="1")
    r = subprocess.run(cmd, cwd=a.cwd, env=env, capture_output=True, text=True)
    if r.returncode != 0 or not os.path.exists(out):
        sys.exit(f"failed ({r.returncode}): {' '.join(cmd)}\n{r.stderr[-2000:]}")
    return read_counts(out)


def parse_bed(text):
    parts = text.split(":")
    if len(parts) not in (3, 4):
        sys.exit(f"--bed {text}: expected n:restart:floor[:nz]")
    n = int(parts[0])
    return n, parts[1], parts[2], int(parts[3]) if len(parts) == 4 else n


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog="\n".join(__doc__.splitlines()[1:]))
    ap.add_argument("--exe", required=True)
    ap.add_argument("--bed", action="append", required=True, type=parse_bed)
    ap.add_argument("--ll", type=int, nargs="+", default=[32], help="last-level sizes, MiB")
    ap.add_argument("--short", type=int, default=4)
    ap.add_argument("--long", type=int, default=24)
    ap.add_argument("--skin", type=float, default=0.0004)
    ap.add_argument("--mat", default="stiffness")
    ap.add_argument("--cwd", default=".", help="where the restart and floor paths start")
    ap.add_argument("--top", type=int, default=12)
    a = ap.parse_args()
    a.exe = os.path.abspath(a.exe)

    work = tempfile.mkdtemp(prefix="count_work_")
    jobs = [(bed, ll, steps) for bed in a.bed for ll in a.ll for steps in (a.short, a.long)]
    with ThreadPoolExecutor(max_workers=2) as pool:
        futures = {job: pool.submit(run_one, a, job[0], job[2], job[1],
                                    os.path.join(work, f"n{job[0][0]}_ll{job[1]}_s{job[2]}.out"))
                   for job in jobs}
        results = {job: f.result() for job, f in futures.items()}

    per_step = {}
    print(f"per particle-step, steps {a.short + 1}..{a.long} of each restart, 1 thread, "
          f"skin {a.skin} m, material {a.mat}")
    print("| particles | last level | " + " | ".join(EVENTS) + " |")
    print("|---:|---:|" + "---:|" * len(EVENTS))
    for bed in a.bed:
        n, _, _, nz = bed
        particles = n * n * nz
        for ll in a.ll:
            (fn_s, tot_s), (fn_l, tot_l) = results[(bed, ll, a.short)], results[(bed, ll, a.long)]
            scale = 1.0 / ((a.long - a.short) * particles)
            row = {e: (tot_l[e] - tot_s[e]) * scale for e in EVENTS}
            per_fn = {f: {e: (fn_l[f][e] - fn_s.get(f, collections.Counter())[e]) * scale
                          for e in ("Ir", "DLmr", "DLmw")} for f in fn_l}
            per_step[(n, ll)] = (particles, per_fn)
            print(f"| {particles} | {ll} MiB | " +
                  " | ".join(f"{row[e]:.0f}" if row[e] >= 100 else f"{row[e]:.2f}" for e in EVENTS)
                  + " |")
    if len(a.bed) < 2:
        return
    first, last = a.bed[0][0], a.bed[-1][0]
    for event, ll in (("Ir", a.ll[0]), ("DLmr", a.ll[-1])):
        small, large = per_step[(first, ll)][1], per_step[(last, ll)][1]
        def change(f):
            return large.get(f, {}).get(event, 0) - small.get(f, {}).get(event, 0)
        diff = sorted(set(small) | set(large), key=lambda f: -abs(change(f)))
        print(f"\n{event} per particle-step by function (last level {ll} MiB), "
              f"{per_step[(first, ll)][0]} against {per_step[(last, ll)][0]} particles, "
              f"largest differences:")
        for f in diff[:a.top]:
            s, l = small.get(f, {}).get(event, 0), large.get(f, {}).get(event, 0)
            print(f"  {s:10.1f} {l:10.1f} {l - s:+10.1f}  {f[:110]}")


if __name__ == "__main__":
    main()
