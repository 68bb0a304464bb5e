#!/usr/bin/env python3
"""Deck-level tests of liggghts-tri: each test runs real decks through the driver and checks
numbers in its dumps and output. Standard library only (it runs under any python3).

usage: decktest.py TEST --exe PATH --work DIR [--vtkdump PATH]
"""
import argparse
import math
import os
import shutil
import struct
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


def run_deck(ctx, deck, variables=None, ranks=1, expect_ok=True, env_extra=None):
    """Runs one deck in ctx.work; returns the combined screen output. `env_extra` adds to (and
    overrides) the environment, e.g. OMP_NUM_THREADS."""
    cmd = [ctx.exe, "-in", os.path.join(HERE, deck), "-var", "dir", HERE, "-log", "none"]
    for k, v in (variables or {}).items():
        cmd += ["-var", k, str(v)]
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks)] + cmd
    env = dict(os.environ, **MPI_ENV)
    env.update(env_extra or {})
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


def test_peratom_variable(ctx):
    run_deck(ctx, "in.peratom_variable", dict(FLIGHT_PERIODIC, px=1))
    _, rows = last_frame(os.path.join(ctx.work, "peratom.dump"))
    check(len(rows) == 15, f"{len(rows)} atoms")
    for tag, r in rows.items():
        for k in (0, 2, 4):
            check(r[k] == r[k + 1], f"atom {tag}: f_shapes column {r[k]} but variable {r[k + 1]}")
    check(len({r[2] for r in rows.values()}) > 1, "all atoms have the same orientation")


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
    a, b = (0, 0, 0), (0.002, 0, 0)
    write_stl(os.path.join(work, "degenerate.stl"), t[:3] + [[a, b, (0.001, 0, 0)]])
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
    "degenerate_mesh": (f"shape m file degenerate.stl {TAIL}", r"degenerate\.stl.*degenerate"),
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


# --------------------------------------------------------------------------------------------
# Contacts (pair tri/gran, fix tri/wall, compute tri/stats, fix tri/adapt_dt).

MESHGEN = os.path.join(HERE, "..", "..", "validation", "meshes", "meshgen.py")
EPS = 1e-4            # the particles' soft layer in the contact decks
SIDE = 0.004          # cube.stl: 2 x 2 squares per face, side 4 mm, centred
DENSITY = 2500.0
BOX_HALF, BOX_HEIGHT = 0.0045, 0.02   # box.stl of the cluster decks


def make_contact_meshes(work):
    subprocess.run([sys.executable, MESHGEN, "cube", "2", repr(SIDE), "cube.stl"], cwd=work,
                   check=True)
    subprocess.run([sys.executable, MESHGEN, "plane", "0.01", "plane.stl"], cwd=work, check=True)
    w, h = BOX_HALF, BOX_HEIGHT

    def quad(a, b, c, d):
        return [[a, b, c], [a, c, d]]
    write_stl(os.path.join(work, "box.stl"),
              quad((-w, -w, 0), (w, -w, 0), (w, w, 0), (-w, w, 0))
              + quad((-w, -w, 0), (-w, w, 0), (-w, w, h), (-w, -w, h))
              + quad((w, -w, 0), (w, -w, h), (w, w, h), (w, w, 0))
              + quad((-w, -w, 0), (-w, -w, h), (w, -w, h), (w, -w, 0))
              + quad((-w, w, 0), (w, w, 0), (w, w, h), (-w, w, h)))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def thermo_rows(out):
    """Every thermo row of a screen output: list of dicts keyed by the header's words."""
    rows, header = [], None
    for line in out.splitlines():
        words = line.split()
        if words and words[0] == "Step":
            header = words
            continue
        if header and len(words) == len(header):
            try:
                rows.append(dict(zip(header, (float(w) for w in words))))
                continue
            except ValueError:
                pass
        if words and words[0] == "Loop":   # other lines (e.g. tri/adapt_dt's) may interleave
            header = None
    return rows


# Material of in.contact_pair / in.contact_wall
MAT = {"kn": 2000.0, "kt": 1000.0, "gamman": 20.0, "gammat": 10.0, "mu": 0.5}


