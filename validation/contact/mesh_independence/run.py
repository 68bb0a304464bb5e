#!/usr/bin/python3
"""Mesh independence of a resting contact: a cube meshed with 12, 48, 192 and 768 triangles
(meshgen.py cube N, N = 1, 2, 4, 8) resting on a plane (fix tri/wall), and a stack of two such
cubes (pair tri/gran between them), with the default contact reduction (`clusters`) and, for
contrast, the paper's baseline (`paper`) and no reduction (`none`).

  /usr/bin/python3 run.py [--exe build/src_plugin/driver/liggghts-tri] [--work /tmp/...]

Measured after settling (mean over the last 10 % of the run):
  contact force   from the code's total force minus gravity (fz + m g): on the single cube the
                  wall force; in the stack the pair force on the top cube and the wall force on
                  the bottom cube (= its contact force + the pair force it carries);
  overlap         from the positions (geometry, not the code's report): wall overlap
                  s/2 - z_bottom, pair overlap s - (z_top - z_bottom) (the layer inside the
                  mesh, the default: the meshes touch at zero overlap; `--layer outside`:
                  s/2 + 2 eps - z_bottom and s + 2 eps - (z_top - z_bottom)).
Targets: force = weight (mg, 2mg) within 1 %; overlap = force / kn within 5 %, hence equal
across resolutions within 5 %.
"""
import argparse
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(REPO, "validation", "meshes"))
sys.path.insert(0, os.path.join(REPO, "validation"))
import meshgen  # noqa: E402
import valtools  # noqa: E402

S, EPS, KN, GAMMAN, RHO, G = 0.004, 1e-4, 200.0, 1200.0, 2500.0, 9.81
DT, STEPS = 2e-5, 3000
NS = (1, 2, 4, 8)
REDUCTIONS = ("clusters", "paper", "none")
TOL_F, TOL_D = 0.01, 0.05
LAYER = "inside"  # set by --layer


def lift():
    """Distance of the meshes (of a mesh and the plane) when a contact starts."""
    return 0.0 if LAYER == "inside" else 2 * EPS


def reach(contact):
    """The soft layers of a contact: the particle's (wall, layer inside) or both (pair; wall, outside)."""
    return EPS if contact == "wall" and LAYER == "inside" else 2 * EPS


def run(exe, work, out, variables, reuse=False):
    """The trace rows and the run's ERROR line ('' when it ran to the end). A baseline run may
    be stopped by the run-safety checks (its contact blows up); the default's may not."""
    screen = os.path.join(work, out + ".screen")
    if not (reuse and os.path.exists(os.path.join(work, out))):
        try:
            valtools.run_deck(exe, os.path.join(HERE, "in.rest"), dict(out=out, **variables),
                              work, screen)
        except subprocess.CalledProcessError:
            if variables["reduction"] == "clusters":
                raise
    error = ""
    with open(screen, errors="replace") as f:
        for line in f:
            if line.startswith("ERROR"):
                error = line.strip()
                break
    return valtools.read_rows(os.path.join(work, out)), error


