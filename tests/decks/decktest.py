#!/usr/bin/env python3
"""Deck-level tests of liggghts-tri: each test runs real decks through the driver and checks
numbers in its dumps and output. Standard library only (it runs under any python3).

usage: decktest.py TEST --exe PATH --work DIR [--vtkdump PATH]
"""
import argparse
import math
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
           "OMPI_MCA_rmaps_base_oversubscribe": "1", "OMP_NUM_THREADS": "1"}


class Failure(Exception):
    pass


def check(cond, message):
    if not cond:
        raise Failure(message)


def run_deck(ctx, deck, variables=None, ranks=1, expect_ok=True):
    """Runs one deck in ctx.work; returns the combined screen output."""
    cmd = [ctx.exe, "-in", os.path.join(HERE, deck), "-var", "dir", HERE, "-log", "none"]
    for k, v in (variables or {}).items():
        cmd += ["-var", k, str(v)]
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks)] + cmd
    env = dict(os.environ, **MPI_ENV)
    p = subprocess.run(cmd, cwd=ctx.work, env=env, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True, errors="replace", timeout=600)
    if expect_ok and p.returncode != 0:
        raise Failure(f"{' '.join(cmd)} exited {p.returncode}:\n{p.stdout[-3000:]}")
    return p.returncode, p.stdout


def last_frame(path):
    """The last snapshot of a LIGGGHTS custom dump: (step, {id: [fields as strings]})."""
    with open(path) as f:
        lines = f.read().splitlines()
    starts = [i for i, l in enumerate(lines) if l.startswith("ITEM: TIMESTEP")]
    check(starts, f"{path} holds no snapshot")
    s = starts[-1]
    step = int(lines[s + 1])
    n = int(lines[s + 3])
    rows = {}
    for l in lines[s + 9: s + 9 + n]:
        fields = l.split()
        rows[int(fields[0])] = fields[1:]
    return step, rows


# --------------------------------------------------------------------------------------------