def test_contact_forces(ctx):
    """Forces and torques of one evaluation (run 0) against hand-computed values."""
    make_contact_meshes(ctx.work)
    h = SIDE / 2                        # half side of the mesh as read (ASCII STL: doubles)
    mass = DENSITY * (2 * h) ** 3
    kn, kt, gn, gt, mu = (MAT[k] for k in ("kn", "kt", "gamman", "gammat", "mu"))
    dt = 1e-5
    # bf: exact geometry, so 1e-12 of the normal force. hybrid: distances within its
    # documented tolerance 1e-4 * epsilon (particle_contacts.h), so the normal force within
    # kn * 1e-8 N; the normal is the direction between closest points 1e-4 m apart, each
    # within 1e-8 m, so lateral force and torque within 1e-4 of F (and F * h).
    rel = {"bf": 1e-12, "hybrid": 1e-4}

    def pair_case(name, kernel, gap, yb=0.0, vxa=0.0, vxb=0.0, vzb=0.0, gamman=0.0, gammat=0.0):
        xa, xb = -(h + gap / 2), h + gap / 2
        v = dict(MAT, xa=repr(xa), xb=repr(xb), yb=repr(yb), vxa=vxa, vxb=vxb, vzb=vzb,
                 gamman=gamman, gammat=gammat, pairargs=f"kernel {kernel}")
        run_deck(ctx, "in.contact_pair", v)
        step, rows = last_frame(os.path.join(ctx.work, "contact.dump"))
        check(step == 0 and len(rows) == 2, f"{name}: frame at step {step} with {len(rows)} atoms")
        a, b = ([float(x) for x in rows[t]] for t in (1, 2))
        check(abs(a[9] - mass) <= 1e-12 * mass, f"{name}: mass {a[9]!r}, cube gives {mass!r}")
        fa, fb, ta, tb = a[3:6], b[3:6], a[6:9], b[6:9]
        # Expected (n = +x from a to b): F_n = kn overlap - gamman m_eff v_n on b, friction
        # from b's sliding along z: history spring kt v dt plus damping, capped by mu F_n.
        overlap = 2 * EPS - gap
        if overlap <= 0:
            fb_exp = [0.0, 0.0, 0.0]
        else:
            meff = mass / 2
            fn = kn * overlap - gamman * meff * (vxb - vxa)
            ft = kt * abs(vzb) * dt + gammat * meff * abs(vzb)
            ft = min(ft, mu * fn) * (1 if vzb > 0 else -1 if vzb < 0 else 0)
            fb_exp = [fn, 0.0, -ft]
        ylo, yhi = max(-h, yb - h), min(h, yb + h)
        p = [(xa + xb) / 2, (ylo + yhi) / 2, 0.0]          # centre of the faces' overlap
        fa_exp = [-c for c in fb_exp]
        ta_exp = cross([p[0] - xa, p[1], p[2]], fa_exp)
        tb_exp = cross([p[0] - xb, p[1] - yb, p[2]], fb_exp)
        scale = max(abs(fb_exp[0]), 1e-300)
        tol_f, tol_t = rel[kernel] * scale, rel[kernel] * scale * h
        for k in range(3):
            check(abs(fb[k] - fb_exp[k]) <= tol_f,
                  f"{name}: force on b {fb}, hand-computed {fb_exp} (tolerance {tol_f:g} N)")
            check(fa[k] == -fb[k], f"{name}: forces not opposite: {fa} vs {fb}")
            check(abs(ta[k] - ta_exp[k]) <= tol_t,
                  f"{name}: torque on a {ta}, hand-computed {ta_exp} (tolerance {tol_t:g} N m)")
            check(abs(tb[k] - tb_exp[k]) <= tol_t,
                  f"{name}: torque on b {tb}, hand-computed {tb_exp} (tolerance {tol_t:g} N m)")
        print(f"{name}: f_b {fb} (hand {fb_exp}), torque a {ta} (hand {ta_exp})")

    def wall_case(name, kernel, gap, eps_wall=None, vz=0.0, gamman=0.0):
        zc = h + gap
        args = f"kernel {kernel}" + (f" epsilon {eps_wall!r}" if eps_wall else "")
        run_deck(ctx, "in.contact_wall", dict(MAT, zc=repr(zc), vz=vz, gamman=gamman,
                                               wallargs=args))
        step, rows = last_frame(os.path.join(ctx.work, "contact.dump"))
        a = [float(x) for x in rows[1]]
        f, t = a[3:6], a[6:9]
        overlap = EPS + (eps_wall or EPS) - gap
        # n from the particle to the wall is -z; v_n = (v_wall - v) . n = vz; m_eff = m.
        fz = kn * overlap - gamman * mass * vz if overlap > 0 else 0.0
        scale = max(fz, 1e-300)
        tol = rel[kernel] * scale
        check(abs(f[2] - fz) <= tol and abs(f[0]) <= tol and abs(f[1]) <= tol,
              f"{name}: wall force {f}, hand-computed (0, 0, {fz!r}) (tolerance {tol:g} N)")
        check(all(abs(c) <= tol * h for c in t), f"{name}: torque {t} on a centred cube")
        print(f"{name}: f {f} (hand fz {fz!r}), torque {t}")

    pair_case("pair_rest_bf", "bf", gap=1e-4)
    pair_case("pair_rest_hybrid", "hybrid", gap=1e-4)
    pair_case("pair_apart_bf", "bf", gap=2.5e-4)
    pair_case("pair_approach_damped_bf", "bf", gap=1e-4, vxa=0.1, vxb=-0.1, gamman=gn)
    pair_case("pair_offset_bf", "bf", gap=1e-4, yb=0.001)
    pair_case("pair_sliding_bf", "bf", gap=1.2e-4, vzb=1.0, gamman=gn, gammat=gt)
    pair_case("pair_sliding_coulomb_bf", "bf", gap=1e-4, yb=0.0005, vzb=20.0, gammat=gt)
    wall_case("wall_eps_bf", "bf", gap=1e-4, eps_wall=5e-5)
    wall_case("wall_default_eps_bf", "bf", gap=1e-4)
    wall_case("wall_approach_hybrid", "hybrid", gap=1e-4, eps_wall=5e-5, vz=-0.1, gamman=gn)
    wall_case("wall_apart_bf", "bf", gap=2e-4, eps_wall=5e-5)


