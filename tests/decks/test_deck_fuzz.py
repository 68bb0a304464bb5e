"""Deck-level fuzzing: random but well-formed decks for the plugin's styles, each run briefly.

Every deck draws, from a fixed seed, the keywords and values of fix tri/particles, pair
tri/gran, fix tri/wall (on a mesh/surface floor), fix tri/adapt_dt, fix tri/vtk, compute
tri/stats, tri/contact/local and tri/contact/atom, a material (hooke/stiffness, hooke or hertz),
the box's periodicity, the time step and a handful of particles at random places (overlapping
ones included, and some thrown at the floor). A third of the decks carry one invalid value or
word (zero, negative, out of range, not a number, an unknown word). Each deck must either run its
steps with finite thermo output and every particle kept, or stop with a LIGGGHTS ERROR: never a
signal, never a hang (60 s), never NaN. A failure prints the deck, so it can be rerun by hand.

FUZZ_DECKS=N and FUZZ_SEED=S (environment) run more or other decks; CI runs 24 from seed 1."""
import math
import os
import random
import re

from decklib import CRASH_WORDS, Failure, check, run

PLANE = """solid floor
 facet normal 0 0 1
  outer loop
   vertex -0.02 -0.02 0
   vertex 0.02 -0.02 0
   vertex 0.02 0.02 0
  endloop
 endfacet
 facet normal 0 0 1
  outer loop
   vertex -0.02 -0.02 0
   vertex 0.02 0.02 0
   vertex -0.02 0.02 0
  endloop
 endfacet
endsolid floor
"""
BAD_VALUES = ["0", "-1", "1e300", "nan", "xyz", "-0.5"]
LOCAL_VALUES = ["pos", "vel", "id", "force", "force_normal", "force_tangential", "torque",
                "contactArea", "delta", "contactPoint", "normal", "kind"]


class Draw:
    """Random choices. A third of the decks get one invalid value or word, at a random one of
    their draws; the rest are valid throughout."""

    def __init__(self, rng):
        self.rng = rng
        self.bad = 0
        self.calls = 0
        self.bad_at = rng.randint(0, 30) if rng.random() < 1 / 3 else -1

    def _spoil(self):
        self.calls += 1
        if self.calls - 1 == self.bad_at:
            self.bad += 1
            return True
        return False

    def value(self, lo, hi, log=True):
        if self._spoil():
            return self.rng.choice(BAD_VALUES)
        x = math.exp(self.rng.uniform(math.log(lo), math.log(hi))) if log else \
            self.rng.uniform(lo, hi)
        return "%.4g" % x

    def word(self, *choices):
        if self._spoil():
            return "bogus"
        return self.rng.choice(choices)

    def maybe(self, p=0.5):
        return self.rng.random() < p


def particles_fix(d, types):
    shapes = []
    for k in range(types):
        if d.maybe(0.7):
            s = f"shape s{k} random ntri {d.rng.choice([8, 12, 20, 40])} size {d.value(2e-3, 5e-3)} " \
                f"seed {d.rng.randint(1, 99)}"
            if d.maybe(0.3):
                s += f" aspect {d.value(0.5, 1, False)} {d.value(0.3, 0.6, False)}"
        else:
            s = f"shape s{k} file cube.stl scale {d.value(0.5, 2)}"
        shapes.append(s)
    words = shapes + [d.word("assign type", "assign random 7")]
    words.append(f"density {d.value(500, 8000)}")
    words.append("epsilon auto" if d.maybe(0.4) else f"epsilon {d.value(2e-5, 3e-4)}")
    words.append(d.word("orient none", "orient file", f"orient random {d.rng.randint(1, 9)}"))
    if d.maybe(0.3):
        words.append(d.word("layer inside", "layer outside"))
    if d.maybe(0.3):
        words.append(d.word("check_timestep setup", "check_timestep off", "check_timestep 10"))
    return "fix shapes all tri/particles " + " ".join(words)


