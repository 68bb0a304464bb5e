#!/usr/bin/env python3
"""examples/chute (LIGGGHTS's meshGran tutorial converted to rocks) run briefly: the tutorial's
own material fixes (model hooke), epsilon auto and the time-step check at work, 40 rocks fed by
fix insert/stream from the tutorial's template, landing on the chute with no intersecting
surfaces and no error. Also counts the lines the conversion changed against the tutorial.
Standard library only.

usage: chute_test.py --exe LIGGGHTS_TRI --work DIR
"""
import argparse
import difflib
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
CHUTE = os.path.join(HERE, "..", "..", "examples", "chute", "in.chute")
TUTORIAL = "/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public/meshGran"


def code_lines(path):
    """The deck's commands: comments and blank lines dropped, whitespace normalised."""
    out = []
    for line in open(path):
        line = line.split("#")[0].split()
        if line:
            out.append(" ".join(line))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--work", required=True)
    a = ap.parse_args()
    if not os.path.isfile(os.path.join(TUTORIAL, "in.meshGran")):
        print(f"FAIL: {TUTORIAL} is missing: install Debian's liggghts-doc "
              "(apt-get install --no-install-recommends liggghts-doc)")
        return 1
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMP_NUM_THREADS="1")
    cmd = [a.exe, "-in", CHUTE, "-log", "none", "-var", "tut", TUTORIAL, "-var", "n", "40",
           "-var", "steps1", "800", "-var", "steps2", "4000"]
    p = subprocess.run(cmd, cwd=a.work, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True, errors="replace", timeout=600)
    out = p.stdout
    failures = []
    if p.returncode != 0 or "ERROR" in out:
        failures.append(f"exit {p.returncode}: {out[-2500:]}")
    # thermo: step atoms ke erot pairs_in_contact contacts_after penetrations vol
    rows = [l.split() for l in out.splitlines()
            if re.match(r"^\s+\d+\s+\d+\s", l) and len(l.split()) == 8]
    if not rows:
        failures.append("no thermo rows")
    else:
        last = rows[-1]
        if int(last[1]) != 40:
            failures.append(f"{last[1]} atoms inserted, expected 40")
        if not any(float(r[4]) > 0 for r in rows):
            failures.append("the rocks never touched the chute or each other")
        if any(float(r[6]) != 0 for r in rows):
            failures.append("real surfaces intersected (penetrations > 0)")
    for what in ("tri/particles: epsilon auto = ", "tri/particles: time-step check: dt 5e-05 s",
                 "tri/particles: template pts1 (radius 0.005 m"):
        if what not in out:
            failures.append(f"no line '{what}...'")
    warnings = [l for l in out.splitlines() if "WARNING" in l and "highly skewed" not in l]
    if warnings:
        failures.append(f"warnings: {warnings}")
    # The conversion: commands of the tutorial that changed or were added/removed.
    tut, ours = code_lines(os.path.join(TUTORIAL, "in.meshGran")), code_lines(CHUTE)
    changed = added = removed = 0
    for op, i1, i2, j1, j2 in difflib.SequenceMatcher(None, tut, ours).get_opcodes():
        if op == "replace":
            changed += max(i2 - i1, j2 - j1)
        elif op == "insert":
            added += j2 - j1
        elif op == "delete":
            removed += i2 - i1
    print(f"conversion: {len(tut)} tutorial commands; {changed} changed, {added} added, "
          f"{removed} removed (examples/chute/in.chute)")
    for f in failures:
        print("FAIL:", f)
    if not failures:
        print(f"chute: 40 rocks inserted and on the chute at t = 0.2 s, "
              f"{max(int(float(r[4])) for r in rows)} pairs in contact at most, no intersection")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
