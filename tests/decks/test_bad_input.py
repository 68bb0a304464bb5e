"""Bad input: each case is a deck that must stop with a LIGGGHTS error naming the problem (the
file or the keyword), never a crash and never a run: fix tri/particles and its meshes, the
contact styles, the orientation and insertion keywords. Every case goes through
decklib.expect_error; a test reports all failing cases at once."""
import os

from decklib import ROCK, TAIL, TOO_LARGE, Failure, check, cube, expect_error, run_deck
from decklib import make_contact_meshes, tetra, write_stl


def make_bad_meshes(work):
    t = tetra()
    write_stl(os.path.join(work, "open.stl"), cube()[:-1])
    write_stl(os.path.join(work, "flipped.stl"), [t[0], t[1], t[2], [t[3][0], t[3][2], t[3][1]]])
    write_stl(os.path.join(work, "inverted.stl"), [[x[0], x[2], x[1]] for x in t])
    a, b = (0, 0, 0), (0.002, 0, 0)
    write_stl(os.path.join(work, "degenerate.stl"), t[:3] + [[a, b, (0.001, 0, 0)]])
    write_stl(os.path.join(work, "nan.stl"), [[("nan", 0, 0)] + t[0][1:]] + t[1:])
    with open(os.path.join(work, "garbage.stl"), "w") as f:
        f.write("solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0\n")
    with open(os.path.join(work, "truncated.stl"), "wb") as f:
        f.write(b"\0" * 80 + (1000).to_bytes(4, "little") + b"\0" * 60)


def expect_errors(ctx, cases):
    """cases: {name: (deck, variables, pattern)}. Runs every case through expect_error and fails
    once, listing every case that did not stop with its error."""
    check(cases, "no cases")
    failures = []
    for name, (deck, variables, pattern) in sorted(cases.items()):
        try:
            print(f"{name}: {expect_error(ctx, deck, variables, pattern)}")
        except Failure as e:
            failures.append(f"{name}: {e}")
    check(not failures, "\n".join(failures))


# fix tri/particles arguments of in.bad_particles -> the error they must give
BAD_PARTICLES = {
    "missing_file": (f"shape m file nosuch.stl {TAIL}", r"nosuch\.stl"),
    "garbage_file": (f"shape m file garbage.stl {TAIL}", r"garbage\.stl"),
    "truncated_file": (f"shape m file truncated.stl {TAIL}", r"truncated\.stl"),
    "unknown_extension": (f"shape m file mesh.xyz {TAIL}", r"mesh\.xyz"),
    "open_mesh": (f"shape m file open.stl {TAIL}", r"open\.stl.*not closed"),
    "flipped_mesh": (f"shape m file flipped.stl {TAIL}", r"flipped\.stl.*orient"),
    "inverted_mesh": (f"shape m file inverted.stl {TAIL}", r"inverted\.stl.*(inverted|inward|negative)"),
    "degenerate_mesh": (f"shape m file degenerate.stl {TAIL}", r"degenerate\.stl.*degenerate"),
    "nan_mesh": (f"shape m file nan.stl {TAIL}", r"nan\.stl.*(NaN|finite|nan)"),
    "odd_ntri": (f"shape r random ntri 21 size 0.004 seed 1 {TAIL}", r"ntri.*even"),
    "small_ntri": (f"shape r random ntri 2 size 0.004 seed 1 {TAIL}", r"ntri"),
    "zero_epsilon": (f"{ROCK} density 2500 epsilon 0", r"epsilon.*> 0"),
    "negative_density": (f"{ROCK} density -1 epsilon 0.0001", r"density.*> 0"),
    "unknown_keyword": (f"{ROCK} {TAIL} colour red", r"unknown keyword 'colour'"),
    "missing_epsilon": (f"{ROCK} density 2500", r"'epsilon' is required"),
    "no_shape": (TAIL, r"at least one 'shape'"),
    "too_large": (TOO_LARGE, r"does not fit"),
    "layer_too_thick": ("shape r random ntri 20 size 0.004 seed 1 density 2500 epsilon 0.0015",
                        r"shape 'r': the surface offset inward by the soft layer \(epsilon 0\.0015 "
                        r"m\) is not valid: .*; epsilon \S+ m would fit \(or 'layer outside'"),
    "bad_layer": (f"{ROCK} {TAIL} layer sideways", r"'layer' expects 'inside' or 'outside', got 'sideways'"),
}
# whole decks -> the error they must give
BAD_DECKS = {
    "nve_without_particles": ("in.bad_nve", r"tri/nve requires fix tri/particles"),
    "vtk_without_particles": ("in.bad_vtk", r"tri/vtk requires fix tri/particles"),
    "atom_style_without_radius": ("in.bad_atom_style", r"requires atom_style sphere"),
}