CLUSTER_OUT = ("cluster_{}.dump")


def cluster_contacts(out):
    rows = thermo_rows(out)
    check(rows, "no thermo rows in the cluster output")
    return max(r["stats[2]"] for r in rows)


def test_threads(ctx):
    """The cluster with 1 and 2 OpenMP threads, parallel pairs and parallel triangles: the
    final dumps (%.17g) must be identical."""
    make_contact_meshes(ctx.work)
    dumps = {}
    for loop in ("pairs", "triangles"):
        for threads in (1, 2):
            phase = f"{loop}_t{threads}"
            _, out = run_deck(ctx, "in.contact_cluster",
                              {"phase": phase, "nsteps": 2000, "pairargs": f"parallel {loop}"},
                              env_extra={"OMP_NUM_THREADS": str(threads)})
            check(cluster_contacts(out) > 0, f"{phase}: no contacts in the cluster")
            step, dumps[phase] = last_frame(os.path.join(ctx.work, CLUSTER_OUT.format(phase)))
            check(step == 2000 and len(dumps[phase]) == 8, f"{phase}: step {step}, "
                  f"{len(dumps[phase])} atoms")
    ref = dumps["pairs_t1"]
    for phase, rows in dumps.items():
        for tag in ref:
            check(rows[tag] == ref[tag], f"atom {tag}: {phase} differs from pairs_t1:\n "
                  f"{rows[tag]}\n {ref[tag]}")


def test_restart_contacts(ctx):
    """2N steps against N + write_restart + (new process) read_restart + N, with rock-rock
    and rock-wall contacts (tangential history) active at the restart step."""
    make_contact_meshes(ctx.work)
    n = 3000  # rock-rock and rock-wall contacts both active at step n (checked below)
    run_deck(ctx, "in.contact_cluster", {"phase": "full", "nsteps": 2 * n})
    _, out = run_deck(ctx, "in.contact_cluster_restart",
                      {"phase": "first", "nsteps": n, "thermo_every": n})
    run_deck(ctx, "in.contact_cluster_resume", {"phase": "second", "nsteps": n})
    at_n = [r for r in thermo_rows(out) if r["Step"] == n]
    check(len(at_n) == 2, f"expected two thermo rows at step {n}, got {at_n}")
    total, pairs_only = at_n[0]["stats[2]"], at_n[1]["stats[2]"]
    print(f"at the restart step: {total:g} contacts, {pairs_only:g} of them rock-rock")
    check(pairs_only > 0, "no rock-rock contact at the restart step: the test would not see "
                          "the pair history")
    check(total - pairs_only > 0, "no rock-wall contact at the restart step")
    _, full = last_frame(os.path.join(ctx.work, CLUSTER_OUT.format("full")))
    _, resumed = last_frame(os.path.join(ctx.work, CLUSTER_OUT.format("second")))
    first_diff = [t for t in full if full[t] != resumed[t]]
    check(not first_diff, f"atoms {first_diff} differ after the restart, e.g. atom "
          f"{first_diff[:1]}:\n {full[first_diff[0]] if first_diff else ''}\n "
          f"{resumed[first_diff[0]] if first_diff else ''}")