def contact_keywords(d):
    options = [
        lambda: "kernel " + d.word("bf", "penalty", "hybrid", "batched"),
        lambda: "newton_iters " + d.value(1, 8, False).split(".")[0],
        lambda: "batch " + d.word("4", "8", "16"),
        lambda: "parallel " + d.word("pairs", "triangles", "batches", "none"),
        lambda: "cull " + d.word("yes", "boxes", "no"),
        lambda: "separation " + d.word("yes", "no"),
        lambda: "coherence " + (d.value(0.01, 0.5) if d.maybe() else "no"),
        lambda: "keep_contacts " + (d.value(1e-5, 1e-3) if d.maybe() else "no"),
        lambda: "reduction " + d.word("clusters", "paper", "none"),
        lambda: "tangential " + d.word("history", "no_history"),
        lambda: "absolute_damping " + d.word("on", "off"),
        lambda: "tangential_damping " + d.word("on", "off"),
    ]
    return " ".join(f() for f in d.rng.sample(options, d.rng.randint(0, 4)))


def material(d, model, types):
    n = f"peratomtypepair {types}"
    pairs = lambda v: " ".join([v] * types * types)
    each = lambda v: " ".join([v] * types)
    if model == "hooke/stiffness":
        kn = d.value(500, 1e5)
        return "\n".join([
            f"fix m1 all property/global kn {n} {pairs(kn)}",
            f"fix m2 all property/global kt {n} {pairs(kn)}",
            f"fix m3 all property/global gamman {n} {pairs('20')}",
            f"fix m4 all property/global gammat {n} {pairs('10')}",
            f"fix m5 all property/global coefficientFriction {n} {pairs('0.5')}"])
    e = d.value(1e5, 1e8)
    cor = d.value(0.2, 0.95, False)
    return "\n".join([
        f"fix m1 all property/global youngsModulus peratomtype {each(e)}",
        f"fix m2 all property/global poissonsRatio peratomtype {each('0.3')}",
        f"fix m3 all property/global coefficientRestitution {n} {pairs(cor)}",
        f"fix m4 all property/global coefficientFriction {n} {pairs('0.5')}",
        "fix m5 all property/global characteristicVelocity scalar 1"])


def deck(rng):
    d = Draw(rng)
    types = d.rng.randint(1, 2)   # one shape per type
    px, py = d.rng.choice("pf"), d.rng.choice("pf")
    lines = ["units si", "atom_style sphere", "atom_modify map array", f"boundary {px} {py} f",
             "newton off", "communicate single vel yes",
             "region box block -0.01 0.01 -0.01 0.01 -0.002 0.03 units box",
             f"create_box {types} box",
             f"neighbor {d.value(5e-4, 3e-3)} bin", "neigh_modify delay 0",
             f"timestep {d.value(1e-7, 3e-6)}"]
    for i in range(d.rng.randint(1, 6)):
        x, y = d.rng.uniform(-0.007, 0.007), d.rng.uniform(-0.007, 0.007)
        z = d.rng.uniform(0.002, 0.02)
        lines.append(f"create_atoms {d.rng.randint(1, types)} single {x:.5f} {y:.5f} {z:.5f} "
                     "units box")
    lines.append(particles_fix(d, types))
    model = d.rng.choice(["hooke/stiffness", "hooke", "hertz"])
    lines.append(material(d, model, types))
    lines.append(f"pair_style tri/gran model {model} {contact_keywords(d)}".rstrip())
    lines.append("pair_coeff * *")
    lines.append("fix floor all mesh/surface file floor.stl type 1")
    wall = "fix walls all tri/wall mesh floor"
    if d.maybe(0.3):
        wall += f" epsilon {d.value(1e-5, 2e-4)}"
    if d.maybe(0.3):
        wall += " virial " + d.word("yes", "no")
    lines.append(f"{wall} model {model} {contact_keywords(d)}".rstrip())
    lines.append("fix gravity all gravity 9.81 vector 0 0 -1")
    lines.append("fix integr all tri/nve")
    if d.maybe(0.4):
        adapt = f"fix adapt all tri/adapt_dt dtmax {d.value(1e-6, 2e-5)} dtmin {d.value(1e-9, 1e-7)}"
        for key, lo, hi in (("approach", 0.1, 1), ("fraction", 0.05, 0.5), ("growth", 1.01, 1.5)):
            if d.maybe(0.3):
                adapt += f" {key} {d.value(lo, hi)}"
        if d.maybe(0.3):
            adapt += " log " + d.word("all", "100")
        lines.append(adapt)
    if d.maybe(0.3):
        lines.append(f"fix out all tri/vtk every {d.word('5', '20')} file post/p walls "
                     + d.word("yes", "no", "floor"))
    lines.append("compute stats all tri/stats " + d.word("all", "pair", "wall"))
    lines.append("compute atoms all tri/contact/atom " + d.word("pair", "wall", ""))
    values = d.rng.sample(LOCAL_VALUES, d.rng.randint(1, 4))
    lines.append("compute net all tri/contact/local " + d.word("pair", "wall", "") + " "
                 + " ".join(values))
    if d.maybe(0.5):
        lines.append("dump dl all local 10 local.dump c_net[1]")
    lines.append("set atom * vz -0.3" if d.maybe(0.5) else "set atom * omegax 20")
    lines.append("thermo_style custom step atoms ke c_stats[1] c_stats[2]")
    lines.append("thermo 10")
    lines.append(f"run {d.rng.choice([20, 50])}")
    return "\n".join(lines) + "\n", d.bad