def test_bad_input(ctx):
    make_bad_meshes(ctx.work)
    cases = {k: ("in.bad_particles", {"args": a}, p) for k, (a, p) in BAD_PARTICLES.items()}
    cases.update({k: (deck, {}, p) for k, (deck, p) in BAD_DECKS.items()})
    for name, dt in (("zero_timestep", "0"), ("negative_timestep", "-2.5")):
        cases[name] = ("in.bad_timestep", {"dt": dt},
                       r"tri/nve: the time step must be a positive number, got " + dt + " s")
    expect_errors(ctx, cases)


# in.contact_bad with one line swapped through a variable -> the error it must give
BAD_CONTACT = {
    "pair_without_particles": ({"particles": "variable nothing equal 0"},
                               r"Pair tri/gran requires fix tri/particles"),
    "missing_kt": ({"ktname": "ktx"},
                   r"Could not locate a fix/property storing value\(s\) for kt "),
    "wall_not_a_mesh": ({"wall": "fix walls all tri/wall mesh grav"},
                        r"tri/wall: fix 'grav' is not a fix mesh/surface"),
    "wall_unknown_id": ({"wall": "fix walls all tri/wall mesh nosuch"},
                        r"tri/wall: 'mesh' must name at least one fix mesh/surface, got 'nosuch'"),
    "adapt_dt_min_above_max": ({"extra": "fix adt all tri/adapt_dt dtmax 1e-6 dtmin 1e-5"},
                               r"tri/adapt_dt: dtmin must not exceed dtmax"),
    "pair_unknown_keyword": ({"pairstyle": "tri/gran colour red"},
                             r"Pair tri/gran: unknown keyword 'colour'"),
    "pair_bad_kernel": ({"pairstyle": "tri/gran kernel fast"},
                        r"Pair tri/gran: 'kernel' expects bf, penalty, hybrid or batched, got 'fast'"),
    "pair_newton_iters": ({"pairstyle": "tri/gran newton_iters 9"},
                          r"'newton_iters 9' is not one of the compiled iteration counts"),
    "pair_bad_coherence": ({"pairstyle": "tri/gran coherence 0"},
                           r"Pair tri/gran: 'coherence' expects no or a reach in \(0, 10\] times "
                           r"the contact cutoff, got '0'"),
    "wall_bad_coherence": ({"wall": "fix walls all tri/wall mesh cad coherence soon"},
                           r"tri/wall: 'coherence' expects no or a reach in \(0, 10\] times "
                           r"the contact cutoff, got 'soon'"),
    "pair_bad_keep_contacts": ({"pairstyle": "tri/gran keep_contacts 0.5"},
                               r"Pair tri/gran: 'keep_contacts' expects no or a tolerance in "
                               r"\(0, 0.01\] times the combined soft layer, got '0.5'"),
    "wall_bad_keep_contacts": ({"wall": "fix walls all tri/wall mesh cad keep_contacts yes"},
                               r"tri/wall: 'keep_contacts' expects no or a tolerance in "
                               r"\(0, 0.01\] times the combined soft layer, got 'yes'"),
    "pair_newton_on": ({"newton": "on off"},
                       r"Pair granular with shear history requires newton pair off"),
}


def test_bad_contact_input(ctx):
    make_contact_meshes(ctx.work)
    # The deck with no line swapped runs: each error below comes from its one changed line.
    run_deck(ctx, "in.contact_bad")
    expect_errors(ctx, {k: ("in.contact_bad", v, p) for k, (v, p) in BAD_CONTACT.items()})


# Orientation and insertion (fix tri/particles `orient file`, `template ID SHAPE`,
# particletemplate/sphere, particledistribution/discrete): decks written here -> the error
# they must give (the rows of tests/bad_input.md).
INSERTION_HEAD = """\
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
INSERTION_SHAPES = "shape a random ntri 20 size 0.004 seed 1 shape b random ntri 20 size 0.003 seed 2"
INSERTION_PTS1 = ("fix pts1 all particletemplate/sphere 15485863 atom_type {t} density constant 2500 "
        "radius constant 0.002\n")
INSERTION_PDD = "fix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"


def particles(extra):
    return f"fix shapes all tri/particles {INSERTION_SHAPES} {extra} {TAIL}\n"


BAD_INSERTION = {
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
    "template_without_shape": (particles("assign random 5") + INSERTION_PTS1.format(t=1),
                               r"fix particletemplate/sphere pts1 has no shape: with 'assign "
                               r"random' and 2 shapes, give it one with 'template pts1 SHAPE'"),
    "template_type_without_shape": (INSERTION_PTS1.format(t=3) + particles("assign type"),
                                    r"fix particletemplate/sphere pts1 inserts atom type 3, but "
                                    r"'assign type' has 2 shape\(s\)"),
    "distribution_before_particles": (INSERTION_PTS1.format(t=1) + INSERTION_PDD + particles("template pts1 a"),
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


def test_bad_insertion_input(ctx):
    cases = {}
    for name, (body, pattern) in BAD_INSERTION.items():
        path = os.path.join(ctx.work, f"in.{name}")
        with open(path, "w") as f:
            f.write(INSERTION_HEAD + body)
        cases[name] = (path, {}, pattern)
    expect_errors(ctx, cases)