def compare_columns(serial, mpi, tol, what):
    """Largest difference per column relative to the column's largest magnitude; checks tol."""
    worst = 0.0
    ncol = len(next(iter(serial.values())))
    for k in range(ncol):
        scale = max(abs(float(r[k])) for r in serial.values())
        for tag in serial:
            d = abs(float(serial[tag][k]) - float(mpi[tag][k]))
            r = d / scale if scale > 0 else d
            worst = max(worst, r)
            check(r <= tol, f"{what}: atom {tag} column {k + 1}: 1 rank {serial[tag][k]}, "
                            f"2 ranks {mpi[tag][k]} (relative {r:.3g} > {tol:g})")
    return worst


def test_ranks_contacts(ctx):
    """1 and 2 MPI ranks (processors 2 1 1, boundary x = 0): a colliding pair across the
    boundary and the cluster. Not bitwise: the rank that owns j evaluates the pair as (j, i),
    and body_interaction(j, i) equals -body_interaction(i, j) only to rounding (measured 1e-15
    relative after one collision); in the cluster the order of the force sums on an atom
    differs too. Chaotic collisions amplify that, so the runs are short and the kernel of the
    cluster is brute force: the hybrid kernel's accept/fallback decision can flip on a
    last-bit difference and then moves a distance by up to its tolerance 1e-4 eps (measured:
    1e-14 -> 4e-9 in one collision at step 1200). Tolerance: 1e-10 of each column's largest
    magnitude."""
    make_contact_meshes(ctx.work)
    tol = 1e-10
    outs = {}
    for ranks in (1, 2):
        phase = "serial" if ranks == 1 else "mpi"
        run_deck(ctx, "in.contact_collide", {"px": ranks, "phase": phase}, ranks=ranks)
        with open(os.path.join(ctx.work, f"touch_{phase}.txt")) as f:
            touching = sum(1 for l in f if l.startswith("touch") and float(l.split()[1]) > 0)
        check(touching > 10, f"collide, {ranks} ranks: in contact on {touching} steps only")
        _, outs[("collide", ranks)] = last_frame(os.path.join(ctx.work, f"collide_{phase}.dump"))
        _, out = run_deck(ctx, "in.contact_cluster",
                          {"px": ranks, "phase": phase, "nsteps": 1500, "pairargs": "kernel bf"},
                          ranks=ranks)
        check(cluster_contacts(out) > 0, f"cluster, {ranks} ranks: no contacts")
        _, outs[("cluster", ranks)] = last_frame(os.path.join(ctx.work, CLUSTER_OUT.format(phase)))
    _, first = first_frame(os.path.join(ctx.work, "collide_serial.dump"))
    check(float(first[1][0]) < 0 < float(first[2][0]), "the pair does not start on both ranks")
    for what, natoms in (("collide", 2), ("cluster", 8)):
        serial, mpi = outs[(what, 1)], outs[(what, 2)]
        check(len(serial) == len(mpi) == natoms, f"{what}: atoms were lost")
        sides = {float(r[0]) < 0 for r in serial.values()}
        bitwise = all(serial[t] == mpi[t] for t in serial)
        worst = compare_columns(serial, mpi, tol, what)
        print(f"{what}: 1 vs 2 ranks {'bitwise equal' if bitwise else 'not bitwise'}, "
              f"largest relative difference {worst:.3g} (tolerance {tol:g}); atoms on "
              f"{len(sides)} sides of x = 0 at the end")


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
    "pair_newton_on": ({"newton": "on off"},
                       r"Pair granular with shear history requires newton pair off"),
}


