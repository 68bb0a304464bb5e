"""What users read: `liggghts-tri -h`, `-screen none`, fix tri/vtk's ParaView frames against a
dump, fix tri/particles' per-atom columns through atom-style variables, and compute tri/erotate
against hand values."""
import os
import subprocess

from decklib import CUBE_SIDE, FLIGHT_PERIODIC, HERE, MPI_ENV, check, cube, last_frame
from decklib import make_contact_meshes, run, run_deck, snapshots, subdir, thermo_rows, write_stl


def test_help(ctx):
    p = subprocess.run([ctx.exe, "-h"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True, errors="replace", timeout=120, env=dict(os.environ, **MPI_ENV))
    for style in ("tri/particles", "tri/nve", "tri/vtk", "tri/gran", "tri/wall", "tri/adapt_dt",
                  "tri/stats"):
        check(style in p.stdout, f"'liggghts-tri -h' does not list {style}")
    check("Pair styles" in p.stdout and "gran" in p.stdout,
          "'liggghts-tri -h' lost LIGGGHTS's own style list")


def test_screen_none(ctx):
    """`-screen none` with a wall: LIGGGHTS 3.8 prints to the screen it was told not to have
    while fix mesh/surface reads the mesh (a segmentation fault in plain liggghts); the driver
    passes /dev/null instead. The deck must run, print nothing and write its dump."""
    make_contact_meshes(ctx.work)
    dump = os.path.join(ctx.work, "contact.dump")
    variables = {"dir": HERE, "zc": repr(CUBE_SIDE / 2 + 5e-5), "vz": "0", "kn": "2000",
                 "kt": "1000", "gamman": "20", "gammat": "10", "mu": "0.5"}
    for flag in ("-screen", "-sc"):
        if os.path.exists(dump):
            os.remove(dump)
        cmd = [ctx.exe, "-in", os.path.join(HERE, "in.contact_wall"), "-log", "none", flag, "none"]
        for k, v in variables.items():
            cmd += ["-var", k, v]
        code, out = run(cmd, ctx.work)
        check(code == 0, f"{' '.join(cmd)} exited {code}:\n{out[-2000:]}")
        check(out.strip() == "", f"{flag} none printed:\n{out[-2000:]}")
        step, rows = last_frame(dump)
        check(step == 0 and set(rows) == {1}, f"{flag} none: dump frame {step}, atoms {sorted(rows)}")


def test_peratom_variable(ctx):
    run_deck(ctx, "in.peratom_variable", dict(FLIGHT_PERIODIC, px=1))
    _, rows = last_frame(os.path.join(ctx.work, "peratom.dump"))
    check(len(rows) == 15, f"{len(rows)} atoms")
    for tag, r in rows.items():
        check(len(r) == 6, f"atom {tag}: {len(r)} columns, expected 6")
        for k in (0, 2, 4):
            check(r[k] == r[k + 1], f"atom {tag}: f_shapes column {r[k]} but variable {r[k + 1]}")
    check(len({r[2] for r in rows.values()}) > 1, "all atoms have the same orientation")


def test_vtk(ctx):
    for ranks in (1, 2):
        sub = subdir(ctx, f"np{ranks}")
        run_deck(sub, "in.vtk_output", dict(FLIGHT_PERIODIC, px=ranks), ranks=ranks)
        ext = "vtp" if ranks == 1 else "pvtp"
        frame = os.path.join(sub.work, "post", f"particles_1000.{ext}")
        check(os.path.exists(frame), f"{frame} was not written")
        pvd = open(os.path.join(sub.work, "post", "particles.pvd")).read()
        for step in (0, 500, 1000):
            check(f"particles_{step}.{ext}" in pvd, f"particles.pvd does not list step {step}")
        p = subprocess.run([ctx.vtkdump, frame], stdout=subprocess.PIPE, text=True, check=True)
        cells = [l.split() for l in p.stdout.splitlines() if l and not l.startswith("#")]
        step, atoms = last_frame(os.path.join(sub.work, "vtk.dump"))
        check(step == 1000 and len(atoms) == 15, f"{ranks} ranks: the dump's last frame is step "
                                                 f"{step} with {len(atoms)} atoms")
        # cells: id shape type vx vy vz wx wy wz fx fy fz
        per_atom = {}
        for c in cells:
            per_atom.setdefault(int(c[0]), []).append(c)
        check(set(per_atom) == set(atoms), "the .vtp particle ids differ from the atoms'")
        ntri = {"0": 20, "1": 40}
        total = sum(ntri[str(int(float(a[6])))] for a in atoms.values())
        check(len(cells) == total, f"{len(cells)} cells, the particles have {total} triangles")
        for tag, cs in per_atom.items():
            a = atoms[tag]
            check(len(cs) == ntri[str(int(float(a[6])))], f"atom {tag} has {len(cs)} cells")
            for c in cs:
                check(int(c[1]) == int(float(a[6])), f"atom {tag}: shape {c[1]} != {a[6]}")
                for k in range(3):
                    check(abs(float(c[3 + k]) - float(a[0 + k])) <= 1e-12 * (1 + abs(float(a[k]))),
                          f"atom {tag}: velocity in .vtp {c[3:6]} != dump {a[0:3]}")
                    check(abs(float(c[6 + k]) - float(a[3 + k])) <= 1e-9 * (1 + abs(float(a[3 + k]))),
                          f"atom {tag}: omega in .vtp {c[6:9]} != dump {a[3:6]}")


# compute tri/erotate: three particles spinning freely (no contacts, no gravity), a cube (side
# 2^-8 m = 3.9 mm, atom 1) and two 40-triangle rocks (atoms 2 and 3, the group `rocks`),
# randomly oriented. A power of two: STL coordinates are single precision, and 0.003 would
# make the cube's inertia (a^5) 4e-8 off the hand value.
EROTATE_SIDE = 2.0 ** -8
EROTATE_DENSITY = 2500.0
EROTATE_OMEGA = {1: (150.0, -220.0, 310.0), 2: (-400.0, 120.0, 90.0), 3: (50.0, 260.0, -330.0)}
EROTATE_TOL = 1e-12

EROTATE_DECK = """\
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


def test_erotate(ctx):
    """compute tri/erotate against hand values. Checked:
      * the cube alone (all minus rocks): 0.5 I |omega|^2 with I = m a^2 / 6, which holds in
        every orientation because a cube's inertia is isotropic;
      * every 100 steps, each compute against 0.5 sum L . omega over its group from a dump of
        the angular momentum (f_shapes[6..8]) and LIGGGHTS's omega, which fix tri/nve keeps
        current;
      * free rotation keeps the energy: NO_SQUISH is symplectic, so its energy error stays
        bounded, of order (omega dt)^2 = 2e-5 here (measured 2e-7 relative over 1000 steps);
        bound 1e-5."""
    write_stl(os.path.join(ctx.work, "cube.stl"), cube(EROTATE_SIDE))
    omegas = "\n".join(f"set atom {t} omegax {w[0]} omegay {w[1]} omegaz {w[2]}"
                       for t, w in EROTATE_OMEGA.items())
    deck = os.path.join(ctx.work, "in.erotate")
    with open(deck, "w") as f:
        f.write(EROTATE_DECK.format(density=EROTATE_DENSITY, omegas=omegas))
    _, out = run_deck(ctx, deck, timeout=300)
    thermo = {int(r["Step"]): (r["erot"], r["erock"]) for r in thermo_rows(out)}
    frames = {step: {t: [float(x) for x in r] for t, r in rows.items()}
              for step, rows in snapshots(os.path.join(ctx.work, "spin.dump"))}
    check(sorted(thermo) == list(range(0, 1001, 100)) and sorted(frames) == sorted(thermo),
          f"thermo steps {sorted(thermo)}, dump steps {sorted(frames)}")
    for s, rows in frames.items():
        check(set(rows) == {1, 2, 3} and all(len(r) == 7 for r in rows.values()),
              f"step {s}: the dump holds atoms {sorted(rows)}, expected 1, 2, 3 with 7 columns")

    def rel(x, y):
        return abs(x - y) / abs(y)

    mass = EROTATE_DENSITY * EROTATE_SIDE ** 3
    w = EROTATE_OMEGA[1]
    cube_hand = 0.5 * (mass * EROTATE_SIDE ** 2 / 6.0) * sum(c * c for c in w)
    all0, rocks0 = thermo[0]
    cube_e = all0 - rocks0
    print(f"cube: compute {cube_e!r} J, hand 0.5 (m a^2/6) |w|^2 = {cube_hand!r} J, "
          f"relative {rel(cube_e, cube_hand):.2g}")
    check(rel(cube_e, cube_hand) <= EROTATE_TOL, f"cube: {cube_e} != {cube_hand}")
    worst = 0.0
    for s, rows in sorted(frames.items()):
        half_l_w = {t: 0.5 * sum(r[1 + d] * r[4 + d] for d in range(3)) for t, r in rows.items()}
        hand_all = sum(half_l_w.values())
        hand_rocks = sum(v for t, v in half_l_w.items() if rows[t][0] == 2)
        e_all, e_rocks = thermo[s]
        for what, got, hand in (("all", e_all, hand_all), ("rocks", e_rocks, hand_rocks)):
            worst = max(worst, rel(got, hand))
            check(rel(got, hand) <= EROTATE_TOL,
                  f"step {s}, group {what}: compute {got!r}, 0.5 L.w {hand!r}")
    print(f"against 0.5 sum L . omega of the dump: largest relative difference {worst:.2g}")
    drift = max(rel(v[0], thermo[0][0]) for v in thermo.values())
    print(f"free rotation, 1000 steps: rotational energy {thermo[0][0]!r} J, largest "
          f"relative change {drift:.2g}")
    check(drift <= 1e-5, f"free rotation changed the energy by {drift:.3g} relative")
