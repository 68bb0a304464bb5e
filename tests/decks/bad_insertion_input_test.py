#!/usr/bin/env python3
"""Bad input of the keywords for orientation and insertion (fix tri/particles `orient file`,
`template ID SHAPE`, particletemplate/sphere, particledistribution/discrete): each deck must
stop with a LIGGGHTS ERROR line matching its pattern (the README's "Bad input and extreme
states" rows), never crash, never run. Standard library only.

usage: bad_insertion_input_test.py --exe LIGGGHTS_TRI --work DIR
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

HEAD = """\
units           si
atom_style      sphere
atom_modify     map array sort 0 0.0
boundary        f f f
newton          off
communicate     single vel yes
region          box block -0.03 0.03 -0.03 0.03 -0.03 0.03 units box
create_box      2 box
neighbor        0.001 bin
neigh_modify    delay 0
timestep        1e-5
"""
SHAPES = "shape a random ntri 20 size 0.004 seed 1 shape b random ntri 20 size 0.003 seed 2"
TAIL = "density 2500 epsilon 0.0001"
PTS1 = ("fix pts1 all particletemplate/sphere 15485863 atom_type {t} density constant 2500 "
        "radius constant 0.002\n")
PDD = "fix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"


def particles(extra):
    return f"fix shapes all tri/particles {SHAPES} {extra} {TAIL}\n"


CASES = {
    "orient_unknown": (particles("orient sideways"),
                       r"'orient' expects 'random SEED', 'none' or 'file', got 'sideways'"),
    "template_unknown_shape": (particles("template pts1 nosuch"),
                               r"'template pts1 nosuch': no shape is named 'nosuch'"),
    "template_twice": (particles("template pts1 a template pts1 b"),
                       r"'template pts1' is given twice"),
    "template_missing_value": (particles("") .replace(TAIL, TAIL + " template pts1"),
                               r"missing shape name after 'template pts1'"),
    "template_no_such_fix": (particles("template ghost a") + "run 1\n",
                             r"'template ghost': no fix has ID 'ghost' \(expected a fix "
                             r"particletemplate/sphere\)"),
    "template_not_a_template": ("fix grav all gravity 9.81 vector 0 0 -1\n"
                                + particles("template grav a") + "run 1\n",
                                r"'template grav': fix grav is a gravity; only "
                                r"particletemplate/sphere templates can be given a shape"),
    "template_without_shape": (particles("assign random 5") + PTS1.format(t=1),
                               r"fix particletemplate/sphere pts1 has no shape: with 'assign "
                               r"random' and 2 shapes, give it one with 'template pts1 SHAPE'"),
    "template_type_without_shape": (PTS1.format(t=3) + particles("assign type"),
                                    r"fix particletemplate/sphere pts1 inserts atom type 3, but "
                                    r"'assign type' has 2 shape\(s\)"),
    "distribution_before_particles": (PTS1.format(t=1) + PDD + particles("template pts1 a"),
                                      r"fix particledistribution/discrete pdd is defined before "
                                      r"fix tri/particles: it has already turned its mass "
                                      r"fractions into particle numbers"),
    "multisphere_template": (particles("assign type")
                             + "fix pms all particletemplate/multiplespheres 15485863 atom_type 1 "
                               "density constant 2500 nspheres 2 ntry 10000 spheres 0 0 0 0.001 "
                               "0.001 0 0 0.001\n"
                             + "fix pdd all particledistribution/discrete 32452843 1 pms 1.0\n"
                             + "run 1\n",
                             r"fix particledistribution/discrete pdd uses fix pms "
                             r"\(particletemplate/multiplespheres\): triangulated particles are "
                             r"inserted from particletemplate/sphere templates only"),
}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--work", required=True)
    a = ap.parse_args()
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    env = dict(os.environ, OMP_NUM_THREADS="1")
    failures = []
    for name, (body, pattern) in sorted(CASES.items()):
        path = os.path.join(a.work, f"in.{name}")
        with open(path, "w") as f:
            f.write(HEAD + body)
        p = subprocess.run([a.exe, "-in", path, "-log", "none"], cwd=a.work, env=env,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                           errors="replace", timeout=120)
        errors = [l for l in p.stdout.splitlines() if "ERROR" in l]
        if p.returncode == 0 or not errors or not re.search(pattern, " ".join(errors)):
            failures.append(f"{name}: exit {p.returncode}, errors {errors or p.stdout[-800:]!r}, "
                            f"wanted /{pattern}/")
        elif any(s in p.stdout for s in ("Segmentation", "signal", "core dumped")):
            failures.append(f"{name}: crashed instead of a clean error")
        else:
            print(f"{name}: {errors[0].strip()}")
    if failures:
        print("FAIL bad_insertion_input:\n  " + "\n  ".join(failures))
        return 1
    print(f"PASS bad_insertion_input: {len(CASES)} decks, each stopped with its message")
    return 0


if __name__ == "__main__":
    sys.exit(main())