def test_bad_contact_input(ctx):
    import re
    make_contact_meshes(ctx.work)
    # The deck with no line swapped runs: each error below comes from its one changed line.
    run_deck(ctx, "in.contact_bad")
    failures = []
    for name, (variables, pattern) in sorted(BAD_CONTACT.items()):
        code, out = run_deck(ctx, "in.contact_bad", variables, expect_ok=False)
        errors = [l for l in out.splitlines() if "ERROR" in l]
        if code == 0 or not errors or not re.search(pattern, " ".join(errors)):
            failures.append(f"{name}: exit {code}, errors {errors or out[-800:]!r}, wanted /{pattern}/")
        elif any(s in out for s in ("Segmentation", "signal", "core dumped")):
            failures.append(f"{name}: crashed instead of a clean error")
        else:
            print(f"{name}: {errors[0].strip()}")
    check(not failures, "\n".join(failures))


def test_stats_and_adapt_dt(ctx):
    """compute tri/stats in thermo and fix tri/adapt_dt's rule on two approaching cubes."""
    import re
    make_contact_meshes(ctx.work)
    dtmax, dtmin, fraction = 2e-6, 2.5e-7, 0.2
    _, out = run_deck(ctx, "in.contact_adapt")
    rows = thermo_rows(out)
    check(len(rows) > 100, f"{len(rows)} thermo rows")
    for r in rows:
        check(r["stats[6]"] <= r["stats[5]"], f"step {r['Step']:g}: {r['stats[6]']:g} contacts "
              f"after reduction > {r['stats[5]']:g} before")
        check(dtmin * (1 - 1e-12) <= r["adt[1]"] <= dtmax * (1 + 1e-12),
              f"step {r['Step']:g}: dt {r['adt[1]']!r} outside [dtmin, dtmax]")
    touching = [r for r in rows if r["stats[2]"] > 0]
    check(touching, "the cubes never touched")
    check(all(r["stats[1]"] > 0 and r["stats[3]"] > 0 for r in touching),
          "pairs in contact without particle pairs checked or triangle pairs tested")
    check(max(r["stats[5]"] for r in touching) > max(r["stats[6]"] for r in touching) == 1,
          "two touching faces did not reduce to one contact point")
    check(min(r["dmin"] for r in touching) < fraction * EPS,
          "the cubes never came closer than 0.2 epsilon")
    check(rows[-1]["stats[2]"] == 0, "the cubes did not separate")
    lines = re.findall(r"tri/adapt_dt: step (\d+): dt (\S+) -> (\S+) \((.*)\)", out)
    check(lines, "fix tri/adapt_dt printed no change")
    growths = halvings = 0
    by_step = {int(r["Step"]): r for r in rows}
    for step, a, b, why in lines:
        a, b = float(a), float(b)
        if why == "no contact":
            growths += 1
            check(abs(b - min(1.1 * a, dtmax)) <= 1e-5 * b, f"step {step}: {a} -> {b} is not "
                  "a 10% growth bounded by dtmax")
        elif why.startswith("a contact closer"):
            halvings += 1
            check(abs(b - max(0.5 * a, dtmin)) <= 1e-5 * b, f"step {step}: {a} -> {b} is not "
                  "a halving bounded by dtmin")
            r = by_step.get(int(step))
            check(r is None or r["dmin"] < fraction * EPS,
                  f"step {step}: halved with the closest distance {r and r['dmin']}")
        else:
            raise Failure(f"unexpected reason '{why}'")
    check(halvings >= 3 and growths >= 8, f"{halvings} halvings, {growths} growths")
    check(any(float(b) == dtmax for _, _, b, w in lines if w == "no contact"),
          "dt never reached dtmax")
    check(any(float(b) == dtmin for _, _, b, w in lines if w != "no contact"),
          "dt never reached dtmin")
    # After the contact: growth again up to dtmax.
    last_halving = max(int(s) for s, _, _, w in lines if w != "no contact")
    check(any(int(s) > last_halving and w == "no contact" for s, _, _, w in lines),
          "dt did not grow again once the cubes separated")
    check(rows[-1]["adt[1]"] == dtmax, f"final dt {rows[-1]['adt[1]']!r}, expected dtmax")
    print(f"{halvings} halvings, {growths} growths; closest distance "
          f"{min(r['dmin'] for r in touching):.4g} m; contacts before/after reduction "
          f"up to {max(r['stats[5]'] for r in touching):g}/"
          f"{max(r['stats[6]'] for r in touching):g}")