def mean(rows, k):
    tail = rows[int(0.9 * len(rows)):]
    return sum(r[k] for r in tail) / len(tail)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", default=valtools.default_exe())
    ap.add_argument("--work", default="/tmp/liggghts-tri-validation/mesh_independence")
    ap.add_argument("--reuse", action="store_true",
                    help="re-read traces already in --work instead of running the decks")
    ap.add_argument("--layer", default="inside", choices=("inside", "outside"),
                    help="fix tri/particles layer (default inside: the mesh is the contact surface)")
    args = ap.parse_args()
    global LAYER
    LAYER = args.layer
    exe = os.path.abspath(args.exe)
    os.makedirs(args.work, exist_ok=True)
    for n in NS:
        meshgen.write_stl(os.path.join(args.work, "cube%d.stl" % n), *meshgen.cube(n, S))
    meshgen.write_stl(os.path.join(args.work, "plane.stl"), *meshgen.plane(0.015))

    res, stopped = [], []
    for stack in (0, 1):
        for red in REDUCTIONS:
            for n in NS:
                out = "%s_%s_N%d.txt" % ("stack" if stack else "single", red, n)
                rows, error = run(exe, args.work, out, {
                    "stack": stack, "mesh": "cube%d.stl" % n, "plane": "plane.stl", "s": S,
                    "eps": EPS, "kn": KN, "gamman": GAMMAN, "reduction": red, "dt": DT,
                    "steps": STEPS, "layer": LAYER}, args.reuse)
                if error:
                    stopped.append((out, error))
                    continue
                m = rows[0][7]
                w = m * G
                za, zb, fa, fb = (mean(rows, k) for k in (1, 2, 3, 4))
                d_wall = S / 2 + lift() - za
                r = dict(stack=stack, red=red, n=n, ntri=12 * n * n, w=w, rows=rows,
                         contacts=mean(rows, 6), raw=mean(rows, 5), drift=rows[-1][8])
                if stack:
                    r["F_pair"], r["F_wall"] = fb, fa + fb
                    r["d_pair"], r["d_wall"] = S + lift() - (zb - za), d_wall
                else:
                    r["F_wall"], r["d_wall"] = fa, d_wall
                res.append(r)

    print(valtools.machine_line())
    print("cube side %g m, mass %.6g kg, weight mg = %.6g N, eps = %g m (layer %s), kn = %g N/m, "
          "gamman = %g 1/s, dt = %g s, %d steps" % (S, res[0]["rows"][0][7], res[0]["w"], EPS,
                                                    LAYER, KN, GAMMAN, DT, STEPS))
    print()
    print("| case | contact | reduction | N | triangles | points | F / weight | error F |"
          " overlap (um) | analytic F/kn (um) | error overlap | spread over N | pass |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    verdicts = []
    for stack in (0, 1):
        for contact in (("wall",) if not stack else ("wall", "pair")):
            load = 1 if contact == "pair" or not stack else 2
            for red in REDUCTIONS:
                sel = [r for r in res if r["stack"] == stack and r["red"] == red]
                if not sel:
                    continue
                ds = [r["d_" + contact] for r in sel]
                spread = max(ds) / min(ds) - 1 if min(ds) > 0 else float("inf")
                for r in sel:
                    target = load * r["w"]
                    ef = r["F_" + contact] / target - 1
                    ed = r["d_" + contact] / (target / KN) - 1
                    ok = abs(ef) <= TOL_F and abs(ed) <= TOL_D and spread <= TOL_D
                    settled = abs(ef) <= TOL_F
                    r["settled"] = r.get("settled", True) and settled
                    if red == "clusters":
                        verdicts.append(ok)
                        verdict = "PASS" if ok else "FAIL"
                    elif settled:
                        verdict = "(contrast) settled, overlap off by %.0f%%" % (100 * ed)
                    else:
                        verdict = "(contrast) not settled: mean force off weight by > 1 %"
                    r["ed_" + contact] = ed
                    print("| %s | %s | %s | %d | %d | %.0f | %.5f | %+.3f%% | %.4f | %.4f | "
                          "%+.2f%% | %s | %s |" % (
                              "stack" if stack else "single", contact, red, r["n"], r["ntri"],
                              r["contacts"], r["F_" + contact] / target, 100 * ef,
                              1e6 * r["d_" + contact], 1e6 * target / KN, 100 * ed,
                              "%.2f%%" % (100 * spread) if red == "clusters" else "-", verdict))
    for out, error in stopped:
        print("| %s | stopped by the run-safety checks: %s | (contrast) |" % (out[:-4], error))
    print()
    print("clusters (the default): %d/%d rows pass" % (sum(verdicts), len(verdicts)))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.8))
    panels = ((0, "wall", "single cube on plane"), (1, "wall", "stack: bottom cube on plane"),
              (1, "pair", "stack: top cube on bottom cube"))
    for a, (stack, contact, title) in zip(ax, panels):
        for red, mk, colour in (("clusters", "o-", "C0"), ("paper", "s--", "C1"),
                                ("none", "^:", "C3")):
            sel = [r for r in res if r["stack"] == stack and r["red"] == red
                   and 0 < r["d_" + contact] < reach(contact)]
            a.plot([r["ntri"] for r in sel], [1 + r["ed_" + contact] for r in sel], mk[1:],
                   color=colour, label="reduction %s" % red)
            for r in sel:  # filled: settled (mean force = load within 1 %); hollow: not settled
                ok = abs(r["F_" + contact] / ((2 if stack and contact == "wall" else 1) * r["w"])
                         - 1) <= TOL_F
                a.plot([r["ntri"]], [1 + r["ed_" + contact]], mk[0], color=colour,
                       mfc=colour if ok else "none", ms=7)
        a.axhspan(1 - TOL_D, 1 + TOL_D, color="C2", alpha=0.15, label="target +-5 %")
        a.axhline(1.0, color="k", lw=0.8)
        a.set_xscale("log")
        a.set_yscale("log")
        a.set_xticks([12 * n * n for n in NS])
        a.set_xticklabels([str(12 * n * n) for n in NS])
        a.set_xlabel("triangles per cube")
        a.set_ylabel("equilibrium overlap / (load / kn)")
        a.set_title(title)
        a.grid(alpha=0.3, which="both")
        a.legend(fontsize=8)
    fig.suptitle("Resting cube: equilibrium overlap against load/kn across mesh resolutions "
                 "(hollow: not settled; runs out of contact or overlap <= 0 left out)")
    fig.tight_layout()
    out = os.path.join(HERE, "mesh_independence.png" if LAYER == "inside"
                       else "mesh_independence_outside.png")
    fig.savefig(out, dpi=110)
    print("plot:", out)
    return 0 if all(verdicts) else 1


if __name__ == "__main__":
    sys.exit(main())
