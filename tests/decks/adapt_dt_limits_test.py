#!/usr/bin/env python3
"""fix tri/adapt_dt's limits: (1) its log is rate-limited, at most 10 lines of changes per
window of `log N` steps and one summary line for the rest, which together account for every
change that `log all` lists; (2) the first intersection of real surfaces in a run is a WARNING, once; sitting at dtmin while they intersect (two soft cubes
driven 12 times through their soft layers) stops with an error naming the pair, the depth and
the remedy. Standard library only.

usage: adapt_dt_limits_test.py --exe LIGGGHTS_TRI --work DIR
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
CHANGE = re.compile(r"tri/adapt_dt: step (\d+): dt (\S+) -> (\S+) \((.*)\)")
SUMMARY = re.compile(r"tri/adapt_dt: steps (\d+)-(\d+): (\d+) more changes not listed "
                     r"\((\d+) halvings, (\d+) growths, (\d+) approach bounds\)")


def write_cube(path, side=0.004):
    h = 0.5 * side
    v = [(sx * h, sy * h, sz * h) for sz in (-1, 1) for sy in (-1, 1) for sx in (-1, 1)]
    faces = [(0, 2, 3), (0, 3, 1), (4, 5, 7), (4, 7, 6), (0, 1, 5), (0, 5, 4),
             (2, 6, 7), (2, 7, 3), (0, 4, 6), (0, 6, 2), (1, 3, 7), (1, 7, 5)]
    with open(path, "w") as f:
        f.write("solid cube\n")
        for t in faces:
            f.write(" facet normal 0 0 0\n  outer loop\n")
            for i in t:
                f.write("   vertex %.9g %.9g %.9g\n" % v[i])
            f.write("  endloop\n endfacet\n")
        f.write("endsolid cube\n")


def run(exe, work, variables):
    cmd = [exe, "-in", os.path.join(HERE, "in.contact_adapt"), "-log", "none",
           "-var", "dir", HERE]
    for k, v in variables.items():
        cmd += ["-var", k, str(v)]
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMP_NUM_THREADS="1")
    p = subprocess.run(cmd, cwd=work, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True, errors="replace", timeout=600)
    return p.returncode, p.stdout


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--work", required=True)
    a = ap.parse_args()
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    write_cube(os.path.join(a.work, "cube.stl"))
    failures = []

    # (1) The same run with every change listed and with a 200-step window.
    code_all, out_all = run(a.exe, a.work, {"adtlog": "all"})
    code_lim, out_lim = run(a.exe, a.work, {"adtlog": 200})
    every = CHANGE.findall(out_all)
    listed = CHANGE.findall(out_lim)
    summaries = SUMMARY.findall(out_lim)
    quiet = sum(int(s[2]) for s in summaries)
    if code_all or code_lim:
        failures.append(f"exit {code_all}, {code_lim}")
    if len(every) <= 10:
        failures.append(f"only {len(every)} changes with 'log all': nothing to limit")
    if not summaries:
        failures.append("no summary line with 'log 200'")
    if len(listed) + quiet != len(every):
        failures.append(f"'log 200' lists {len(listed)} changes and sums up {quiet}, "
                        f"'log all' lists {len(every)}")
    for s in summaries:
        if int(s[2]) != int(s[3]) + int(s[4]) + int(s[5]):
            failures.append(f"summary {s}: the counts do not add up")
    # Per window of 200 steps (windows start at a change), at most 10 lines.
    count, start = 0, None
    for step, *_ in listed:
        step = int(step)
        if start is None or step >= start + 200:
            start, count = step, 0
        count += 1
        if count > 10:
            failures.append(f"more than 10 lines in the window starting at step {start}")
            break
    print(f"log all: {len(every)} changes; log 200: {len(listed)} lines + {len(summaries)} "
          f"summaries of {quiet} more")

    # (2) Soft cubes at 2 x 2 m/s: a linear spring would need 2.5 mm of overlap (12 x the
    # combined layer of 0.2 mm); dt is pinned at dtmin = dtmax, so nothing can be halved.
    code, out = run(a.exe, a.work, {"vx": 2.0, "knv": 50, "dtmax": 1e-6, "dtmin": 1e-6,
                                    "adtlog": "all"})
    errors = [l for l in out.splitlines() if "ERROR" in l]
    warnings = re.findall(r"WARNING: tri/particles: step \d+: real surfaces intersect for the "
                          r"first time in this run \(1 interaction\(s\), e\.g\. particles 1 and "
                          r"2; deepest overlap", out)
    if len(warnings) != 1:
        failures.append(f"{len(warnings)} first-intersection warnings, expected 1")
    want = (r"Fix tri/adapt_dt: step \d+: dt has been at dtmin \(1e-06 s\) for 10 steps while "
            r"real surfaces intersect \(1 interaction\(s\), e\.g\. particles 1 and 2; deepest "
            r"overlap \S+ m = \S+ x the combined soft layer 2 epsilon\): the contact force cannot "
            r"push them apart at this stiffness; use a stiffer kn, a wider epsilon, or a lower dtmin")
    if code == 0 or not errors or not re.search(want, " ".join(errors)):
        failures.append(f"stuck at dtmin: exit {code}, errors {errors or out[-1500:]!r}")
    else:
        print(errors[0])

    # (3) A bad log window.
    code, out = run(a.exe, a.work, {"adtlog": 2.5})
    if code == 0 or "Fix tri/adapt_dt: 'log' expects a number of steps or 'all', got '2.5'" not in out:
        failures.append(f"log 2.5: exit {code}: {out[-800:]}")

    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
