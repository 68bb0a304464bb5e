"""What every deck test shares: running a deck through liggghts-tri, reading its thermo
output and dumps, the one harness for decks that must stop with an error, the columns of
compute tri/stats by name, and writers of small meshes. Standard library only.

A test is a function `test_NAME(ctx)` in a module `test_*.py` beside this file (decktests.py
finds and runs it); it fails by raising Failure, normally through check().
"""
import argparse
import os
import re
import struct
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
           "OMPI_MCA_rmaps_base_oversubscribe": "1", "OMP_NUM_THREADS": "1"}
CRASH_WORDS = ("Segmentation", "signal", "core dumped")

# Deck settings that more than one test module uses: in.flight periodic in x and y; fix
# tri/particles arguments of in.bad_particles (a rock; the rest of a shape; a shape larger
# than the box).
FLIGHT_PERIODIC = {"bx": "p", "by": "p"}
ROCK = "shape r random ntri 20 size 0.004 seed 1"
TAIL = "density 2500 epsilon 0.0001"
TOO_LARGE = f"shape r random ntri 20 size 0.5 seed 1 {TAIL}"


class Failure(Exception):
    pass


_checks = 0


def check(cond, message):
    """Fails the test with `message` unless `cond`. Counted: a test that makes no check fails."""
    global _checks
    _checks += 1
    if not cond:
        raise Failure(message)


def checks_made():
    return _checks


# --------------------------------------------------------------------------------------------
# compute tri/stats columns, by name. tri-stats-columns prints one line per column,
# "index<TAB>name<TAB>unit<TAB>meaning", index 1-based as in c_ID[index].

_stats_tool = None
_stats = None          # [(index, name, unit, meaning)], read once


def configure(stats_columns=None):
    """Called once by the runner with the path of tri-stats-columns (or None)."""
    global _stats_tool, _stats
    _stats_tool, _stats = stats_columns, None


def stats_columns():
    global _stats
    if _stats is None:
        if not _stats_tool:
            raise Failure("this test needs compute tri/stats columns: pass --stats-columns "
                          "PATH of tri-stats-columns")
        p = subprocess.run([_stats_tool], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           text=True, errors="replace", timeout=60)
        if p.returncode != 0:
            raise Failure(f"{_stats_tool} exited {p.returncode}: {p.stdout[-1000:]}")
        table = []
        for line in p.stdout.splitlines():
            fields = line.split("\t")
            if len(fields) != 4 or not fields[0].isdigit() or not fields[1]:
                raise Failure(f"{_stats_tool}: not 'index<TAB>name<TAB>unit<TAB>meaning': "
                              f"{line!r}")
            table.append((int(fields[0]), fields[1], fields[2], fields[3]))
        names = [t[1] for t in table]
        if not table or [t[0] for t in table] != list(range(1, len(table) + 1)) \
                or len(set(names)) != len(names):
            raise Failure(f"{_stats_tool}: indices not 1..n or names not unique:\n{p.stdout}")
        _stats = table
    return _stats


def stat(name):
    """The 1-based index of the compute tri/stats column `name` (c_ID[index])."""
    for index, n, _, _ in stats_columns():
        if n == name:
            return index
    raise Failure(f"compute tri/stats has no column '{name}' "
                  f"(it has {', '.join(t[1] for t in stats_columns())})")


def stat_name(index):
    for i, n, _, _ in stats_columns():
        if i == index:
            return n
    raise Failure(f"compute tri/stats has no column {index} (it has {len(stats_columns())})")


def stat_variables():
    """-var stat_NAME INDEX for every column, so a deck writes c_stats[${stat_contacts_after}]."""
    return {f"stat_{name}": index for index, name, _, _ in stats_columns()}


# --------------------------------------------------------------------------------------------
# Running decks

