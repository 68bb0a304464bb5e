"""read_restart with a deck whose fix tri/particles differs from the run that wrote the file
(src_plugin/liggghts/restart_shapes.h): epsilon, density, the number of shapes, a shape's
triangles or geometry, the order of the shapes, and a restart file without the shape record
(as written before it existed) must each stop with an ERROR saying exactly what differs; the
same deck must continue."""
import os
import re
import struct

from decklib import Failure, check, expect_error, last_frame, run_deck
from style_decks import BASE, PAIR, resumed_base, write_files

ROCK20 = "shape rock20 random ntri 20 size 0.004 seed 7"
ROCK40 = "shape rock40 random ntri 40 size 0.004 seed 8"
BLOCK = "shape block file cube.stl"
TAIL = "assign random 4242 orient random 99"
ORIGINAL = f"{ROCK20} {ROCK40} {BLOCK} {TAIL} density 2500 epsilon 0.0001"
# cube.stl: a cube of side 2^-9 m; slab.stl: a 2^-8 x 2^-9 x 2^-10 m box, the same volume
# (exactly: the sides are powers of two) and triangle count, another bounding radius and
# other moments.
CUBE = (2.0 ** -9, 2.0 ** -9, 2.0 ** -9)
SLAB = (2.0 ** -8, 2.0 ** -9, 2.0 ** -10)

WRITE = """\
units           si
atom_style      sphere
atom_modify     map array sort 0 0.0
boundary        f f f
newton          off
communicate     single vel yes
region          box block -0.02 0.02 -0.02 0.02 -0.02 0.02 units box
create_box      1 box
neighbor        0.001 bin
neigh_modify    delay 0
timestep        1e-5
create_atoms    1 single -0.006 0.0 0.0 units box
create_atoms    1 single 0.0 0.0 0.0 units box
create_atoms    1 single 0.006 0.0 0.0 units box
fix shapes all tri/particles {particles}
velocity        all set 0.1 0.0 0.0 units box
fix integr all tri/nve
run 10
write_restart   mismatch.restart
"""

READ = """\
read_restart    {restart}
atom_modify     sort 0 0.0
timestep        1e-5
newton          off
communicate     single vel yes
neighbor        0.001 bin
neigh_modify    delay 0
fix shapes all tri/particles {particles}
fix integr all tri/nve
run 10
"""

