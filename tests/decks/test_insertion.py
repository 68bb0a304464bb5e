"""LIGGGHTS's own insertion of triangulated particles: fix insert/stream, insert/pack or
insert/rate/region with two particletemplate/sphere templates, a particledistribution/discrete
of mass fractions 0.3 / 0.7, and two shapes of different mass (a 4 mm rock of 20 triangles, a
3 mm rock of 40: 2.4 times lighter), falling under gravity above a floor (fix tri/wall).

The templates' radius (1 mm) is half the shapes' reach: LIGGGHTS would pack such spheres far
too densely for the real particles, and weigh them all the same. Checked:
  * one info line per template at the first insertion, naming its shape, reach and mass;
  * every atom has a shape, and its radius and mass are that shape's (its reach, the mesh's bounding
    radius; density x volume), never the template's;
  * the shapes' mass fractions are 0.3 / 0.7 within 3 standard deviations of a binomial draw of
    that many particles (with the templates' sphere masses they would be 0.50 / 0.50);
  * no two particles and no particle and the floor start intersecting: compute tri/stats
    penetrations (columns by name from tri-stats-columns) is 0 on every step (insert/pack fills
    a region that ends at the floor), and at the first insertion no particle pair touches
    even with its soft layers (compute tri/stats pair, pairs_in_contact);
  * all requested particles were inserted.
Tests insert_MODE, modes: stream (templates defined before fix tri/particles, `template` keyword, particlerate),
pack (templates after it, `template` keyword, mass_in_region: the inserted mass is the asked
one), rate_region (`assign type`: the templates' atom types 1 and 2 pick the shapes, massrate; the
insert fix's `omega` is the particles' spin).

insert_stream_ranks: stream on two MPI ranks (processors 2 1 1: the insertion volume is cut in
two, and particles inserted on one rank are ghosts on the other), with the same checks.
"""
import math
import os
import re

from decklib import check, last_frame, run_deck, stat, thermo_rows, write_stl

FRACTION_BIG = 0.3
EPS = 1e-4

HEAD = """\
units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
newton          off
communicate     single vel yes
processors      {ranks} 1 1
region          domain block -0.03 0.03 -0.03 0.03 -0.005 0.1 units box
create_box      2 domain
neighbor        0.001 bin
neigh_modify    delay 0
timestep        1e-5
fix m1 all property/global kn peratomtypepair 2 1000 1000 1000 1000
fix m2 all property/global kt peratomtypepair 2 500 500 500 500
fix m3 all property/global gamman peratomtypepair 2 40 40 40 40
fix m4 all property/global gammat peratomtypepair 2 20 20 20 20
fix m5 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5
"""
PARTICLES = """\
fix shapes all tri/particles shape big random ntri 20 size 0.004 seed 11 &
    shape small random ntri 40 size 0.0025 seed 12 {assign} &
    density 2500 epsilon {eps} orient random 99
"""
TEMPLATES = """\
fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.001
fix pts2 all particletemplate/sphere 32452843 atom_type {type2} density constant 2500 radius constant 0.001
"""
TAIL = """\
fix pdd all particledistribution/discrete 49979687 2 pts1 {fb} pts2 {fs}
pair_style      tri/gran
pair_coeff      * *
fix floor all mesh/surface file floor.stl type 1
fix walls all tri/wall mesh floor
fix grav all gravity 9.81 vector 0 0 -1
fix integr all tri/nve
{insert}
compute stats all tri/stats
compute pstats all tri/stats pair
thermo_style custom step atoms c_stats[{pen}] c_pstats[{contacts}]
thermo 1
dump d all custom {steps} final.dump id type radius mass f_shapes[1] omegaz
dump_modify d format "%d %d %.17g %.17g %.17g %.17g"
run {steps}
"""

