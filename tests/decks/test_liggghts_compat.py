"""LIGGGHTS compatibility: tutorial decks of Debian's liggghts-doc give the same screen output
(every thermo row, and every other line but timings) and byte-identical dump files under
`liggghts` and `liggghts-tri`; meshGran and noCohesion also on 2 MPI ranks. The driver only
adds styles, so a sphere deck must not notice it.

The decks are copied to the work directory (the installed files are never edited) and
shortened by rewriting their run lengths (and packing's growth and relaxation steps), so each
run takes a few seconds on 2 cores. Every rewrite must match a line of the deck as installed:
if a new liggghts-doc changes a deck, the test says which line it did not find.

Run alone, with a choice of decks:

  python3 test_liggghts_compat.py --exe LIGGGHTS_TRI --work DIR [--liggghts PATH]
      [--docdir DIR] [--only NAME...]
"""
import argparse
import filecmp
import os
import re
import shutil
import sys
import time

import decklib
from decklib import Failure, check

DOCDIR = "/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public"
# name: (tutorial directory, input file, {installed line (words joined by one space): new
# line}, MPI rank counts). Lengths: enough steps that particles are inserted, fall, collide
# with each other and the walls (the thermo rows show kinetic and rotational energy change).
DECKS = {
    "newModels": ("contactModels", "in.newModels", {
        "run 5000": "run 1000",
        "run 50000 upto": "run 3000 upto",
    }, (1,)),
    "noCohesion": ("cohesion", "in.noCohesion", {
        "run 10000": "run 9000",
        "run 50000 upto": "run 11000 upto",
    }, (1, 2)),
    "packing": ("packing", "in.packing", {
        "variable growts equal 50000": "variable growts equal 2000",
        "variable relaxts equal 20000": "variable relaxts equal 1000",
    }, (1,)),
    "meshGran": ("meshGran", "in.meshGran", {
        "run 10000 upto": "run 3000 upto",
        "run 40000 upto": "run 4000 upto",
    }, (1, 2)),
    "chute_wear": ("chute_wear", "in.chute_wear", {
        "run 100000 upto": "run 12000 upto",   # the first particles reach the chute at 10500
        # a frame every 1000 steps, not 200 (the chute has 3232 triangles)
        "dump dmp all custom/vtk 200 post/chute_*.vtk id type type x y z ix iy iz vx vy vz fx "
        "fy fz omegax omegay omegaz radius":
        "dump dmp all custom/vtk 1000 post/chute_*.vtk id type type x y z ix iy iz vx vy vz fx "
        "fy fz omegax omegay omegaz radius",
        "dump dumpstress all mesh/gran/VTK 200 post/mesh_*.vtk stress wear cad":
        "dump dumpstress all mesh/gran/VTK 1000 post/mesh_*.vtk stress wear cad",
    }, (1,)),
}

# Screen lines that legitimately differ between two runs: wall-clock times.
TIMING = re.compile(r"^(Loop time of|(Pair|Neigh|Comm|Outpt|Other|Modify)\s+time|"
                    r".*finish time|Total wall time|Setting up run|Memory usage)")


def shorten(src, dst, rewrites):
    """Copies the deck `src` to `dst` with the lines of `rewrites` replaced (matched word by
    word, comments and spacing kept out of the comparison)."""
    found = set()
    out = []
    with open(src) as f:
        for line in f:
            words = " ".join(line.split("#", 1)[0].split())
            if words in rewrites:
                found.add(words)
                out.append(rewrites[words] + "\n")
            else:
                out.append(line)
    missing = sorted(set(rewrites) - found)
    if missing:
        raise Failure(f"{src}: no line {missing!r} to shorten (did liggghts-doc change?)")
    with open(dst, "w") as f:
        f.writelines(out)


def run(exe, tutorial, deck, rewrites, ranks, work):
    """Runs the shortened deck in a fresh copy of its tutorial directory; returns (screen
    output, directory)."""
    shutil.rmtree(work, ignore_errors=True)
    shutil.copytree(tutorial, work)
    os.makedirs(os.path.join(work, "post"), exist_ok=True)
    shorten(os.path.join(tutorial, deck), os.path.join(work, "in.short"), rewrites)
    cmd = [exe, "-in", "in.short", "-log", "none"]
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks), "--oversubscribe"] + cmd
    start = time.time()
    code, out = decklib.run(cmd, work, timeout=600)
    if code != 0 or "ERROR" in out:
        raise Failure(f"{' '.join(cmd)} in {work} exited {code}:\n{out[-3000:]}")
    print(f"  {' '.join(cmd)}: {time.time() - start:.1f} s", flush=True)
    return out, work