# --------------------------------------------------------------------------------------------
# Extreme input: shapes of 1e5 triangles, particles created inside each other, 100 m/s.

def expect_error(ctx, deck, variables, pattern):
    """Runs a deck that must stop with a LIGGGHTS error matching `pattern`; returns the line."""
    import re
    code, out = run_deck(ctx, deck, variables, expect_ok=False)
    errors = [l.strip() for l in out.splitlines() if "ERROR" in l]
    check(not any(s in out for s in ("Segmentation", "signal", "core dumped")),
          f"{deck} {variables}: crashed:\n{out[-2000:]}")
    check(code != 0 and errors and re.search(pattern, " ".join(errors)),
          f"{deck} {variables}: exit {code}, errors {errors or out[-1500:]!r}, wanted /{pattern}/")
    return errors[0]


def write_binary_stl(path, triangles):
    with open(path, "wb") as f:
        f.write(b"\0" * 80 + struct.pack("<I", len(triangles)))
        for t in triangles:
            f.write(struct.pack("<12fH", 0, 0, 0, *t[0], *t[1], *t[2], 0))


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


def test_extreme_shapes(ctx):
    """1e5-triangle shapes: a file one works (set-up and contacts in seconds, `cull no`
    included); a random rock finer than its soft layer stops with the limit's message; a shape
    larger than the box stops (also in test_bad_input)."""
    import time
    make_contact_meshes(ctx.work)
    write_binary_stl(os.path.join(ctx.work, "bigcube.stl"), fine_cube(92, 0.4))
    for pairstyle in ("tri/gran", "tri/gran cull no"):
        start = time.time()
        _, out = run_deck(ctx, "in.extreme_big", {"pairstyle": pairstyle})
        seconds = time.time() - start
        rows = thermo_rows(out)
        check(len(rows) == 5, f"{pairstyle}: {len(rows)} thermo rows")
        for r in rows:
            check(r["Atoms"] == 2, f"{pairstyle}: step {r['Step']:g}: {r['Atoms']:g} atoms")
            check(r["stats[2]"] == 1 and r["stats[6]"] == 1 and r["stats[9]"] == 0,
                  f"{pairstyle}: step {r['Step']:g}: not one clean contact: {r}")
            # kn 2000 N/m, soft-layer overlap 1.5e-4 m: 0.3 N, pushing the cubes apart.
            check(math.isfinite(r["fx1"]) and -0.31 < r["fx1"] < -0.29
                  and r["fx2"] == -r["fx1"], f"{pairstyle}: step {r['Step']:g}: forces "
                  f"{r['fx1']}, {r['fx2']}")
        print(f"101568 + 48 triangles, {pairstyle}: {rows[-1]['stats[3]']:g} triangle pairs "
              f"tested per step, {rows[-1]['stats[5]']:g} contacts -> 1, fx {rows[-1]['fx1']:.4g} "
              f"N; {seconds:.1f} s with set-up")
    line = expect_error(ctx, "in.bad_particles",
                        {"args": "shape r random ntri 100000 size 0.004 seed 1 " + TAIL},
                        r"shape r \(100000 triangles\) has a mean edge length of \S+ m, shorter "
                        r"than epsilon \(0\.0001 m\).*coarser mesh \(about \d+ triangles")
    print(f"ntri 100000, size 4 mm: {line}")
    line = expect_error(ctx, "in.bad_particles", {"args": BAD_INPUT["too_large"][0]},
                        r"does not fit in the simulation box")
    print(f"size 0.5 m in a 0.04 m box: {line}")