# Volumes and the number format come from the run itself: the patterns only fix the words
# and the values the deck sets.
G = r"[0-9.e+-]+"
CASES = {
    "epsilon": (f"{ROCK20} {ROCK40} {BLOCK} {TAIL} density 2500 epsilon 0.0002",
                r"this deck differs from the run that wrote the restart file: epsilon 0\.0001 in "
                r"the restart file, 0\.0002 in this deck$"),
    "density": (f"{ROCK20} {ROCK40} {BLOCK} {TAIL} density 2600 epsilon 0.0001",
                r": density 2500 in the restart file, 2600 in this deck$"),
    "epsilon_and_density": (f"{ROCK20} {ROCK40} {BLOCK} {TAIL} density 2500.5 epsilon 0.00011",
                            r": epsilon 0\.0001 in the restart file, 0\.00011 in this deck; "
                            r"density 2500 in the restart file, 2500\.5 in this deck$"),
    "triangles": (f"{ROCK20} shape rock40 random ntri 20 size 0.004 seed 8 {BLOCK} {TAIL} "
                  f"density 2500 epsilon 0.0001",
                  rf": shape 2 'rock40': 40 triangles, volume {G} m\^3 in the restart file; "
                  rf"'rock40': 20 triangles, volume {G} m\^3 in this deck$"),
    "geometry": (f"shape rock20 random ntri 20 size 0.004 seed 17 {ROCK40} {BLOCK} {TAIL} "
                 f"density 2500 epsilon 0.0001",
                 rf": shape 1 'rock20': 20 triangles, volume ({G}) m\^3 in the restart file; "
                 rf"'rock20': 20 triangles, volume (?!\1 )({G}) m\^3 in this deck$"),
    # the same name, triangle count and volume: what is left to tell them apart is printed
    "same_volume": (f"{ROCK20} {ROCK40} shape block file slab.stl {TAIL} density 2500 "
                    f"epsilon 0.0001",
                    rf": shape 3 'block': 12 triangles, volume ({G}) m\^3, bounding radius "
                    rf"({G}) m, principal moments per density {G} {G} {G} m\^5 in the restart "
                    rf"file; 'block': 12 triangles, volume \1 m\^3, bounding radius (?!\2 )"
                    rf"{G} m, principal moments per density {G} {G} {G} m\^5 in this deck$"),
    "more_shapes": (f"{ROCK20} {ROCK40} {BLOCK} shape extra random ntri 30 size 0.004 seed 9 "
                    f"{TAIL} density 2500 epsilon 0.0001",
                    r": 3 shapes in the restart file \(rock20, rock40, block\), 4 in this deck "
                    r"\(rock20, rock40, block, extra\)$"),
    "fewer_shapes": (f"{ROCK20} {TAIL} density 2500 epsilon 0.0001",
                     r": 3 shapes in the restart file \(rock20, rock40, block\), 1 in this deck "
                     r"\(rock20\)$"),
    "order": (f"{ROCK40} {ROCK20} {BLOCK} {TAIL} density 2500 epsilon 0.0001",
              rf": shape 1 'rock20': 20 triangles, .* in the restart file; 'rock40': 40 "
              rf"triangles, .* in this deck; shape 2 'rock40': 40 triangles, .* in the restart "
              rf"file; 'rock20': 20 triangles, .* in this deck$"),
    "renamed": (f"shape pebble random ntri 20 size 0.004 seed 7 {ROCK40} {BLOCK} {TAIL} "
                f"density 2500 epsilon 0.0001",
                rf": shape 1 'rock20': 20 triangles, volume ({G}) m\^3 in the restart file; "
                rf"'pebble': 20 triangles, volume \1 m\^3 in this deck$"),
    "layer_outside_file": (ORIGINAL,
                           r"the soft layer 'layer outside' in the restart file \(every file "
                           r"before the layer moved inside\), 'layer inside' in this deck \(give "
                           r"fix tri/particles 'layer outside' to continue it\)"),
    "old_file": (ORIGINAL,
                 r"Fix tri/particles: the restart file was written by an earlier liggghts-tri, "
                 r"whose restart files carry no shape record and cannot be read by this "
                 r"version: rerun the deck that wrote it$"),
}


def write_box(path, sides):
    """A closed box [0, a] x [0, b] x [0, c], triangles counter-clockwise seen from outside."""
    v = [(x * sides[0], y * sides[1], z * sides[2]) for x in (0, 1) for y in (0, 1)
         for z in (0, 1)]
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    with open(path, "w") as f:
        f.write("solid box\n")
        for p, q, r, t in faces:
            for tri in ((p, q, r), (p, r, t)):
                f.write(" facet normal 0 0 0\n  outer loop\n")
                for k in tri:
                    f.write("   vertex %r %r %r\n" % v[k])
                f.write("  endloop\n endfacet\n")
        f.write("endsolid box\n")


def write_deck(work, name, text):
    deck = os.path.join(work, f"in.{name}")
    with open(deck, "w") as f:
        f.write(text)
    return deck


