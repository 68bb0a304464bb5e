#!/usr/bin/env python3
"""Kept separating axes and the tight cull (issue 12) change no trajectory: in.separation (27
spinning rocks thrown into an open box: flights, rock-rock and rock-wall contacts, a forming
pile) gives bitwise the same final positions, velocities, spins, forces and orientations

  * with the default contact settings (kept separating axes, cull in two frames and face
    planes) and with `separation no cull boxes` (every pair searched, world-frame boxes only:
    the code before issue 12), for pair tri/gran and fix tri/wall alike;
  * on 1 and 2 OpenMP threads and on 1 and 2 MPI ranks;
  * in one run of 2N steps and in N steps + write_restart + N steps from the file (the axes
    travel in LIGGGHTS's contact history and the wall fix's per-atom array);

and the axes do their work: body pairs are proven apart (pairs_separated) and fewer triangle
pairs are tested than without them. Standard library only.

usage: separation_test.py --exe LIGGGHTS_TRI --columns TRI_STATS_COLUMNS --work DIR [--steps N]
"""
import argparse
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1"}
FAILURES = []


def check(ok, what):
    if not ok:
        FAILURES.append(what)
    return ok


def write_box(path, half=0.008, height=0.025):
    """An open box: floor z = 0, side walls x, y = +-half, normals inwards."""
    def quad(a, b, c, d):
        return [(a, b, c), (a, c, d)]
    w = half
    c = [(-w, -w), (w, -w), (w, w), (-w, w)]
    tris = quad((-w, -w, 0.0), (w, -w, 0.0), (w, w, 0.0), (-w, w, 0.0))
    for k in range(4):
        a, b = c[k], c[(k + 1) % 4]
        tris += quad((a[0], a[1], 0.0), (a[0], a[1], height), (b[0], b[1], height), (b[0], b[1], 0.0))
    with open(path, "w") as f:
        f.write("solid box\n")
        for t in tris:
            f.write(" facet normal 0 0 0\n  outer loop\n")
            for p in t:
                f.write("   vertex %.9g %.9g %.9g\n" % p)
            f.write("  endloop\n endfacet\n")
        f.write("endsolid box\n")


def columns(tool):
    cols = {}
    out = subprocess.run([tool], capture_output=True, text=True, check=True).stdout
    for line in out.splitlines():
        f = line.split("\t")
        if len(f) >= 2 and f[0].strip().isdigit():
            cols[f[1].strip()] = int(f[0])
    return cols


def last_frame(path):
    with open(path) as f:
        lines = f.read().splitlines()
    starts = [i for i, l in enumerate(lines) if l.startswith("ITEM: TIMESTEP")]
    s = starts[-1]
    n = int(lines[s + 3])
    return int(lines[s + 1]), {int(l.split()[0]): l.split()[1:] for l in lines[s + 9: s + 9 + n]}


def run(a, cols, name, variables, threads=1, ranks=1):
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), **MPI_ENV)
    cmd = (["mpirun", "-np", str(ranks), "--oversubscribe"] if ranks > 1 else []) + [
        a.exe, "-in", os.path.join(HERE, "in.separation"), "-log", "none",
        "-var", "k_tested", str(cols["triangle_pairs_tested"]),
        "-var", "k_separated", str(cols["pairs_separated"]), "-var", "px", str(ranks)]
    for k, v in variables.items():
        cmd += ["-var", k, str(v)]
    p = subprocess.run(cmd, cwd=a.work, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True, errors="replace", timeout=600)
    if not check(p.returncode == 0 and "ERROR" not in p.stdout,
                 f"{name}: exit {p.returncode}: {p.stdout[-1500:]}"):
        return None, []
    # thermo: step atoms pair(checked contact tested separated) wall(checked contact tested separated)
    rows = [[float(x) for x in l.split()] for l in p.stdout.splitlines()
            if len(l.split()) == 10 and l.split()[0].isdigit()]
    return p.stdout, rows


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--columns", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--steps", type=int, default=1000)
    a = ap.parse_args()
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    write_box(os.path.join(a.work, "box.stl"))
    cols = columns(a.columns)
    n = a.steps
    full = {"mode": "full", "nsteps": 2 * n}
    _, rows = run(a, cols, "default", dict(full, phase="default"))
    _, plain_rows = run(a, cols, "plain", dict(full, phase="plain",
                                                contact="kernel hybrid separation no cull boxes"))
    run(a, cols, "threads", dict(full, phase="threads"), threads=2)
    run(a, cols, "ranks", dict(full, phase="ranks"), ranks=2)
    run(a, cols, "first", {"mode": "first", "nsteps": n, "phase": "first"})
    run(a, cols, "second", {"mode": "second", "nsteps": n, "phase": "second"})
    if FAILURES:
        print("FAIL separation:\n  " + "\n  ".join(FAILURES))
        return 1
    step, ref = last_frame(os.path.join(a.work, "separation_default.dump"))
    check(step == 2 * n and len(ref) == 27, f"default: step {step}, {len(ref)} atoms")
    for phase in ("plain", "threads", "ranks", "second"):
        s, got = last_frame(os.path.join(a.work, f"separation_{phase}.dump"))
        check(s == 2 * n, f"{phase}: last frame at step {s}")
        diff = [t for t in ref if got.get(t) != ref[t]]
        check(not diff, f"{phase} differs from the default run in atoms {diff[:5]}: "
                        f"{ref[diff[0]] if diff else ''} != {got.get(diff[0]) if diff else ''}")
    # The axes did work (summed over the thermo samples): pairs and walls proven apart, fewer
    # triangle pairs tested, contacts happened.
    pair_contacts = sum(r[3] for r in rows)
    wall_contacts = sum(r[7] for r in rows)
    separated = sum(r[5] for r in rows), sum(r[9] for r in rows)
    tested = sum(r[4] + r[8] for r in rows)
    plain_tested = sum(r[4] + r[8] for r in plain_rows)
    check(pair_contacts > 0 and wall_contacts > 0,
          f"no contacts in the samples (pairs {pair_contacts}, walls {wall_contacts})")
    check(separated[0] > 0 and separated[1] > 0, f"pairs_separated {separated} (pair, wall)")
    check(sum(r[9] for r in plain_rows) + sum(r[5] for r in plain_rows) == 0,
          "separation no still proves pairs apart")
    check(tested < plain_tested, f"triangle pairs tested {tested} not below {plain_tested}")
    if FAILURES:
        print("FAIL separation:\n  " + "\n  ".join(FAILURES))
        return 1
    print(f"PASS separation: default, separation no / cull boxes, 2 threads, 2 ranks and a restart "
          f"after {n} steps bitwise equal after {2 * n} steps; pairs proven apart {separated[0]:.0f} "
          f"(walls {separated[1]:.0f}) in the samples, triangle pairs tested {tested:.0f} against "
          f"{plain_tested:.0f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