def subdir(ctx, name):
    """A copy of ctx whose work folder is ctx.work/name (created)."""
    sub = argparse.Namespace(**vars(ctx))
    sub.work = os.path.join(ctx.work, name)
    os.makedirs(sub.work, exist_ok=True)
    return sub


def run_deck(ctx, deck, variables=None, ranks=1, expect_ok=True, env_extra=None, timeout=600,
             mpirun=None):
    """Runs one deck (a path relative to this folder, or absolute) in ctx.work; returns (exit
    code, combined screen output). The output is a DeckOutput: the screen text as LIGGGHTS
    prints it, and in .log the log file, which also holds every command as run (-echo log), for
    thermo_rows. Variables: dir (this folder unless given), stat_NAME for every compute
    tri/stats column when the columns are known, then `variables`. `env_extra` adds to (and
    overrides) the environment, e.g. OMP_NUM_THREADS. Through mpirun when ranks > 1, or always
    with mpirun=True."""
    values = {"dir": HERE, "layer": "inside"}
    if _stats_tool:
        values.update(stat_variables())
    values.update(variables or {})
    log = os.path.join(ctx.work, "log.deck")
    if os.path.exists(log):
        os.remove(log)
    cmd = [ctx.exe, "-in", os.path.join(HERE, deck), "-log", log, "-echo", "log"]
    for k, v in values.items():
        cmd += ["-var", k, str(v)]
    if mpirun or (mpirun is None and ranks > 1):
        cmd = ["mpirun", "-np", str(ranks)] + cmd
    code, out = run(cmd, ctx.work, env_extra, timeout)
    out = DeckOutput(out)
    if os.path.exists(log):
        with open(log, errors="replace") as f:
            out.log = f.read()
    if expect_ok and code != 0:
        raise Failure(f"{' '.join(cmd)} exited {code}:\n{out[-3000:]}")
    return code, out


class DeckOutput(str):
    """A deck's screen output; .log: its log file with the commands echoed (None if there is
    none), where thermo_rows finds the thermo_style in force. Echoing to the screen instead
    would put the decks' lines, comments included, into every search of the screen text."""
    log = None


def run(cmd, cwd, env_extra=None, timeout=600):
    """Runs a command as run_deck does (MPI_ENV, then `env_extra`, where None removes a
    variable) without adding to it; returns (exit code, combined screen output)."""
    env = dict(os.environ, **MPI_ENV)
    for key, value in (env_extra or {}).items():
        if value is None:
            env.pop(key, None)
        else:
            env[key] = value
    try:
        p = subprocess.run(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True, errors="replace",
                           timeout=timeout)
    except subprocess.TimeoutExpired:
        raise Failure(f"{' '.join(cmd)} in {cwd}: still running after {timeout} s")
    return p.returncode, p.stdout


ERROR_SOURCE = re.compile(r"\s*\([^()]*:\d+\)\s*$")   # LIGGGHTS's trailing " (file.cpp:123)"


def expect_error(ctx, deck, variables, pattern, with_output=False):
    """Runs a deck that must stop with a LIGGGHTS error matching `pattern`, without a crash.
    The pattern is searched in the ERROR lines, each without its trailing source location
    (so `$` is the end of the message), joined by spaces. Returns the first of them (and the
    screen output, with with_output=True)."""
    code, out = run_deck(ctx, deck, variables, expect_ok=False)
    errors = [ERROR_SOURCE.sub("", l.strip()) for l in out.splitlines() if "ERROR" in l]
    check(not any(s in out for s in CRASH_WORDS),
          f"{deck} {variables}: crashed instead of a clean error:\n{out[-2000:]}")
    check(code != 0 and errors and re.search(pattern, " ".join(errors)),
          f"{deck} {variables}: exit {code}, errors {errors or out[-1500:]!r}, wanted /{pattern}/")
    return (errors[0], out) if with_output else errors[0]


# --------------------------------------------------------------------------------------------
# Reading output

