"""Every style of Debian's LIGGGHTS beside fix tri/particles, class by class, as the
compatibility matrix (tri-style-matrix, from src_plugin/liggghts/style_matrix.cpp) says.

Each style has one short deck (style_decks.py: the base deck of 18 rocks settling on a mesh
floor, plus the style's lines, used so that it does its work: a compute in the thermo line or a
dump, a region by a group, a dump written). A style that works (as with spheres, or with its
stated meaning) must run to the end with finite thermo output and no particle lost; a refused
one must stop with an ERROR naming it; an irrelevant one must run or stop with an ERROR. None
may end in a signal, hang or print NaN. A style that `liggghts -h` lists and the matrix does not
classify, or that has no deck, fails the classification test until it is added to both."""
import concurrent.futures
import os
import re
import subprocess

from decklib import CRASH_WORDS, Failure, check, run, snapshots
from style_decks import BASE, PAIR, SEQUENCES, SNIPPETS, deck_text, write_files

SECTIONS = {  # `liggghts -h` section title -> the matrix's kind
    "Atom styles": "atom_style", "Integrate styles": "run_style", "Pair styles": "pair_style",
    "Normal models for pair gran": "pair gran model",
    "Tangential models for pair gran": "pair gran tangential",
    "Cohesion models for pair gran": "pair gran cohesion",
    "Rolling models for pair gran": "pair gran rolling_friction",
    "Surface models for pair gran": "pair gran surface",
    "Fix styles": "fix", "Compute styles": "compute", "Region styles": "region",
    "Dump styles": "dump", "Command styles": "command"}
# What the plugin adds: classified by its own manual, not by this matrix.
OWN = re.compile(r"^tri/")


def liggghts_styles(liggghts):
    """{"kind style"} of every style `liggghts -h` lists, kinds as the matrix names them."""
    code, out = run([liggghts, "-h"], os.getcwd(), timeout=60)
    styles, kind = set(), None
    for line in out.splitlines():
        title = re.match(r"^\* (.*?):?\s*$", line)
        if title:
            kind = SECTIONS.get(title.group(1))
            continue
        if kind and line.strip():
            styles.update(f"{kind} {w}" for w in line.split() if not OWN.match(w))
    check(len(styles) > 200, f"`{liggghts} -h` listed {len(styles)} styles:\n{out[-2000:]}")
    return styles


def matrix(ctx):
    """{"kind style": (class, note, instead)} from tri-style-matrix."""
    if not ctx.style_matrix:
        raise Failure("this test needs the matrix: pass --style-matrix PATH of tri-style-matrix")
    out = subprocess.run([ctx.style_matrix], stdout=subprocess.PIPE, text=True,
                         check=True).stdout
    rows = {}
    for line in out.splitlines():
        kind, style, cls, note, instead = line.split("\t")
        rows[f"{kind} {style}"] = (cls, note, instead)
    return rows


def run_in_folder(ctx, name, text):
    """Runs deck `text` in its own folder ctx.work/NAME (with the files style_decks writes);
    returns (exit code, screen output)."""
    work = os.path.join(ctx.work, re.sub(r"\W+", "_", name))
    os.makedirs(work, exist_ok=True)
    write_files(work)
    with open(os.path.join(work, "in.deck"), "w") as f:
        f.write(text)
    return run([ctx.exe, "-in", "in.deck"], work, timeout=120)


def outcome(ctx, key):
    """(status, detail) of the style's deck: status RUNS, ERROR, SIGNAL, HANG or NAN."""
    try:
        code, out = run_in_folder(ctx, key, deck_text(key))
    except Failure as e:
        return "HANG", str(e)
    errors = [l.strip() for l in out.splitlines() if l.startswith("ERROR")]
    if code < 0 or any(w in out for w in CRASH_WORDS):
        return "SIGNAL", f"exit {code}: {out[-1500:]}"
    if errors:
        return "ERROR", errors[0]
    if code != 0:
        return "SIGNAL", f"exit {code} without an ERROR: {out[-1500:]}"
    if re.search(r"(?<![\w.])[-+]?(nan|inf)(?![\w.])", out, re.I):
        return "NAN", out[-1500:]
    if "Lost atoms" in out or "Loop time" not in out:
        return "LOST", out[-1500:]
    return "RUNS", ""


def style_of(key):
    """The style a deck's key is for: "kind style" of "kind style" or "kind style:variant"."""
    return key.split(":")[0]