NUMBER = re.compile(r"^\s*\d+\s+(\S+)\s+(\S+)")


def check_deck(ctx, k, text, bad):
    path = os.path.join(ctx.work, f"in.fuzz{k}")
    with open(path, "w") as f:
        f.write(text)
    code, out = run([ctx.exe, "-in", path, "-log", "none"], ctx.work, timeout=60)
    where = f"deck {k} ({bad} invalid values drawn):\n{text}\n--- output (end):\n{out[-1500:]}"
    check(code >= 0 and not any(w in out for w in CRASH_WORDS), f"crashed: {where}")
    errors = [l for l in out.splitlines() if l.startswith("ERROR")]
    if code != 0:
        check(errors, f"exit {code} without an ERROR line: {where}")
        return "error: " + errors[0][:100]
    check(not errors, f"exit 0 after an ERROR: {where}")
    check("Loop time" in out, f"exit 0 without a run: {where}")
    atoms = None
    for l in out.splitlines():
        low = l.lower()
        check("nan" not in low.split() and "inf" not in low.split() and "-nan" not in low,
              f"NaN or inf in the output ({l.strip()}): {where}")
        m = NUMBER.match(l)
        if m and re.fullmatch(r"\d+", m.group(1)):
            atoms = atoms if atoms is not None else int(m.group(1))
            check(int(m.group(1)) == atoms, f"particles lost ({l.strip()}): {where}")
    return "ran"


def test_deck_fuzz(ctx):
    os.makedirs(os.path.join(ctx.work, "post"))
    with open(os.path.join(ctx.work, "floor.stl"), "w") as f:
        f.write(PLANE)
    from decklib import cube, write_stl
    write_stl(os.path.join(ctx.work, "cube.stl"), [[[c - 0.001 for c in p] for p in t]
                                                   for t in cube()])
    seed = int(os.environ.get("FUZZ_SEED", "1"))
    count = int(os.environ.get("FUZZ_DECKS", "24"))
    rng = random.Random(seed)
    outcomes = {"ran": 0, "error": 0}
    failures = []
    for k in range(count):
        text, bad = deck(rng)
        try:
            result = check_deck(ctx, k, text, bad)
        except Failure as e:
            failures.append(str(e))
            continue
        outcomes["ran" if result == "ran" else "error"] += 1
        print(f"deck {k}: {result}")
    print(f"seed {seed}: {count} decks, {outcomes['ran']} ran, {outcomes['error']} stopped with "
          f"an ERROR, {len(failures)} failed")
    check(not failures, "\n\n".join(failures))
    check(outcomes["ran"] >= count // 4, "fewer than a quarter of the decks ran: the generator "
                                         "draws too many invalid values to test the runs")