def thermo_lines(out):
    """The thermo rows of a screen output (the lines under each 'Step ...' header)."""
    rows, header = [], None
    for line in out.splitlines():
        words = line.split()
        if words and words[0] == "Step":
            header = len(words)
        elif header and words and words[0] == "Loop":
            header = None
        elif header and len(words) == header and words[0].isdigit():
            rows.append(line)
    return rows


def output_files(root):
    files = []
    for d, _, names in os.walk(root):
        for n in names:
            files.append(os.path.relpath(os.path.join(d, n), root))
    return sorted(f for f in files if f != "in.short")


def compare(name, ref, got):
    """(screen, dir) of liggghts against liggghts-tri: thermo rows, other lines, files."""
    (out_a, dir_a), (out_b, dir_b) = ref, got
    rows_a, rows_b = thermo_lines(out_a), thermo_lines(out_b)
    if not rows_a:
        raise Failure(f"{name}: no thermo rows in liggghts's output:\n{out_a[-2000:]}")
    if rows_a != rows_b:
        diff = next((k for k, (a, b) in enumerate(zip(rows_a, rows_b)) if a != b),
                    min(len(rows_a), len(rows_b)))
        raise Failure(f"{name}: thermo rows differ ({len(rows_a)} and {len(rows_b)} rows), "
                      f"first at row {diff}:\n  liggghts:     "
                      f"{rows_a[diff] if diff < len(rows_a) else '(none)'}\n  liggghts-tri: "
                      f"{rows_b[diff] if diff < len(rows_b) else '(none)'}")
    lines_a = [l for l in out_a.splitlines() if not TIMING.match(l)]
    lines_b = [l for l in out_b.splitlines() if not TIMING.match(l)]
    if lines_a != lines_b:
        extra = [l for l in lines_b if l not in lines_a][:5]
        missing = [l for l in lines_a if l not in lines_b][:5]
        raise Failure(f"{name}: screen output differs beyond timings: only under liggghts-tri "
                      f"{extra}, only under liggghts {missing}")
    files_a, files_b = output_files(dir_a), output_files(dir_b)
    if files_a != files_b:
        raise Failure(f"{name}: different output files: liggghts {files_a}, liggghts-tri "
                      f"{files_b}")
    dumps = [f for f in files_a if f.startswith("post" + os.sep)]
    if not dumps:
        raise Failure(f"{name}: no dump files were written")
    for f in files_a:
        if not filecmp.cmp(os.path.join(dir_a, f), os.path.join(dir_b, f), shallow=False):
            raise Failure(f"{name}: {f} differs between liggghts and liggghts-tri")
    first, last = rows_a[0].split(), rows_a[-1].split()
    return (f"{len(rows_a)} thermo rows equal (step {first[0]}: {' '.join(first[1:])}; step "
            f"{last[0]}: {' '.join(last[1:])}), {len(dumps)} dump files byte-identical")


def compat(ctx, liggghts, docdir=DOCDIR, only=None):
    check(os.path.isdir(docdir), f"{docdir} not found: install the tutorial decks with "
                                 "'apt-get install --no-install-recommends liggghts-doc' "
                                 "(examples/build.sh does)")
    check(liggghts, "no liggghts executable (--liggghts)")
    failures, compared = [], 0
    for name, (sub, deck, rewrites, rank_counts) in DECKS.items():
        if only and name not in only:
            continue
        for ranks in rank_counts:
            label = f"{name} ({ranks} rank{'s' if ranks > 1 else ''})"
            try:
                tutorial = os.path.join(docdir, sub)
                base = os.path.join(ctx.work, f"{name}_np{ranks}")
                ref = run(liggghts, tutorial, deck, rewrites, ranks, base + "_liggghts")
                got = run(ctx.exe, tutorial, deck, rewrites, ranks, base + "_liggghts-tri")
                print(f"{label}: {compare(label, ref, got)}", flush=True)
                compared += 1
            except Failure as e:
                failures.append(str(e))
                print(f"{label}: FAIL", flush=True)
    check(not failures, "\n".join(failures))
    check(compared > 0, f"no deck compared (only {only})")


def test_liggghts_compat(ctx):
    compat(ctx, ctx.liggghts or shutil.which("liggghts") or "/usr/bin/liggghts")


def main():
    ap = argparse.ArgumentParser(description="test_liggghts_compat, a choice of decks")
    ap.add_argument("--exe", required=True, help="liggghts-tri")
    ap.add_argument("--work", required=True)
    ap.add_argument("--liggghts", default=shutil.which("liggghts") or "/usr/bin/liggghts")
    ap.add_argument("--docdir", default=DOCDIR)
    ap.add_argument("--only", nargs="*", help="deck names to run (default: all)")
    a = ap.parse_args()
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    try:
        compat(a, a.liggghts, a.docdir, a.only)
    except Failure as e:
        print(f"FAIL liggghts_compat: {e}")
        return 1
    print("PASS liggghts_compat")
    return 0


if __name__ == "__main__":
    sys.exit(main())