def run_class(ctx, cls):
    """Runs every deck of every style of class `cls`; returns [(key, row, status, detail)]."""
    rows = {k: v for k, v in matrix(ctx).items() if v[0] == cls}
    check(rows, f"the matrix has no style of class {cls}")
    keys = sorted(k for k in SNIPPETS if style_of(k) in rows)
    with concurrent.futures.ThreadPoolExecutor(max(2, os.cpu_count() or 2)) as pool:
        results = list(pool.map(lambda k: outcome(ctx, k), keys))
    counts = {}
    for status, _ in results:
        counts[status] = counts.get(status, 0) + 1
    print(f"{cls}: {len(keys)} styles, " + ", ".join(f"{n} {s}" for s, n in sorted(counts.items())))
    return [(k, rows[style_of(k)], s, d) for k, (s, d) in zip(keys, results)]


def report(bad):
    return "\n".join(f"  {k}: {s} {d[-600:]}" for k, _, s, d in bad)


def test_style_matrix_classifies_every_style(ctx):
    """The matrix classifies exactly the styles `liggghts -h` lists, and each has a deck."""
    listed, classified = liggghts_styles(ctx.liggghts), set(matrix(ctx))
    missing, extra = sorted(listed - classified), sorted(classified - listed)
    check(not missing, "styles of `liggghts -h` the matrix does not classify (add a row to "
          "src_plugin/liggghts/style_matrix.cpp and a deck to style_decks.py): " +
          ", ".join(missing))
    check(not extra, "rows of the matrix for styles `liggghts -h` does not list: " +
          ", ".join(extra))
    decks = {style_of(k) for k in SNIPPETS}
    no_deck, stale = sorted(classified - decks), sorted(decks - classified)
    check(not no_deck, "styles without a deck in style_decks.py: " + ", ".join(no_deck))
    check(not stale, "decks in style_decks.py for no style of the matrix: " + ", ".join(stale))
    print(f"{len(listed)} styles of `liggghts -h`, all classified, each with a deck")


def test_style_matrix_works(ctx):
    """Every style that works (as with spheres or with its stated meaning) runs its deck."""
    results = run_class(ctx, "works") + run_class(ctx, "meaning")
    bad = [r for r in results if r[2] != "RUNS"]
    check(not bad, "styles the matrix says work, whose decks did not run:\n" + report(bad))


def test_style_matrix_refused(ctx):
    """Every refused style stops its deck with an ERROR: the plugin's (naming a tri/ style or
    triangulated particles) or LIGGGHTS's own naming the style."""
    bad = [r for r in run_class(ctx, "refused") if r[2] != "ERROR" or not (
        re.search(r"tri/|triangulated", r[3]) or style_of(r[0]).split()[-1] in r[3])]
    check(not bad, "refused styles that did not stop with an ERROR that names them or the "
          "plugin's replacement:\n" + report(bad))


def test_style_matrix_irrelevant(ctx):
    """Every style of other models (SPH, CFD coupling, molecules) runs or stops with an
    ERROR: never a signal, a hang or NaN."""
    bad = [r for r in run_class(ctx, "irrelevant") if r[2] not in ("RUNS", "ERROR")]
    check(not bad, "irrelevant styles that crashed, hung or printed NaN:\n" + report(bad))


def run_text(ctx, name, text):
    """Runs deck `text` (run_in_folder) that must run without an ERROR; returns its output and
    leaves its files in ctx.work/NAME."""
    code, out = run_in_folder(ctx, name, text)
    check(code == 0 and "ERROR" not in out, f"{name} exited {code}:\n{out[-2000:]}")
    return out


def test_runs_split_with_pre_no_and_clear(ctx):
    """`run N pre no` continues a run without init or setup: 10 + 10 steps give the bits of
    one run of 20 (thermo rows with %.17g), and the second run's first row, printed before any
    force evaluation, repeats the first run's last (compute tri/stats included). After `clear`
    the plugin's styles are still there: the same deck runs again in the same input."""
    base = BASE.format(atom_style="sphere", pair_style=PAIR)
    thermo = ("compute st all tri/stats\nthermo_style custom step atoms ke c_st[6]\n"
              "thermo_modify format float %.17g\n")
    whole = run_text(ctx, "in.whole", base + thermo + "run 20\n")
    split = run_text(ctx, "in.split", base + thermo + "run 10\nrun 10 pre no\n")

    def row(out, step):
        rows = [l.split() for l in out.splitlines() if l.split()[:1] == [str(step)]]
        check(rows, f"no thermo row of step {step}:\n{out[-1500:]}")
        return rows[-1]
    check(row(whole, 20) == row(split, 20),
          f"step 20: {row(whole, 20)} in one run, {row(split, 20)} after `run 10 pre no`")
    tens = [l.split() for l in split.splitlines() if l.split()[:1] == ["10"]]
    check(len(tens) == 2 and tens[0] == tens[1] and float(tens[0][3]) > 0.0,
          f"step 10 at the end of `run 10` and the start of `run 10 pre no`: {tens}")
    again = run_text(ctx, "in.clear", base + "run 5\nclear\n" + base + "run 5\n")
    check(again.count("Loop time") == 2, "the deck did not run twice around `clear`")