def test_help(ctx):
    p = subprocess.run([ctx.exe, "-h"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True, errors="replace", timeout=120, env=dict(os.environ, **MPI_ENV))
    for style in ("tri/particles", "tri/nve", "tri/vtk", "tri/gran", "tri/wall", "tri/adapt_dt",
                  "tri/stats"):
        check(style in p.stdout, f"'liggghts-tri -h' does not list {style}")
    check("Pair styles" in p.stdout and "gran" in p.stdout,
          "'liggghts-tri -h' lost LIGGGHTS's own style list")


def test_freefall(ctx):
    run_deck(ctx, "in.freefall")
    step, rows = last_frame(os.path.join(ctx.work, "freefall.dump"))
    check(step == 10000, f"last frame at step {step}")
    f = [float(v) for v in rows[1]]
    t = step * 1e-5
    x0, v0, g = (0.001, -0.002, 0.03), (0.1, -0.05, 0.2), (0.0, 0.0, -9.81)
    for k in range(3):
        exact = x0[k] + v0[k] * t + 0.5 * g[k] * t * t
        check(abs(f[k] - exact) < 1e-12, f"x[{k}] = {f[k]!r}, parabola gives {exact!r}")
        check(abs(f[3 + k] - (v0[k] + g[k] * t)) < 1e-12, f"v[{k}] off the analytic value")
    q = f[10:14]
    check(abs(math.sqrt(sum(c * c for c in q)) - 1.0) < 1e-12, "quaternion lost its norm")
    # The particle must really spin: the orientation differs from the initial one and the
    # space-frame angular momentum is conserved (no torque) to round-off.
    _, first = first_frame(os.path.join(ctx.work, "freefall.dump"))
    q0 = [float(v) for v in first[1][10:14]]
    check(abs(sum(a * b for a, b in zip(q, q0))) < 0.999, "the particle did not rotate")
    L0 = [float(v) for v in first[1][14:17]]
    L = f[14:17]
    normL = math.sqrt(sum(c * c for c in L0))
    check(normL > 0, "no angular momentum was set from omega")
    for k in range(3):
        check(abs(L[k] - L0[k]) < 1e-12 * normL, f"L[{k}] drifted: {L0[k]!r} -> {L[k]!r}")


def first_frame(path):
    with open(path) as f:
        lines = f.read().splitlines()
    n = int(lines[3])
    rows = {}
    for l in lines[9: 9 + n]:
        fields = l.split()
        rows[int(fields[0])] = fields[1:]
    return int(lines[1]), rows


FLIGHT_PERIODIC = {"bx": "p", "by": "p"}


def test_restart(ctx):
    run_deck(ctx, "in.flight_full", dict(FLIGHT_PERIODIC, px=1, phase="full"))
    run_deck(ctx, "in.flight_first", dict(FLIGHT_PERIODIC, px=1, phase="first"))
    run_deck(ctx, "in.flight_resume", {"phase": "second"})
    step_a, full = last_frame(os.path.join(ctx.work, "flight_full.dump"))
    step_b, resumed = last_frame(os.path.join(ctx.work, "flight_second.dump"))
    check(step_a == step_b == 4000, f"frames at steps {step_a} and {step_b}")
    check(len(full) == 15, f"{len(full)} atoms, expected 15")
    for tag in full:
        check(full[tag] == resumed[tag],
              f"atom {tag} differs after restart:\n {full[tag]}\n {resumed[tag]}")


def test_ranks(ctx):
    run_deck(ctx, "in.flight_full", dict(FLIGHT_PERIODIC, px=1, phase="serial"))
    out_dir = ctx.work
    run_deck(ctx, "in.flight_full", dict(FLIGHT_PERIODIC, px=2, phase="mpi"), ranks=2)
    _, first = first_frame(os.path.join(out_dir, "flight_serial.dump"))
    _, serial = last_frame(os.path.join(out_dir, "flight_serial.dump"))
    _, mpi = last_frame(os.path.join(out_dir, "flight_mpi.dump"))
    check(len(serial) == len(mpi) == 15, "atoms were lost")
    crossed = sum(1 for t in serial if (float(first[t][0]) < 0) != (float(serial[t][0]) < 0))
    check(crossed >= 3, f"only {crossed} particles crossed the subdomain boundary x = 0")
    # Free flight involves no sums over atoms, so the split cannot change a single bit.
    for tag in serial:
        check(serial[tag] == mpi[tag], f"atom {tag}: 1 rank {serial[tag]} != 2 ranks {mpi[tag]}")


def test_vtk(ctx):
    for ranks in (1, 2):
        sub = os.path.join(ctx.work, f"np{ranks}")
        os.makedirs(sub, exist_ok=True)
        sub_ctx = argparse.Namespace(**vars(ctx))
        sub_ctx.work = sub
        run_deck(sub_ctx, "in.vtk_output", dict(FLIGHT_PERIODIC, px=ranks), ranks=ranks)
        ext = "vtp" if ranks == 1 else "pvtp"
        frame = os.path.join(sub, "post", f"particles_1000.{ext}")
        check(os.path.exists(frame), f"{frame} was not written")
        pvd = open(os.path.join(sub, "post", "particles.pvd")).read()
        for step in (0, 500, 1000):
            check(f"particles_{step}.{ext}" in pvd, f"particles.pvd does not list step {step}")
        p = subprocess.run([ctx.vtkdump, frame], stdout=subprocess.PIPE, text=True, check=True)
        cells = [l.split() for l in p.stdout.splitlines() if l and not l.startswith("#")]
        _, atoms = last_frame(os.path.join(sub, "vtk.dump"))
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


# --------------------------------------------------------------------------------------------
# Bad input: each case is a deck that must stop with a LIGGGHTS error naming the problem.

def write_stl(path, triangles):
    with open(path, "w") as f:
        f.write("solid t\n")
        for tri in triangles:
            f.write(" facet normal 0 0 0\n  outer loop\n")
            for p in tri:
                f.write("   vertex %s %s %s\n" % tuple(p))
            f.write("  endloop\n endfacet\n")
        f.write("endsolid t\n")


def tetra():
    a, b, c, d = (0, 0, 0), (0.002, 0, 0), (0, 0.002, 0), (0, 0, 0.002)
    return [[a, c, b], [a, b, d], [a, d, c], [b, c, d]]


def cube():
    v = [(x * 0.002, y * 0.002, z * 0.002) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    return [[v[a], v[b], v[c]] for a, b, c, d in quads] + [[v[a], v[c], v[d]] for a, b, c, d in quads]


def make_bad_meshes(work):
    t = tetra()
    write_stl(os.path.join(work, "open.stl"), cube()[:-1])
    write_stl(os.path.join(work, "flipped.stl"), [t[0], t[1], t[2], [t[3][0], t[3][2], t[3][1]]])
    write_stl(os.path.join(work, "inverted.stl"), [[x[0], x[2], x[1]] for x in t])
    write_stl(os.path.join(work, "nan.stl"), [[("nan", 0, 0)] + t[0][1:]] + t[1:])
    with open(os.path.join(work, "garbage.stl"), "w") as f:
        f.write("solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0\n")
    with open(os.path.join(work, "truncated.stl"), "wb") as f:
        f.write(b"\0" * 80 + (1000).to_bytes(4, "little") + b"\0" * 60)


ROCK = "shape r random ntri 20 size 0.004 seed 1"
TAIL = "density 2500 epsilon 0.0001"
BAD_INPUT = {
    "missing_file": (f"shape m file nosuch.stl {TAIL}", r"nosuch\.stl"),
    "garbage_file": (f"shape m file garbage.stl {TAIL}", r"garbage\.stl"),
    "truncated_file": (f"shape m file truncated.stl {TAIL}", r"truncated\.stl"),
    "unknown_extension": (f"shape m file mesh.xyz {TAIL}", r"mesh\.xyz"),
    "open_mesh": (f"shape m file open.stl {TAIL}", r"open\.stl.*not closed"),
    "flipped_mesh": (f"shape m file flipped.stl {TAIL}", r"flipped\.stl.*orient"),
    "inverted_mesh": (f"shape m file inverted.stl {TAIL}", r"inverted\.stl.*(inverted|inward|negative)"),
    "nan_mesh": (f"shape m file nan.stl {TAIL}", r"nan\.stl.*(NaN|finite|nan)"),
    "odd_ntri": (f"shape r random ntri 21 size 0.004 seed 1 {TAIL}", r"ntri.*even"),
    "small_ntri": (f"shape r random ntri 2 size 0.004 seed 1 {TAIL}", r"ntri"),
    "zero_epsilon": (f"{ROCK} density 2500 epsilon 0", r"epsilon.*> 0"),
    "negative_density": (f"{ROCK} density -1 epsilon 0.0001", r"density.*> 0"),
    "unknown_keyword": (f"{ROCK} {TAIL} colour red", r"unknown keyword 'colour'"),
    "missing_epsilon": (f"{ROCK} density 2500", r"'epsilon' is required"),
    "no_shape": (TAIL, r"at least one 'shape'"),
    "too_large": (f"shape r random ntri 20 size 0.5 seed 1 {TAIL}", r"does not fit"),
}
BAD_DECKS = {
    "nve_without_particles": ("in.bad_nve", r"tri/nve requires fix tri/particles"),
    "vtk_without_particles": ("in.bad_vtk", r"tri/vtk requires fix tri/particles"),
    "atom_style_without_radius": ("in.bad_atom_style", r"requires atom_style sphere"),
}


def test_bad_input(ctx):
    import re
    make_bad_meshes(ctx.work)
    failures = []
    cases = {k: ("in.bad_particles", v[1], {"args": v[0]}) for k, v in BAD_INPUT.items()}
    cases.update({k: (v[0], v[1], {}) for k, v in BAD_DECKS.items()})
    for name, (deck, pattern, variables) in sorted(cases.items()):
        code, out = run_deck(ctx, deck, variables, expect_ok=False)
        errors = [l for l in out.splitlines() if "ERROR" in l]
        if code == 0 or not errors or not re.search(pattern, " ".join(errors)):
            failures.append(f"{name}: exit {code}, errors {errors or out[-800:]!r}, wanted /{pattern}/")
        elif any(s in out for s in ("Segmentation", "signal", "core dumped")):
            failures.append(f"{name}: crashed instead of a clean error")
        else:
            print(f"{name}: {errors[0].strip()}")
    check(not failures, "\n".join(failures))


TESTS = {name[5:]: fn for name, fn in globals().items() if name.startswith("test_")}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("test", choices=sorted(TESTS))
    ap.add_argument("--exe", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--vtkdump")
    ctx = ap.parse_args()
    shutil.rmtree(ctx.work, ignore_errors=True)
    os.makedirs(ctx.work)
    try:
        TESTS[ctx.test](ctx)
    except Failure as e:
        print(f"FAIL {ctx.test}: {e}")
        return 1
    print(f"PASS {ctx.test}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