def test_extreme_motion(ctx):
    """Two cubes launched at each other at 100 m/s: with fix tri/adapt_dt they bounce (no
    intersection, no tunnelling, no NaN); without it the run stops naming the speed and dt.
    Particles created inside each other and a wall: the first step stops; the same deck with
    the particles apart runs."""
    import re
    make_contact_meshes(ctx.work)
    line = expect_error(ctx, "in.extreme_fast", {},
                        r"step 1: particles 1 and 2 meet at 200 m/s, 0\.002 m per time step of "
                        r"1e-05 s, more than epsilon \(0\.0001 m\).*use a smaller timestep or "
                        r"fix tri/adapt_dt")
    print(f"100 m/s, dt 1e-5, no tri/adapt_dt: {line}")
    line = expect_error(ctx, "in.extreme_fast",
                        {"adapt": "fix adt all tri/adapt_dt dtmax 1e-5 dtmin 1e-6"},
                        r"particles 1 and 2 meet at .*lower dtmin of fix tri/adapt_dt")
    print(f"100 m/s, tri/adapt_dt with dtmin 1e-6: {line}")

    _, out = run_deck(ctx, "in.extreme_fast",
                      {"adapt": "fix adt all tri/adapt_dt dtmax 1e-5 dtmin 1e-10"})
    rows = thermo_rows(out)
    check(len(rows) == 151, f"{len(rows)} thermo rows")
    for r in rows:
        check(all(math.isfinite(v) for v in r.values()), f"step {r['Step']:g}: not finite: {r}")
        check(r["stats[9]"] == 0, f"step {r['Step']:g}: real surfaces intersect")
        # Faces 4 mm apart at centre distance 4 mm: x2 - x1 > 4 mm means no face went through.
        check(r["x2"] - r["x1"] > 0.004, f"step {r['Step']:g}: centres "
              f"{r['x2'] - r['x1']:.6g} m apart: the cubes went into each other")
        check(r["Dt"] <= 1e-5 * (1 + 1e-12), f"step {r['Step']:g}: dt {r['Dt']} > dtmax")
    touching = [r for r in rows if r["stats[2]"] > 0]
    check(touching, "the cubes never touched")
    for r in touching:
        # 0.5 epsilon per step at 200 m/s; the reactive halving may lower it further.
        check(r["Dt"] <= 2.5e-7 * (1 + 1e-9), f"step {r['Step']:g}: dt {r['Dt']} in contact")
    deepest = min(r["dmin"] for r in touching)
    last = rows[-1]
    check(last["stats[2]"] == 0 and last["vx1"] < 0 < last["vx2"],
          f"no bounce: final velocities {last['vx1']}, {last['vx2']}")
    energy = (last["vx1"] ** 2 + last["vx2"] ** 2) / (2 * 100.0 ** 2)
    check(0.98 < energy < 1.02, f"undamped bounce kept {energy:.4f} of the kinetic energy")
    check(last["Dt"] > 1e-6, f"dt did not grow again after the bounce: {last['Dt']}")
    reasons = re.findall(r"tri/adapt_dt: step (\d+): dt \S+ -> \S+ \((.*)\)", out)
    check(any(s == "0" and w.startswith("approach: particles 1 and 2 close in at 200 m/s")
              for s, w in reasons), "dt was not bounded before the first step")
    print(f"100 m/s with tri/adapt_dt: dt {rows[0]['Dt']:g} s from step 0, closest distance "
          f"{deepest:.3g} m, final vx {last['vx1']:.5g} {last['vx2']:.5g} m/s "
          f"({100 * energy:.2f} % of the energy), final dt {last['Dt']:.3g} s")

    w, h = 0.018, 0.05

    def quad(a, b, c, d):
        return [[a, b, c], [a, c, d]]
    write_stl(os.path.join(ctx.work, "floorbox.stl"),
              quad((-w, -w, 0), (w, -w, 0), (w, w, 0), (-w, w, 0))
              + quad((-w, -w, 0), (-w, w, 0), (-w, w, h), (-w, -w, h))
              + quad((w, -w, 0), (w, -w, h), (w, w, h), (w, w, 0))
              + quad((-w, -w, 0), (-w, -w, h), (w, -w, h), (w, -w, 0))
              + quad((-w, w, 0), (w, w, 0), (w, w, h), (-w, w, h)))
    line = expect_error(ctx, "in.extreme_overlap", {},
                        r"the run starts with intersecting surfaces \(3 particle pair\(s\), "
                        r"e\.g\. particles \d+ and \d+; 1 particle-wall contact\(s\)\).*"
                        r"at least 2 x epsilon apart")
    print(f"created inside each other and a wall: {line}")
    _, out = run_deck(ctx, "in.extreme_overlap", {"apart": 1})
    rows = thermo_rows(out)
    check(rows and all(r["Atoms"] == 4 and r["stats[9]"] == 0 for r in rows),
          "the control run (particles apart) lost atoms or intersected")
    check("ERROR" not in out and "WARNING" not in out, "the control run complained")


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