def test_set_diameter_is_reset_with_a_warning(ctx):
    """`set diameter` (or mass) changes what fix tri/particles owns: the next run resets every
    particle to its shape's contact reach and mass, and warns, naming how many."""
    base = BASE.format(atom_style="sphere", pair_style=PAIR)
    dump = "dump r all custom 5 radius.dump id radius mass\ndump_modify r sort id\n"
    out = run_text(ctx, "in.set", base + dump + "run 5\nset group all diameter 0.001\nrun 5\n")
    check(out.count("WARNING") == 1 and "18 particle(s) had their radius or mass changed" in out,
          f"no (or more than one) warning of the changed radii:\n{out[-2000:]}")
    frames = snapshots(os.path.join(ctx.work, "in_set", "radius.dump"))
    (before_step, before), (last_step, last) = frames[1], frames[-1]
    check(before_step == 5 and last_step == 10, f"frames at {[f[0] for f in frames]}")
    check(last == before, "the radii and masses after the reset are not the shapes'")


def test_decks_that_take_the_styles_apart(ctx):
    """unfix, a fix defined again, pair_style none, deleted particles, a changed box, between
    runs (style_decks.SEQUENCES): each deck runs, or stops with the ERROR it names."""
    base = BASE.format(atom_style="sphere", pair_style=PAIR)
    bad = []
    for name, (lines, error) in SEQUENCES.items():
        code, out = run_in_folder(ctx, name, base + lines + "\n")
        errors = [l for l in out.splitlines() if l.startswith("ERROR")]
        if code < 0 or any(w in out for w in CRASH_WORDS):
            bad.append(f"{name}: a signal (exit {code}):\n{out[-800:]}")
        elif error is None and (code != 0 or errors):
            bad.append(f"{name}: should run, got exit {code} {errors}")
        elif error is not None and not (code != 0 and errors and error in errors[0]):
            bad.append(f"{name}: should stop with an ERROR containing {error!r}, got exit "
                       f"{code} {errors}")
    check(not bad, "\n".join(bad))
    print(f"{len(SEQUENCES)} decks, each as expected")


def test_massflow_counts_the_particles_whose_centres_cross(ctx):
    """fix massflow/mesh beside mesh particles: the 9 rocks of the upper layer, sent down
    through a plane mesh at z = 6.5 mm, are counted once each, with their meshes' mass: the
    count and mass of the particles that started above the plane and end below it."""
    base = BASE.format(atom_style="sphere", pair_style=PAIR)
    out = run_text(ctx, "in.massflow", base + """\
region above block INF INF INF INF 0.0065 INF units box
region below block INF INF INF INF INF 0.0065 units box
group top region above
velocity all set 0 0 -0.5
fix sm all mesh/surface file flow.stl type 1
fix s all massflow/mesh mesh sm vec_side 0 0 -1 count once
variable crossed equal count(top,below)
variable mcrossed equal mass(top,below)
thermo_style custom step f_s[1] f_s[2] v_crossed v_mcrossed
thermo_modify format float %.17g
thermo 100
run 400
""")
    rows = [l.split() for l in out.splitlines() if l.split()[:1] == ["400"]]
    check(rows, f"no thermo row at step 400:\n{out[-1500:]}")
    mass, count, crossed, mcrossed = (float(w) for w in rows[-1][1:5])
    print(f"massflow/mesh: {count:g} particles, {mass:.6e} kg; crossed: {crossed:g}, "
          f"{mcrossed:.6e} kg")
    check(crossed == 9 and count == crossed, f"counted {count:g}, crossed {crossed:g} (of 9)")
    check(abs(mass - mcrossed) <= 1e-12 * mcrossed, f"mass {mass:g} kg, crossed {mcrossed:g} kg")
