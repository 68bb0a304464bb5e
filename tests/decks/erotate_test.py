#!/usr/bin/env python3
"""compute tri/erotate against hand values: three particles spinning freely (no contacts, no
gravity), a cube (side 2^-8 m = 3.9 mm, atom 1) and two 40-triangle rocks (atoms 2 and 3, the
group `rocks`), randomly oriented. Checked:
  * the cube alone (all minus rocks): 0.5 I |omega|^2 with I = m a^2 / 6, which holds in every
    orientation because a cube's inertia is isotropic;
  * every 100 steps, each compute against 0.5 sum L . omega over its group from a dump of the
    angular momentum (f_shapes[6..8]) and LIGGGHTS's omega, which fix tri/nve keeps current;
  * free rotation keeps the energy: NO_SQUISH is symplectic, so its energy error stays bounded,
    of order (omega dt)^2 = 2e-5 here (measured 2e-7 relative over 1000 steps); bound 1e-5.
Standard library only.

usage: erotate_test.py --exe LIGGGHTS_TRI --work DIR
"""
import argparse
import os
import shutil
import subprocess
import sys

# A power of two: STL coordinates are single precision, and 0.003 would make the cube's inertia
# (a^5) 4e-8 off the hand value.
SIDE = 2.0 ** -8
DENSITY = 2500.0
OMEGA = {1: (150.0, -220.0, 310.0), 2: (-400.0, 120.0, 90.0), 3: (50.0, 260.0, -330.0)}
TOL = 1e-12

DECK = """\
units           si
atom_style      sphere
atom_modify     map array sort 0 0.0   # no pair style: LIGGGHTS cannot size sort bins
boundary        f f f
newton          off
communicate     single vel yes
region          box block -0.02 0.02 -0.02 0.02 -0.02 0.02 units box
create_box      2 box
neighbor        0.001 bin
neigh_modify    delay 0
timestep        1e-5
create_atoms    1 single -0.008 0.0 0.0 units box
create_atoms    2 single 0.008 0.0 0.0 units box
create_atoms    2 single 0.0 0.0 0.01 units box
fix shapes all tri/particles shape cube file cube.stl &
    shape rock random ntri 40 size 0.005 seed 8 aspect 0.9 0.6 &
    assign type density {density} epsilon 0.0001 orient random 99
{omegas}
fix integr all tri/nve
group rocks type 2
compute erot all tri/erotate
compute erock rocks tri/erotate
thermo_style custom step c_erot c_erock
thermo_modify format float %.17g
thermo 100
dump d all custom 100 spin.dump id type omegax omegay omegaz f_shapes[6] f_shapes[7] f_shapes[8]
dump_modify d sort id format "%d %d %.17g %.17g %.17g %.17g %.17g %.17g"
run 1000
"""


def write_cube(path, a):
    """A closed cube [0, a]^3, triangles counter-clockwise seen from outside."""
    v = [(x * a, y * a, z * a) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    with open(path, "w") as f:
        f.write("solid cube\n")
        for p, q, r, s in faces:
            for tri in ((p, q, r), (p, r, s)):
                f.write(" facet normal 0 0 0\n  outer loop\n")
                for k in tri:
                    f.write("   vertex %r %r %r\n" % v[k])
                f.write("  endloop\n endfacet\n")
        f.write("endsolid cube\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--work", required=True)
    a = ap.parse_args()
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    write_cube(os.path.join(a.work, "cube.stl"), SIDE)
    omegas = "\n".join(f"set atom {t} omegax {w[0]} omegay {w[1]} omegaz {w[2]}"
                       for t, w in OMEGA.items())
    with open(os.path.join(a.work, "in.erotate"), "w") as f:
        f.write(DECK.format(density=DENSITY, omegas=omegas))
    env = dict(os.environ, OMP_NUM_THREADS="1")
    p = subprocess.run([a.exe, "-in", "in.erotate", "-log", "none"], cwd=a.work, env=env,
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                       errors="replace", timeout=300)
    failures = []
    if p.returncode != 0:
        print(p.stdout[-3000:])
        print(f"FAIL erotate: exit {p.returncode}")
        return 1
    thermo = {}
    for line in p.stdout.splitlines():
        f = line.split()
        if len(f) == 3 and f[0].isdigit():
            thermo[int(f[0])] = (float(f[1]), float(f[2]))
    frames, step = {}, None
    with open(os.path.join(a.work, "spin.dump")) as f:
        lines = f.read().splitlines()
    for k, line in enumerate(lines):
        if line.startswith("ITEM: TIMESTEP"):
            step = int(lines[k + 1])
            frames[step] = {}
        elif step is not None and not line.startswith("ITEM") and len(line.split()) == 8:
            v = [float(x) for x in line.split()]
            frames[step][int(v[0])] = v[1:]
    if sorted(thermo) != list(range(0, 1001, 100)) or sorted(frames) != sorted(thermo):
        failures.append(f"thermo steps {sorted(thermo)}, dump steps {sorted(frames)}")

    def rel(x, y):
        return abs(x - y) / abs(y)

    mass = DENSITY * SIDE ** 3
    w = OMEGA[1]
    cube_hand = 0.5 * (mass * SIDE ** 2 / 6.0) * sum(c * c for c in w)
    all0, rocks0 = thermo.get(0, (0.0, 0.0))
    cube = all0 - rocks0
    print(f"cube: compute {cube!r} J, hand 0.5 (m a^2/6) |w|^2 = {cube_hand!r} J, "
          f"relative {rel(cube, cube_hand):.2g}")
    if rel(cube, cube_hand) > TOL:
        failures.append(f"cube: {cube} != {cube_hand}")
    worst = 0.0
    for s, rows in sorted(frames.items()):
        half_l_w = {t: 0.5 * sum(r[1 + d] * r[4 + d] for d in range(3)) for t, r in rows.items()}
        hand_all = sum(half_l_w.values())
        hand_rocks = sum(v for t, v in half_l_w.items() if rows[t][0] == 2)
        e_all, e_rocks = thermo.get(s, (0.0, 0.0))
        for what, got, hand in (("all", e_all, hand_all), ("rocks", e_rocks, hand_rocks)):
            worst = max(worst, rel(got, hand))
            if rel(got, hand) > TOL:
                failures.append(f"step {s}, group {what}: compute {got!r}, 0.5 L.w {hand!r}")
    print(f"against 0.5 sum L . omega of the dump: largest relative difference {worst:.2g}")
    if thermo:
        drift = max(rel(v[0], thermo[0][0]) for v in thermo.values())
        print(f"free rotation, 1000 steps: rotational energy {thermo[0][0]!r} J, largest "
              f"relative change {drift:.2g}")
        if drift > 1e-5:
            failures.append(f"free rotation changed the energy by {drift:.3g} relative")
    if failures:
        print("FAIL erotate:\n  " + "\n  ".join(failures))
        return 1
    print("PASS erotate")
    return 0


if __name__ == "__main__":
    sys.exit(main())
