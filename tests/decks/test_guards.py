"""LIGGGHTS sphere styles next to fix tri/particles (src_plugin/liggghts/incompatible_styles.h):
each case is a small deck of two rocks above a wall in which one line of a LIGGGHTS sphere deck
is kept; it must stop before its first step with an ERROR that names the style, its ID and the
tri/ replacement. A last deck keeps the lines of a sphere deck that must stay allowed (gravity,
materials, mesh/surface with move/mesh, freeze, insertion, thermo computes, dumps) and must
run."""
import os
import re

from decklib import Failure, check, expect_error, run_deck, thermo_rows

HEAD = """\
units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
newton          off
communicate     single vel yes
region          box block -0.02 0.02 -0.02 0.02 -0.01 0.03 units box
create_box      1 box
neighbor        0.001 bin
neigh_modify    delay 0
timestep        1e-5
create_atoms    1 single -0.004 0.0 0.005 units box
create_atoms    1 single 0.004 0.0 0.006 units box
fix shapes all tri/particles shape r random ntri 20 size 0.004 seed 7 &
    density 2500 epsilon 0.0001 orient random 99
fix m1 all property/global kn peratomtypepair 1 2000
fix m2 all property/global kt peratomtypepair 1 1000
fix m3 all property/global gamman peratomtypepair 1 20
fix m4 all property/global gammat peratomtypepair 1 10
fix m5 all property/global coefficientFriction peratomtypepair 1 0.5
fix grav all gravity 9.81 vector 0.0 0.0 -1.0
fix cad all mesh/surface file plane.stl type 1
"""
PAIR = "pair_style tri/gran\npair_coeff * *\n"
WALL = "fix walls all tri/wall mesh cad\n"
NVE = "fix integr all tri/nve\n"
TAIL = "thermo 10\nrun 20\n"

# name: (deck body after HEAD, pattern the ERROR line must match)
CASES = {
    "nve_sphere": (PAIR + WALL + "fix integr all nve/sphere\n",
                   r"fix nve/sphere \(ID integr\) cannot work with triangulated particles: it "
                   r"integrates spheres.*use fix tri/nve"),
    "nve": (PAIR + WALL + "fix integr all nve\n",
            r"fix nve \(ID integr\) cannot work.*translation only.*use fix tri/nve"),
    "nve_beside_tri_nve": (PAIR + WALL + NVE + "fix twice all nve\n",
                           r"fix nve \(ID twice\).*would move twice.*use fix tri/nve"),
    "nve_limit": (PAIR + WALL + "fix integr all nve/limit absolute 0.001\n",
                  r"fix nve/limit \(ID integr\).*use fix tri/nve, and fix tri/adapt_dt"),
    "move": (PAIR + WALL + "fix integr all move linear 0.0 0.0 -0.1\n",
             r"fix move \(ID integr\).*fix move/mesh, with fix tri/wall"),
    "wall_gran_primitive": (
        PAIR + NVE + "fix zwall all wall/gran model hooke/stiffness tangential history "
                     "primitive type 1 zplane 0.0\n",
        r"fix wall/gran \(ID zwall\) cannot work.*spheres of the bounding radius.*use fix "
        r"tri/wall mesh MESH_ID with a fix mesh/surface"),
    "wall_gran_mesh": (
        PAIR + NVE + "fix granwalls all wall/gran model hooke/stiffness tangential history "
                     "mesh n_meshes 1 meshes cad\n",
        r"fix wall/gran \(ID granwalls\).*use fix tri/wall"),
    "pair_gran": ("pair_style gran model hooke/stiffness tangential history\npair_coeff * *\n"
                  + WALL + NVE,
                  r"pair_style gran cannot work.*spheres of the contact reach.*use pair_style "
                  r"tri/gran model hooke\|hertz\|hooke/stiffness \(the same fix property/global "
                  r"materials as pair gran\)"),
    "pair_hybrid": ("pair_style hybrid/overlay tri/gran soft 0.001\npair_coeff * * tri/gran\n"
                    "pair_coeff * * soft 1.0\n" + WALL + NVE,
                    r"pair_style hybrid/overlay \(sub-styles tri/gran, soft\).*use pair_style "
                    r"tri/gran alone"),
    "pair_soft": ("pair_style soft 0.001\npair_coeff * * 1.0\n" + WALL + NVE,
                  r"pair_style soft cannot work.*use pair_style tri/gran"),
    "compute_erotate_sphere": (PAIR + WALL + NVE + "compute rke all erotate/sphere\n"
                               "thermo_style custom step ke c_rke\n",
                               r"compute erotate/sphere \(ID rke\) cannot work.*inertia of a "
                               r"sphere.*use compute tri/erotate"),
    "compute_erotate": (PAIR + WALL + NVE + "compute rke all erotate\n",
                        r"compute erotate \(ID rke\).*use compute tri/erotate"),
    "compute_erotate_sphere_atom": (
        PAIR + WALL + NVE + "compute rka all erotate/sphere/atom\n",
        r"compute erotate/sphere/atom \(ID rka\).*per atom the variable "
        r"0\.5\*\(f_shapes\[6\]\*omegax\+f_shapes\[7\]\*omegay\+f_shapes\[8\]\*omegaz\)"),
    "compute_contact_atom": (PAIR + WALL + NVE + "compute c all contact/atom\n",
                             r"compute contact/atom \(ID c\).*use compute tri/contact/atom"),
    "check_timestep_gran": (PAIR + WALL + NVE + "fix ts all check/timestep/gran 10 0.1 0.1\n",
                            r"fix check/timestep/gran \(ID ts\).*use the time-step check of fix tri/particles "
                            r"\(check_timestep setup\|N, on at every run by default\) and fix tri/adapt_dt"),
}