THERMO_STYLE = re.compile(r"^\s*thermo_style\s+custom\s+(.*?)\s*$")
COMPUTE_VECTOR = re.compile(r"^c_(\w+)\[(\d+)\]$")
HEADER_WIDTH = 8      # LIGGGHTS 3.8 cuts a thermo header word to 8 characters


def thermo_rows(out, stats=("stats",)):
    """Every thermo row of a run_deck output: a list of dicts, one per row, keyed by column.
    Read from its log (out.log), where the thermo_style in force is echoed after variable
    substitution: the keys come from it, since LIGGGHTS cuts header words to 8 characters (a
    plain screen text gives the header words as they are). c_ID[k] of a compute tri/stats
    whose ID is in `stats` is ID.NAME by its column name (e.g. stats.contacts_after, never
    stats[6]); another c_X, f_X or v_X is X (adt[1], dmin); a built-in keyword is its header
    word (Step, Atoms, Dt, KinEng). A missing key fails the test, naming the columns there
    are."""
    rows, header, keywords = [], None, None
    text = getattr(out, "log", None) or out
    for line in text.splitlines():
        m = THERMO_STYLE.match(line)
        if m:
            keywords = m.group(1).split("#")[0].split()   # the echo keeps comments
            continue
        words = line.split()
        if words and words[0] == "Step":
            header = _thermo_keys(words, keywords, stats)
            continue
        if header and len(words) == len(header):
            try:
                rows.append(ThermoRow(zip(header, (float(w) for w in words))))
                continue
            except ValueError:
                pass
        if words and words[0] == "Loop":   # other lines (e.g. tri/adapt_dt's) may interleave
            header = None
    return rows


class ThermoRow(dict):
    def __missing__(self, key):
        raise Failure(f"thermo has no column '{key}'; it has {', '.join(self)}")


def _thermo_keys(words, keywords, stats):
    if keywords is None:               # thermo_style one or multi: the header is all there is
        return words
    check(len(keywords) == len(words), f"thermo header {words} does not match the thermo_style "
                                       f"keywords {keywords}")
    keys = []
    for word, keyword in zip(words, keywords):
        if keyword[:2] in ("c_", "f_", "v_"):
            check(word == keyword[2:2 + HEADER_WIDTH],
                  f"thermo header word '{word}' is not the thermo_style keyword '{keyword}'")
            m = COMPUTE_VECTOR.match(keyword)
            if m and m.group(1) in stats:
                keys.append(f"{m.group(1)}.{stat_name(int(m.group(2)))}")
            else:
                keys.append(keyword[2:])
        else:
            keys.append(word)
    return keys


def snapshots(path):
    """Every snapshot of a LIGGGHTS custom dump, in order: [(step, {id: [fields as strings]})].
    Fields stay strings so that %.17g columns compare bit for bit."""
    check(os.path.exists(path), f"{path} was not written")
    with open(path) as f:
        lines = f.read().splitlines()
    out, k = [], 0
    while k < len(lines):
        if lines[k].startswith("ITEM: TIMESTEP"):
            step, n = int(lines[k + 1]), int(lines[k + 3])
            rows = {}
            for l in lines[k + 9:k + 9 + n]:
                fields = l.split()
                rows[int(fields[0])] = fields[1:]
            check(len(rows) == n, f"{path}, step {step}: {len(rows)} atom rows of {n}")
            out.append((step, rows))
            k += 9 + n
        else:
            k += 1
    check(out, f"{path} holds no snapshot")
    return out


def first_frame(path):
    """The first snapshot of a custom dump: (step, {id: [fields as strings]})."""
    return snapshots(path)[0]


def last_frame(path):
    """The last snapshot of a custom dump: (step, {id: [fields as strings]})."""
    return snapshots(path)[-1]


# --------------------------------------------------------------------------------------------
# Meshes

