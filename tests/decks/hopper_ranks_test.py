#!/usr/bin/env python3
"""The reduced hopper of examples/hopper (64 rocks) on 1, 2 and 4 MPI ranks (Open MPI,
oversubscribed; processors 1x1, 2x1, 2x2, so the x = 0 and y = 0 planes through the outlet
cut the pile): the final positions and orientations agree within 1e-10 (in practice they are
bitwise equal), rocks touched each other and the walls on the way, no atom was lost and no NaN
appeared. Standard library only.

usage: hopper_ranks_test.py --exe LIGGGHTS_TRI --work DIR [--steps N] [--every M]

--every M (study mode) dumps every M steps and prints the difference at each dump instead of
checking only the last one; that is how the table below was measured.

What "relative" means: the largest |x_N - x_1| over all atoms and components divided by the
particles' size, 4 mm (the rocks' bounding diameter; the hopper is 50 times larger), and the
largest |q_N - q_1| over the components of the unit orientation quaternions (w x y z,
f_shapes[2..5]). Positions are about 0.05 m, so one rounding of a coordinate is 7e-18 m =
2e-15 of a particle size.

Why 1e-10, and why it is in effect a test of bitwise equality. A granular pile is chaotic, and
the hybrid kernel's accept/fallback decision can flip on a last-bit difference and then move a
contact distance by up to its tolerance (1e-4 epsilon): a difference grows by two to four
orders of magnitude per 500 steps of contacts. Measured with the pair style as it
was before it evaluated pairs in a canonical order (commit e2c992f: the rank that owns j
evaluated a pair as (j, i), and forces were summed in neighbour-list order), `--every 500
--steps 16000`, largest difference against 1 rank (position / particle size, quaternion):

  steps          2 ranks             4 ranks
  500..5500      0         0         0         0          free fall: no contacts yet
  6000           2.8e-11   1.6e-10   2.8e-11   1.6e-10    first funnel contacts at ~5600
  6500           2.4e-07   3.2e-07   2.4e-07   3.2e-07
  7000           6.1e-05   1.9e-04   6.1e-05   1.9e-04
  8000           4.7e-03   1.2e-02   4.7e-03   1.2e-02
  10000          1.6       1.6       1.5       1.3        rocks on the floor, elsewhere
  16000          14        1.9       13        1.8

A tolerance could therefore only pick when the check stops passing, never whether the code is
right: 1e-10 (0.4 nm, 5e4 roundings) fails within ~500 steps of contacts if any last-bit
difference appears, and a looser one would just move that moment. Now pair tri/gran evaluates
every pair as (lower tag, higher tag) and sums each atom's pair forces in partner-tag order;
the walls already summed per atom in global triangle order. Measured since: 1, 2 and 4 ranks
bitwise equal at every 500 steps to 16000 (all zeros in the table).

The test runs 12000 steps (0.24 s): free fall to ~5600, the funnel (particle-particle and
particle-wall contacts) and the outlet, and the first rocks landing on the floor; contacts in
about 40 % of the thermo samples. 6 s wall on an idle 2-core machine.
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
HOPPER = os.path.join(HERE, "..", "..", "examples", "hopper")
SIZE = 0.004        # the rocks' bounding diameter (m), in.hopper's `size`
TOL = 1e-10
STEPS = 12000
GRIDS = {1: (1, 1), 2: (2, 1), 4: (2, 2)}
# thermo of in.hopper: step time atoms ke nout pair_contacts wall_contacts before after
# fallbacks penetrations deepest_overlap
NCOL = 12


def make_deck(work, every):
    """in.hopper as it is, plus a dump of id, position and orientation every `every` steps and
    thermo every 100 steps (to see the contacts), inserted before its run command."""
    with open(os.path.join(HOPPER, "in.hopper")) as f:
        lines = f.read().splitlines()
    runs = [k for k, l in enumerate(lines) if re.match(r"\s*run\s", l)]
    if len(runs) != 1:
        raise SystemExit(f"expected one run command in in.hopper, found {len(runs)}")
    cols = "id x y z f_shapes[2] f_shapes[3] f_shapes[4] f_shapes[5]"
    fmt = " ".join(["%d"] + ["%.17g"] * 7)
    extra = [f"dump pos all custom {every} positions.dump {cols}",
             f'dump_modify pos sort id format "{fmt}"',
             "thermo 100"]
    lines[runs[0]:runs[0]] = extra
    path = os.path.join(work, "in.hopper_ranks")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return path


def frames(path):
    """Every snapshot of a custom dump: {step: {id: [floats]}}."""
    out = {}
    with open(path) as f:
        lines = f.read().splitlines()
    k = 0
    while k < len(lines):
        if lines[k].startswith("ITEM: TIMESTEP"):
            step = int(lines[k + 1])
            n = int(lines[k + 3])
            rows = {}
            for l in lines[k + 9:k + 9 + n]:
                v = l.split()
                rows[int(v[0])] = [float(x) for x in v[1:]]
            out[step] = rows
            k += 9 + n
        else:
            k += 1
    return out


def run(exe, deck, work, ranks, steps):
    px, py = GRIDS[ranks]
    sub = os.path.join(work, f"np{ranks}")
    os.makedirs(os.path.join(sub, "post"))
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMP_NUM_THREADS="1")
    tend = repr(steps * 2e-5)
    cmd = ["mpirun", "--oversubscribe", "-np", str(ranks), exe, "-in", deck, "-log", "none",
           "-var", "dir", HOPPER, "-var", "n", "4", "-var", "tend", tend, "-var", "vtk", "0",
           "-var", "px", str(px), "-var", "py", str(py)]
    p = subprocess.run(cmd, cwd=sub, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True, errors="replace", timeout=900)
    rows = []
    for line in p.stdout.splitlines():
        f = line.split()
        if len(f) == NCOL and f[0].isdigit():
            rows.append([float(x) for x in f])
    return p, rows, os.path.join(sub, "positions.dump")


def differences(ref, other):
    """Largest position difference / SIZE and largest quaternion component difference. A
    quaternion and its negative are the same rotation, but both runs start from the same one
    and integrate continuously, so the components are compared as they are."""
    dx = dq = 0.0
    for tag, r in ref.items():
        o = other[tag]
        dx = max(dx, max(abs(r[k] - o[k]) for k in range(3)) / SIZE)
        dq = max(dq, max(abs(r[k] - o[k]) for k in range(3, 7)))
    return dx, dq


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--steps", type=int, default=STEPS)
    ap.add_argument("--every", type=int, default=0, help="study: dump every M steps")
    a = ap.parse_args()
    every = a.every or a.steps
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    deck = make_deck(a.work, every)
    failures = []
    dumps, contacts = {}, {}
    for ranks in GRIDS:
        p, rows, dump = run(a.exe, deck, a.work, ranks, a.steps)
        out = p.stdout
        if p.returncode != 0:
            failures.append(f"{ranks} ranks: exit {p.returncode}: {out[-2000:]}")
            continue
        if "nan" in out.lower().replace("nanoseconds", ""):
            failures.append(f"{ranks} ranks: NaN in the output")
        if not rows or any(not math.isfinite(x) for r in rows for x in r):
            failures.append(f"{ranks} ranks: no thermo output or a non-finite value")
            continue
        if {int(r[2]) for r in rows} != {64}:
            failures.append(f"{ranks} ranks: atom count changed: {sorted({r[2] for r in rows})}")
        # thermo every 100 steps: samples with particle-particle and particle-wall contacts
        contacts[ranks] = (sum(r[5] > 0 for r in rows), sum(r[6] > 0 for r in rows),
                           len(rows), rows[-1][4])
        dumps[ranks] = frames(dump)
    if 1 in contacts:
        pp, pw, n, out = contacts[1]
        print(f"1 rank: particle contacts in {pp} and wall contacts in {pw} of {n} thermo "
              f"samples (every 100 steps), {out:.0f} of 64 discharged")
        if pp < 5 or pw < 5:
            failures.append(f"too few contacts: particle {pp}, wall {pw} thermo samples")
    if 1 in dumps:
        ref = dumps[1]
        steps = sorted(ref)
        print("step   " + "   ".join(f"{r} ranks: dx/size    dq" for r in GRIDS if r > 1))
        for step in steps:
            cells = []
            for ranks in GRIDS:
                if ranks == 1 or ranks not in dumps:
                    continue
                other = dumps[ranks].get(step)
                if other is None or set(other) != set(ref[step]):
                    failures.append(f"{ranks} ranks, step {step}: missing or different atoms")
                    continue
                dx, dq = differences(ref[step], other)
                cells.append(f"{dx:9.2e} {dq:9.2e}")
                if step == a.steps and (dx > TOL or dq > TOL):
                    failures.append(f"{ranks} ranks, step {step}: position difference {dx:.3g} "
                                    f"of a particle size, quaternion {dq:.3g} (tolerance {TOL:g})")
            print(f"{step:6d}   " + "      ".join(cells))
        if a.steps not in ref:
            failures.append(f"no dump at step {a.steps}")
    if failures:
        print("FAIL hopper_ranks:\n  " + "\n  ".join(failures))
        return 1
    same = all(dumps[r][a.steps] == dumps[1][a.steps] for r in dumps)
    print(f"PASS hopper_ranks: 1, 2 and 4 ranks agree within {TOL:g} after {a.steps} steps"
          f"{' (bitwise equal)' if same else ''}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
