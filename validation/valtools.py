"""Helpers shared by the validation scripts: standard library only, nothing heavy at import.

Scripts put this folder on sys.path from their own location, e.g.
  sys.path.insert(0, os.path.join(REPO, "validation")); import valtools
"""
import os
import platform
import re
import resource
import subprocess
import sys

REPO = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

# Open MPI refuses to run as root without these (the containers run as root).
MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1"}

# Benchmarks against spheres: the phases whose time per step does not drift as they run. Only
# there may the (cheap) sphere side run more steps than the rocks; a phase that changes as it
# runs (a pile forming, a hopper discharging, a gas cooling) is timed over the same steps on
# both sides, the same simulated window.
STEADY_PHASES = {"free", "settled"}


def cpu_measurable(run):
    """Whether a measured run's CPU time (its cpu_ms_per_step over its steps) is well above
    the spread of the start-up subtracted from it (50 ms); below, a CPU figure means nothing."""
    steps = run.get("total_steps", run["steps"])
    return run["cpu_ms_per_step"] * (steps - 1) >= 50.0


def default_exe():
    """The liggghts-tri to run: $LIGGGHTS_TRI, else build/src_plugin/driver/liggghts-tri in the repo."""
    return os.environ.get("LIGGGHTS_TRI",
                          os.path.join(REPO, "build", "src_plugin", "driver", "liggghts-tri"))


def run_env(threads=1):
    """os.environ plus the root-friendly Open MPI variables and OMP_NUM_THREADS=threads."""
    return dict(os.environ, OMP_NUM_THREADS=str(threads), **MPI_ENV)


def deck_command(exe, deck, variables, log="none"):
    """The command line [exe, -in, deck, -log, log, -var k v, ...] for a dict of deck variables."""
    cmd = [exe, "-in", deck, "-log", log]
    for k, v in variables.items():
        cmd += ["-var", k, str(v)]
    return cmd


def stats_columns(tool, wanted=()):
    """name -> 1-based column of compute tri/stats, from the tri-stats-columns program `tool`;
    exits naming any of `wanted` that it lacks."""
    out = subprocess.run([tool], capture_output=True, text=True, check=True).stdout
    cols = {}
    for line in out.splitlines():
        f = line.split("\t")
        if len(f) >= 2 and f[0].strip().isdigit():
            cols[f[1].strip()] = int(f[0])
    missing = [c for c in wanted if c not in cols]
    if missing:
        sys.exit(f"{tool} has no column {missing}")
    return cols


def run_measured(cmd, cwd, env, timeout):
    """Runs `cmd` in cwd (created) with its output in cwd/screen.txt; returns (exit code, the
    output, the CPU seconds of the run and its children)."""
    os.makedirs(cwd, exist_ok=True)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(os.path.join(cwd, "screen.txt"), "w") as f:
        p = subprocess.run(cmd, cwd=cwd, env=env, stdout=f, stderr=subprocess.STDOUT,
                           timeout=timeout)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(os.path.join(cwd, "screen.txt"), errors="replace") as f:
        text = f.read()
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return p.returncode, text, cpu


def run_problems(text):
    """What makes a run's output unusable: an ERROR, lost atoms, a nan or inf."""
    return [w for w, pat in (("ERROR", r"^ERROR"), ("lost atoms", r"Lost atoms"),
                             ("nan", r"\b(nan|-nan|inf)\b")) if re.search(pat, text, re.M | re.I)]


def run_deck(exe, deck, variables, cwd, screen, threads=1, exit_on_error=False):
    """Runs a deck (-log none, run_env) in cwd with its screen output in the file `screen`; returns
    the command (list); a failure raises CalledProcessError, or exits with a message if asked."""
    # (not "-screen none": LIGGGHTS 3.8's STL reader then writes to a null FILE* and crashes)
    cmd = deck_command(exe, deck, variables)
    with open(screen, "w") as out:
        r = subprocess.run(cmd, cwd=cwd, env=run_env(threads), stdout=out,
                           stderr=subprocess.STDOUT, check=not exit_on_error)
    if r.returncode != 0:
        sys.exit(f"{' '.join(cmd)} failed, see {screen}")
    return cmd


def cpu_model():
    """The first 'model name' of /proc/cpuinfo, or 'unknown CPU'."""
    try:
        with open("/proc/cpuinfo") as f:
            return next(l.split(":", 1)[1].strip() for l in f if l.startswith("model name"))
    except (OSError, StopIteration):
        return "unknown CPU"


def machine_line(cores=False):
    """The 'machine: host, CPU[, N cores]; ...' line the tables start with (1 rank, 1 thread)."""
    if cores:
        return (f"machine: {platform.node()}, {cpu_model()}, {os.cpu_count()} cores; "
                "OMP_NUM_THREADS=1, 1 MPI rank")
    return "machine: %s, %s; 1 MPI rank, OMP_NUM_THREADS=1" % (platform.node(), cpu_model())


def read_rows(path):
    """Rows of floats of a whitespace-separated text file, '#' lines and blank lines skipped."""
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            rows.append([float(v) for v in line.split()])
    return rows


def read_discharge(path, missing_ok=False):
    """[time, particles out (int), mass out] rows of a hopper discharge.txt; [] if missing and ok."""
    rows = []
    try:
        with open(path) as f:
            for line in f:
                if line.startswith("#") or not line.strip():
                    continue
                t, n, m = line.split()[:3]
                rows.append([float(t), int(float(n)), float(m)])
    except OSError:
        if not missing_ok:
            raise
    return rows


def slope(x, y):
    """Least-squares slope of y against x."""
    mx, my = sum(x) / len(x), sum(y) / len(y)
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sum((a - mx) ** 2 for a in x)


def fit(x, y):
    """Least-squares line of y against x: (slope, intercept, rms of the residuals)."""
    n = len(x)
    mx, my = sum(x) / n, sum(y) / n
    k = slope(x, y)
    res = [b - (my + k * (a - mx)) for a, b in zip(x, y)]
    return k, my - k * mx, (sum(r * r for r in res) / n) ** 0.5