def test_restart_mismatch(ctx):
    work = ctx.work
    write_box(os.path.join(work, "cube.stl"), CUBE)
    write_box(os.path.join(work, "slab.stl"), SLAB)
    run_deck(ctx, write_deck(work, "write", WRITE.format(particles=ORIGINAL)), timeout=300)
    # The same file with its record's magic overwritten: what this version sees in a restart
    # file of the earlier format (three doubles, no magic).
    with open(os.path.join(work, "mismatch.restart"), "rb") as f:
        data = f.read()
    check(data.count(b"tri/rst3") == 1, "the restart file does not hold one shape record")
    with open(os.path.join(work, "old.restart"), "wb") as f:
        f.write(data.replace(b"tri/rst3", b"\0" * 8))
    # The record as written before the layer field (magic tri/rst2, no int64 after epsilon and
    # density): every such file's layer lay outside the meshes.
    at = data.index(b"tri/rst3")
    size = struct.unpack("<i", data[at - 4:at])[0]
    rst2 = (data[:at - 4] + struct.pack("<i", size - 8) + b"tri/rst2" + data[at + 8:at + 24] +
            data[at + 32:])
    with open(os.path.join(work, "outside.restart"), "wb") as f:
        f.write(rst2)
    _, out = run_deck(ctx, write_deck(work, "outside", READ.format(
        restart="outside.restart", particles=ORIGINAL + " layer outside")), timeout=300)
    check("ERROR" not in out, f"a tri/rst2 file read with 'layer outside': {out[-1500:]}")
    print("tri/rst2 file, layer outside: continues")

    _, out = run_deck(ctx, write_deck(work, "same", READ.format(restart="mismatch.restart",
                                                                 particles=ORIGINAL)),
                      timeout=300)
    check("ERROR" not in out, f"same deck: {out[-1500:]}")
    print("same deck: continues")
    check(CASES, "no cases")
    failures = []
    for name, (particles, pattern) in CASES.items():
        restart = {"old_file": "old.restart", "layer_outside_file": "outside.restart"}.get(
            name, "mismatch.restart")
        deck = write_deck(work, name, READ.format(restart=restart, particles=particles))
        try:
            line = expect_error(ctx, deck, {}, pattern)
            check(re.search(pattern, line), f"the first error {line!r} is not /{pattern}/")
            print(f"{name}: {line}")
        except Failure as e:
            failures.append(f"{name}: {e}")
    check(not failures, "\n".join(failures))
    print(f"{len(CASES)} differences named, the same deck continues")


def test_restarts_continue_the_run(ctx):
    """A deck with `epsilon auto` (the default) continues from its restart file: the restart
    keeps the layer the run resolved (and says so), and 10 steps after it give the bits of one
    run of 20 steps, from a file written between two runs (write_restart) and from one written
    during the run (`restart 10`: pair tri/gran's contact history is brought up to date for
    it)."""
    base = BASE.format(atom_style="sphere", pair_style=PAIR)
    check("epsilon" not in base, "the base deck gives an epsilon: it must leave it to auto")
    dump = ("dump d all custom 10 {name}.dump id x y z vx vy vz omegax omegay omegaz "
            "f_shapes[1] f_shapes[2] f_shapes[3] f_shapes[4]\n"
            "dump_modify d sort id format \"%d" + " %.17g" * 13 + "\"\n")
    decks = {"in.whole": base + dump.format(name="whole") + "restart 10 during\nrun 20\n",
             "in.first": base + "run 10\nwrite_restart s.restart\n",
             "in.resumed": resumed_base("s.restart") + dump.format(name="resumed") + "run 10\n",
             "in.during": resumed_base("during.10") + dump.format(name="during") + "run 10\n"}
    write_files(ctx.work)
    outputs = {}
    for name, text in decks.items():
        with open(os.path.join(ctx.work, name), "w") as f:
            f.write(text)
        _, outputs[name] = run_deck(ctx, os.path.join(ctx.work, name))
    eps = re.findall(r"epsilon auto = (\S+) m", outputs["in.first"])
    check(eps, "the first run printed no 'epsilon auto'")
    whole = last_frame(os.path.join(ctx.work, "whole.dump"))
    check(whole[0] == 20, f"the whole run's last frame is at step {whole[0]}")
    for name in ("resumed", "during"):
        check(f"epsilon auto = {eps[-1]} m, as in the restart file" in outputs[f"in.{name}"],
              f"in.{name} did not take epsilon {eps[-1]} from the restart file")
        again = last_frame(os.path.join(ctx.work, f"{name}.dump"))
        check(again[0] == 20, f"in.{name}'s last frame is at step {again[0]}")
        check(whole[1] == again[1], f"in.{name} differs from the whole run at step 20")