MODES = {
    # 100 particles in 4 insertions of 25 (every 500 steps: extrude 0.01 m at 2 m/s)
    "stream": dict(
        order="templates_first", assign="template pts1 big template pts2 small", type2=1,
        insert="fix inface all mesh/surface/planar file face.stl type 1\n"
               "fix ins all insert/stream seed 67867967 distributiontemplate pdd nparticles 100 "
               "particlerate 5000 overlapcheck yes all_in yes vel constant 0 0 -2 "
               "insertion_face inface extrude_length 0.01",
        steps=1600, count=100),
    # mass_in_region 3 g at once in a 40 x 40 x 30 mm box on the floor: about 170 particles
    "pack": dict(
        order="particles_first", assign="template pts1 big template pts2 small", type2=1,
        insert="region ins block -0.02 0.02 -0.02 0.02 0.0 0.03 units box\n"
               "fix ins all insert/pack seed 67867967 distributiontemplate pdd "
               "insert_every once overlapcheck yes all_in yes vel constant 0 0 0 "
               "region ins mass_in_region 0.003",
        steps=300, mass=0.003),
    # 120 particles at 0.2 kg/s, every 500 steps: about 70 per insertion
    "rate_region": dict(
        order="particles_first", assign="assign type", type2=2,
        insert="region ins block -0.02 0.02 -0.02 0.02 0.05 0.08 units box\n"
               "fix ins all insert/rate/region seed 67867967 distributiontemplate pdd "
               "nparticles 120 massrate 0.2 insert_every 500 overlapcheck yes all_in yes "
               "vel constant 0 0 0 omega constant 0 0 50 region ins",
        steps=1100, count=120, omega=50.0),
}


def square(z, h):
    a, b, c, d = (-h, -h, z), (h, -h, z), (h, h, z), (-h, h, z)
    return [[a, b, c], [a, c, d]]


def deck(mode, ranks):
    m = MODES[mode]
    particles = PARTICLES.format(assign=m["assign"], eps=EPS)
    templates = TEMPLATES.format(type2=m["type2"])
    first, second = ((templates, particles) if m["order"] == "templates_first"
                     else (particles, templates))
    return HEAD.format(ranks=ranks) + first + second + TAIL.format(
        fb=FRACTION_BIG, fs=1 - FRACTION_BIG, insert=m["insert"], pen=stat("penetrations"),
        contacts=stat("pairs_in_contact"), steps=m["steps"])


