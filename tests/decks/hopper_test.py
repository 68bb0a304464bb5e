#!/usr/bin/env python3
"""The reduced hopper of examples/hopper through liggghts-tri, checked for what the full run
must show: particles enter the funnel, touch its walls and each other (compute tri/stats),
leave through the outlet, and none is lost; no NaN anywhere. Standard library only.

usage: hopper_test.py --exe LIGGGHTS_TRI --work DIR
"""
import argparse
import math
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
HOPPER = os.path.join(HERE, "..", "..", "examples", "hopper")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--work", required=True)
    a = ap.parse_args()
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(os.path.join(a.work, "post"))
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMP_NUM_THREADS="1")
    # 64 rocks, 0.2 s: the lattice falls 65 mm to the outlet in about 0.12 s.
    cmd = [a.exe, "-in", os.path.join(HOPPER, "in.hopper"), "-log", "none",
           "-var", "dir", HOPPER, "-var", "n", "4", "-var", "tend", "0.2", "-var", "vtk", "0"]
    p = subprocess.run(cmd, cwd=a.work, env=env, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True, errors="replace", timeout=900)
    out = p.stdout
    failures = []
    if p.returncode != 0:
        failures.append(f"exit {p.returncode}: {out[-2000:]}")
    if "nan" in out.lower().replace("nanoseconds", ""):
        failures.append("NaN in the output")
    # thermo: step time atoms ke nout pair_contacts wall_contacts before after fallbacks
    #         penetrations deepest_overlap
    rows = []
    for line in out.splitlines():
        f = line.split()
        if len(f) == 12 and f[0].isdigit():
            rows.append([float(x) for x in f])
    if not rows:
        failures.append("no thermo output")
    else:
        atoms = {int(r[2]) for r in rows}
        if atoms != {64}:
            failures.append(f"atom count changed: {sorted(atoms)}")
        if max(r[5] for r in rows) <= 0:
            failures.append("no particle ever touched another particle")
        if max(r[6] for r in rows) <= 0:
            failures.append("no particle ever touched the hopper")
        if not all(r[8] <= r[7] for r in rows):
            failures.append("reduction produced more contact points than triangle-pair contacts")
        if any(not math.isfinite(x) for r in rows for x in r):
            failures.append("non-finite thermo value")
        left = rows[-1][4]
        if left < 16:
            failures.append(f"only {left:.0f} of 64 particles left through the outlet")
    summary = [l for l in out.splitlines() if l.startswith("hopper summary")]
    print(summary[0] if summary else "no summary line")
    if failures:
        print("FAIL hopper:\n  " + "\n  ".join(failures))
        return 1
    print(f"PASS hopper: {rows[-1][4]:.0f} of 64 discharged, up to "
          f"{max(r[5] for r in rows):.0f} particle pairs and {max(r[6] for r in rows):.0f} "
          f"particle-wall pairs in contact")
    return 0


if __name__ == "__main__":
    sys.exit(main())