def write_stl(path, triangles):
    with open(path, "w") as f:
        f.write("solid t\n")
        for tri in triangles:
            f.write(" facet normal 0 0 0\n  outer loop\n")
            for p in tri:
                f.write("   vertex %s %s %s\n" % tuple(p))
            f.write("  endloop\n endfacet\n")
        f.write("endsolid t\n")


def write_binary_stl(path, triangles):
    with open(path, "wb") as f:
        f.write(b"\0" * 80 + struct.pack("<I", len(triangles)))
        for t in triangles:
            f.write(struct.pack("<12fH", 0, 0, 0, *t[0], *t[1], *t[2], 0))


def tetra():
    """A closed, outward tetrahedron with three 2 mm edges along the axes."""
    a, b, c, d = (0, 0, 0), (0.002, 0, 0), (0, 0.002, 0), (0, 0, 0.002)
    return [[a, c, b], [a, b, d], [a, d, c], [b, c, d]]


def cube(side=0.002):
    """The closed, outward cube [0, side]^3: 12 triangles, first the six faces' first halves
    and then their second halves (so that cube()[:-1] is a cube with one half face open)."""
    v = [(x * side, y * side, z * side) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    return [[v[a], v[b], v[c]] for a, b, c, d in quads] + [[v[a], v[c], v[d]] for a, b, c, d in quads]


def fine_cube(n, side):
    """A closed, outward cube of side `side` centred at 0: n x n squares, 12 n^2 triangles."""
    h, tris = side / 2, []

    def face(o, u, v):
        def p(i, j):
            return tuple(o[k] + (i / n) * u[k] + (j / n) * v[k] for k in range(3))
        for a in range(n):
            for b in range(n):
                tris.append((p(a, b), p(a + 1, b), p(a + 1, b + 1)))
                tris.append((p(a, b), p(a + 1, b + 1), p(a, b + 1)))
    s = side
    face((-h, -h, -h), (0, s, 0), (s, 0, 0))
    face((-h, -h, h), (s, 0, 0), (0, s, 0))
    face((-h, -h, -h), (s, 0, 0), (0, 0, s))
    face((-h, h, -h), (0, 0, s), (s, 0, 0))
    face((-h, -h, -h), (0, 0, s), (0, s, 0))
    face((h, -h, -h), (0, s, 0), (0, 0, s))
    return tris


def open_box(w, h):
    """An open box: the floor z = 0 of [-w, w]^2 and four side walls up to z = h, facing in."""
    def quad(a, b, c, d):
        return [[a, b, c], [a, c, d]]
    return (quad((-w, -w, 0), (w, -w, 0), (w, w, 0), (-w, w, 0))
            + quad((-w, -w, 0), (-w, w, 0), (-w, w, h), (-w, -w, h))
            + quad((w, -w, 0), (w, -w, h), (w, w, h), (w, w, 0))
            + quad((-w, -w, 0), (-w, -w, h), (w, -w, h), (w, -w, 0))
            + quad((-w, w, 0), (w, w, 0), (w, w, h), (-w, w, h)))


# The contact decks' meshes, written into the work folder: cube.stl (meshgen.py, 2 x 2 squares
# per face, side CUBE_SIDE, centred), plane.stl (a 2 cm square at z = 0) and box.stl (the
# cluster decks' open box).
MESHGEN = os.path.join(HERE, "..", "..", "validation", "meshes", "meshgen.py")
EPS = 1e-4            # the particles' soft layer in the contact decks
CUBE_SIDE = 0.004
BOX_HALF, BOX_HEIGHT = 0.0045, 0.02


def make_contact_meshes(work):
    subprocess.run([sys.executable, MESHGEN, "cube", "2", repr(CUBE_SIDE), "cube.stl"], cwd=work,
                   check=True)
    subprocess.run([sys.executable, MESHGEN, "plane", "0.01", "plane.stl"], cwd=work, check=True)
    write_stl(os.path.join(work, "box.stl"), open_box(BOX_HALF, BOX_HEIGHT))