# The lines of a sphere deck that carry over: all of HEAD (gravity, property/global,
# mesh/surface), and these (insertion: the inserted spheres become rocks at their first step).
ALLOWED = (PAIR + "fix mover all move/mesh mesh cad linear 0.0 0.0 0.01\n" + WALL + NVE
           + "region top block -0.015 0.015 -0.015 0.015 0.012 0.028 units box\n"
           + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 "
             "radius constant 0.0021\n"
           + "fix pdd1 all particledistribution/discrete 15485867 1 pts1 1.0\n"
           + "fix ins all insert/pack seed 32452843 distributiontemplate pdd1 insert_every once "
             "overlapcheck yes all_in yes particles_in_region 6 region top\n"
           + "group second id 2\nfix hold second freeze\n"
           + "compute erot all tri/erotate\ncompute stats all tri/stats\n"
           + "compute rad all property/atom radius\n"
           + "thermo_style custom step atoms ke c_erot c_stats[${stat_pairs_checked}]\n"
           + "dump d all custom 10 allowed.dump id x y z vx vy vz omegax omegay omegaz c_rad\n")


def write_plane(path, half=0.015):
    with open(path, "w") as f:
        f.write("solid plane\n")
        a, b, c, d = (-half, -half, 0), (half, -half, 0), (half, half, 0), (-half, half, 0)
        for tri in ((a, b, c), (a, c, d)):
            f.write(" facet normal 0 0 1\n  outer loop\n")
            for p in tri:
                f.write("   vertex %r %r %r\n" % p)
            f.write("  endloop\n endfacet\n")
        f.write("endsolid plane\n")


def write_deck(work, name, body):
    deck = os.path.join(work, f"in.{name}")
    with open(deck, "w") as f:
        f.write(HEAD + body + TAIL)
    return deck


def test_guards(ctx):
    write_plane(os.path.join(ctx.work, "plane.stl"))
    check(CASES, "no cases")
    failures = []
    for name, (body, pattern) in CASES.items():
        try:
            line, out = expect_error(ctx, write_deck(ctx.work, name, body), {}, pattern,
                                     with_output=True)
            check(re.search(pattern, line), f"the first error {line!r} is not /{pattern}/")
            check(not any(l.split()[:1] == ["Step"] for l in out.splitlines()),
                  "the run started before the error")
            print(f"{name}: {line}")
        except Failure as e:
            failures.append(f"{name}: {e}")
    check(not failures, "\n".join(failures))
    _, out = run_deck(ctx, write_deck(ctx.work, "allowed", ALLOWED), timeout=300)
    check("ERROR" not in out, f"allowed: {out[-2000:]}")
    atoms = [int(r["Atoms"]) for r in thermo_rows(out)]
    check(atoms and atoms[-1] == 8, f"allowed: atom counts {atoms} in thermo, expected 2 + 6 "
                                    "inserted")
    print("allowed: gravity, property/global, mesh/surface, move/mesh, freeze, "
          "particletemplate/sphere, particledistribution/discrete, insert/pack, tri/ styles, "
          f"property/atom, thermo and dump custom run (8 atoms); {len(CASES)} refusals")