def insertion(ctx, mode, ranks=1):
    m = MODES[mode]
    write_stl(os.path.join(ctx.work, "floor.stl"), square(0.0, 0.03))
    write_stl(os.path.join(ctx.work, "face.stl"), square(0.09, 0.02))
    path = os.path.join(ctx.work, "in.insert")
    with open(path, "w") as f:
        f.write(deck(mode, ranks))
    _, out = run_deck(ctx, path, ranks=ranks)

    # The info lines: template -> shape, its reach and mass.
    info = {}
    for t, s, r, mass in re.findall(r"tri/particles: template (\S+) \(radius \S+ m, mass \S+ kg\) "
                                    r"-> shape (\S+) \(reach (\S+) m, mass (\S+) kg\)",
                                    out):
        info[t] = (s, float(r), float(mass))
    for line in out.splitlines():
        if line.startswith("tri/particles: template"):
            print(line)
    check(sorted(info) == ["pts1", "pts2"] and info["pts1"][0] == "big"
          and info["pts2"][0] == "small", f"info lines: {info}")
    shape_of = {0: info["pts1"], 1: info["pts2"]}   # shape index: big 0, small 1

    # Thermo: step atoms penetrations (particles and floor) particle_pairs_in_contact
    rows = thermo_rows(out, ("stats", "pstats"))
    check(rows, "no thermo output")
    for r in rows:
        check(r["stats.penetrations"] == 0, f"step {r['Step']:.0f}: "
              f"{r['stats.penetrations']:.0f} intersecting surfaces ({r['Atoms']:.0f} atoms)")
    first = next((r for r in rows if r["Atoms"] > 0), None)
    check(first is not None, "nothing was inserted")
    check(first["pstats.pairs_in_contact"] == 0,
          f"step {first['Step']:.0f}, the first insertion: {first['pstats.pairs_in_contact']:.0f} "
          "particle pairs touch with their soft layers")

    # The final atoms: every one has a shape, with that shape's radius and mass.
    _, final = last_frame(os.path.join(ctx.work, "final.dump"))
    atoms = [[str(tag)] + r for tag, r in final.items()]
    check(atoms, "no atoms in the final dump")
    count = {0: 0, 1: 0}
    values = {}
    spin = [float(r[5]) for r in atoms]
    for tag, typ, radius, mass, shape, _ in atoms:
        s = float(shape)
        check(s in (0.0, 1.0), f"atom {tag}: shape {shape}")
        name, reach, smass = shape_of[int(s)]
        count[int(s)] += 1
        # The info line prints 6 digits; all atoms of one shape must agree exactly.
        check(abs(float(radius) - reach) <= 1e-5 * reach and abs(float(mass) - smass) <= 1e-5 * smass,
              f"atom {tag} ({name}): radius {radius}, mass {mass}; the shape has {reach} and "
              f"{smass}")
        values.setdefault(int(s), set()).add((radius, mass))
        if mode == "rate_region":
            check(int(typ) == int(s) + 1, f"atom {tag}: type {typ} but shape {name} ('assign type')")
    for s, v in values.items():
        check(len(v) == 1, f"shape {shape_of[s][0]}: its atoms differ in radius or mass: {v}")
    n = len(atoms)
    m_big, m_small = shape_of[0][2], shape_of[1][2]
    mass_big, mass_all = count[0] * m_big, count[0] * m_big + count[1] * m_small
    # Expected number fraction of big particles, and its binomial spread for n particles.
    p_big = (FRACTION_BIG / m_big) / (FRACTION_BIG / m_big + (1 - FRACTION_BIG) / m_small)
    sigma = math.sqrt(n * p_big * (1 - p_big)) if n else 0.0
    frac = mass_big / mass_all if mass_all else float("nan")
    print(f"{mode}: {n} particles, {count[0]} big ({m_big:.4g} kg) and {count[1]} small "
          f"({m_small:.4g} kg): mass fraction of big {frac:.4f} (asked {FRACTION_BIG}); "
          f"{count[0]} big against {n * p_big:.1f} +- {sigma:.1f} expected; inserted mass "
          f"{mass_all:.5g} kg")
    check(abs(count[0] - n * p_big) <= 3 * sigma + 1,
          f"{count[0]} big particles of {n}, expected {n * p_big:.1f} +- {3 * sigma:.1f} (mass "
          f"fraction {frac:.3f} instead of {FRACTION_BIG})")
    if "omega" in m:  # free rotation moves omega about L, but keeps it near the start value
        mean = sum(spin) / len(spin)
        print(f"{mode}: mean omega_z at the end {mean:.4g} rad/s, inserted with {m['omega']}")
        check(abs(mean - m["omega"]) < 0.2 * m["omega"],
              f"mean omega_z {mean}: the insert fix's omega {m['omega']} was lost")
    if "count" in m:
        check(n == m["count"], f"{n} particles inserted, {m['count']} asked")
    if "mass" in m:
        check(abs(mass_all - m["mass"]) <= 2 * m_big,
              f"inserted mass {mass_all} kg, mass_in_region asked {m['mass']} kg")
    print(f"insertion {mode} ({ranks} rank(s)): no intersections in {len(rows)} steps, no "
          f"particle pair within reach at the first insertion (step {first['Step']:.0f}, "
          f"{first['Atoms']:.0f} atoms)")


def test_insert_stream(ctx):
    insertion(ctx, "stream")


def test_insert_pack(ctx):
    insertion(ctx, "pack")


def test_insert_rate_region(ctx):
    insertion(ctx, "rate_region")


def test_insert_stream_ranks(ctx):
    insertion(ctx, "stream", ranks=2)
