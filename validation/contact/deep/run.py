#!/usr/bin/python3
"""Deep contacts: restitution of icosphere impacts whose linear spring reaches 2, 4 and 8 times
the contact's soft layers (the real surfaces intersect), against the linear spring-dashpot
solution; past the resolvable depth, the run must stop with the deep-contact error.

  /usr/bin/python3 run.py [--exe build/src_plugin/driver/liggghts-tri] [--work /tmp/...]
                          [--layer inside|outside]

The contact's soft layers ("the layer" below): with the particle's layer inside its mesh (the
default) the particle's eps against the wall (whose mesh has no layer) and 2 eps between two
particles; with `--layer outside` (the earlier convention, the wall taking the particle's eps)
2 eps for both.

Both a particle-wall impact (fix tri/wall) and a particle-particle one (pair tri/gran), each
undamped (e = 1: the force is the gradient of one potential) and damped for e = 0.73 (limitForce
on, the tri/gran default). Prints the table, writes deep.png next to this script. Needs Debian's
matplotlib (/usr/bin/python3).
"""
import argparse
import importlib.util
import math
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(REPO, "validation", "meshes"))
sys.path.insert(0, os.path.join(REPO, "validation"))
import meshgen  # noqa: E402
import valtools  # noqa: E402

# The closed-form spring-dashpot of the restitution study (one place for it).
_spec = importlib.util.spec_from_file_location(
    "restitution_run", os.path.join(REPO, "validation", "contact", "restitution", "run.py"))
restitution = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(restitution)

R, EPS, RHO, V0 = 0.0025, 5e-5, 2500.0, 1.0   # the 5 mm ball at 1 m/s
LAYER_OF = {0: EPS, 1: 2 * EPS}                # the contact's soft layers: wall, pair (--layer)
LEVEL = 3                                      # 1280 triangles
DT = 1e-6
LAYERS = (2, 4, 8)                             # peak overlap of the undamped spring / layer
PAST_LIMIT_M = 1.6e-3                          # m, a spring peak past 0.25 x 2R (+ the layer): the error
E_DAMPED = 0.73
TOL = 0.03
LIMIT_FRACTION = 0.25                          # penetration_depth.h kDeepContactLimitFraction


def stat_indices(exe):
    tool = os.path.join(os.path.dirname(os.path.dirname(exe)), "tools", "tri-stats-columns")
    out = subprocess.run([tool], check=True, capture_output=True, text=True).stdout
    return {"stat_" + l.split("\t")[1]: l.split("\t")[0] for l in out.splitlines() if "\t" in l}


def zeta_for_e(e, kn, meff):
    """Damping ratio whose limitForce-on contact restitutes e (bisection on the closed form)."""
    lo, hi = 0.0, 0.9
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        _, em = restitution.analytic(kn, meff, 2 * mid * math.sqrt(kn / meff), 1.0, 0.0, "on")
        lo, hi = (mid, hi) if em > e else (lo, mid)
    return 0.5 * (lo + hi)


def measure(rows):
    idx = [k for k, r in enumerate(rows) if abs(r[2]) > 0.0]
    i0, i1 = idx[0], idx[-1]
    assert i1 + 1 < len(rows), "run ended during the contact"
    v_in, v_out = rows[i0 - 1][1], rows[i1 + 1][1]
    return {"v_in": v_in, "e": -v_out / v_in, "tc": (i1 - i0 + 1) * DT, "mass": rows[0][6],
            "peak": max(r[3] for r in rows), "ratio": max(r[5] for r in rows),
            "deep_steps": sum(1 for r in rows if r[4] > 0)}


def run(exe, work, name, variables):
    cmd = valtools.deck_command(exe, os.path.join(HERE, "in.deep"), dict(out=name, **variables))
    with open(os.path.join(work, name + ".screen"), "w") as out:
        r = subprocess.run(cmd, cwd=work, env=valtools.run_env(1), stdout=out,
                           stderr=subprocess.STDOUT)
    with open(os.path.join(work, name + ".screen"), errors="replace") as f:
        screen = f.read()
    return r.returncode, screen


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", default=valtools.default_exe())
    ap.add_argument("--work", default="/tmp/liggghts-tri-validation/deep")
    ap.add_argument("--layer", default="inside", choices=("inside", "outside"),
                    help="fix tri/particles layer (default inside: the mesh is the contact surface)")
    args = ap.parse_args()
    if args.layer == "outside":
        LAYER_OF[0] = 2 * EPS
    exe = os.path.abspath(args.exe)
    os.makedirs(args.work, exist_ok=True)
    verts, faces = meshgen.icosphere(LEVEL, R)
    meshgen.write_stl(os.path.join(args.work, "ico.stl"), verts, faces)
    meshgen.write_stl(os.path.join(args.work, "plane.stl"), *meshgen.plane(0.01))
    vol = sum(
        (verts[a][0] * (verts[b][1] * verts[c][2] - verts[b][2] * verts[c][1])
         - verts[a][1] * (verts[b][0] * verts[c][2] - verts[b][2] * verts[c][0])
         + verts[a][2] * (verts[b][0] * verts[c][1] - verts[b][1] * verts[c][0])) / 6.0
        for a, b, c in faces)
    mass = RHO * vol
    stats = stat_indices(exe)

    results, traces = [], {}
    for pair in (0, 1):
        meff = mass if pair == 0 else mass / 2
        LAYER = LAYER_OF[pair]
        for layers in LAYERS:
            kn = meff * V0 ** 2 / (layers * LAYER) ** 2
            tc0 = math.pi * math.sqrt(meff / kn)
            for e_t in (1.0, E_DAMPED):
                zeta = 0.0 if e_t == 1.0 else zeta_for_e(e_t, kn, meff)
                gamman = 2 * zeta * math.sqrt(kn / meff)
                name = "%s_%dx_e%.2f.txt" % ("pair" if pair else "wall", layers, e_t)
                var = dict(pair=pair, R=R, eps=EPS, kn="%.10g" % kn, gamman="%.10g" % gamman,
                           v0=V0, dt=DT, steps=int(1.6 * tc0 / DT) + 200, layer=args.layer,
                           **stats)
                rc, screen = run(exe, args.work, name, var)
                if rc != 0:
                    sys.exit("%s failed (exit %d), see %s.screen" % (name, rc, name))
                rows = valtools.read_rows(os.path.join(args.work, name))
                m = measure(rows)
                _, e_a = restitution.analytic(kn, meff, gamman, -m["v_in"], 0.0, "on")
                r = dict(pair=pair, layers=layers, kn=kn, zeta=zeta, e_a=e_a, layer=LAYER, **m)
                r["err"] = r["e"] / e_a - 1
                r["ok"] = abs(r["err"]) <= TOL
                results.append(r)
                traces[(pair, layers, e_t)] = rows

    # Past the limit: the error, naming the pair and the depth.
    errors = []
    for pair in (0, 1):
        meff = mass if pair == 0 else mass / 2
        kn = meff * V0 ** 2 / PAST_LIMIT_M ** 2
        tc0 = math.pi * math.sqrt(meff / kn)
        past = round(PAST_LIMIT_M / LAYER_OF[pair])
        name = "%s_%dx_limit.txt" % ("pair" if pair else "wall", past)
        rc, screen = run(exe, args.work, name, dict(pair=pair, R=R, eps=EPS, kn="%.10g" % kn,
                                                    gamman=0, v0=V0, dt=DT,
                                                    steps=int(1.6 * tc0 / DT), layer=args.layer,
                                                    **stats))
        m = re.search(r"ERROR: (Fix tri/particles: step \d+: the real surfaces of .*?)"
                      r"(?: \(\S+:\d+\))?$", screen, re.M)
        errors.append(dict(pair=pair, kn=kn, rc=rc, past=past,
                           message=m.group(1) if m else None))

    limit = LIMIT_FRACTION * 2 * R
    print(valtools.machine_line())
    print("icosphere level %d (%d triangles), R = %g m, mass = %.6g kg, eps = %g m (layer %s; the "
          "contact's layers: wall %g m, pair %g m), v0 = %g m/s, dt = %g s; resolvable depth past "
          "the layer %g m = %.1f wall layers, %.1f pair layers"
          % (LEVEL, len(faces), R, mass, EPS, args.layer, LAYER_OF[0], LAYER_OF[1], V0, DT,
             limit, limit / LAYER_OF[0], limit / LAYER_OF[1]))
    print("| contact | spring peak / layer | kn (N/m) | zeta | e analytic | e measured | error | "
          "peak overlap / layer | steps with deep contact | depth / limit | pass (3%) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in results:
        print("| %s | %d | %.5g | %.4f | %.4f | %.4f | %+.2f%% | %.2f | %d | %.2f | %s |" % (
            "pair" if r["pair"] else "wall", r["layers"], r["kn"], r["zeta"], r["e_a"], r["e"],
            100 * r["err"], r["peak"] / r["layer"], r["deep_steps"], r["ratio"],
            "PASS" if r["ok"] else "FAIL"))
    print("worst |error|: %.3f%%; %d/%d pass" % (100 * max(abs(r["err"]) for r in results),
                                                 sum(r["ok"] for r in results), len(results)))
    for e in errors:
        print("%s, spring peak %d layers (kn %.4g N/m): exit %d: %s" % (
            "pair" if e["pair"] else "wall", e["past"], e["kn"], e["rc"], e["message"]))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(12, 4.8))
    a = ax[0]
    for (pair, layers, e_t), rows in sorted(traces.items()):
        if e_t != 1.0:
            continue
        kn = next(r["kn"] for r in results if r["pair"] == pair and r["layers"] == layers)
        sel = [r for r in rows if abs(r[2]) > 0]
        LAYER = LAYER_OF[pair]
        a.plot([r[3] / LAYER for r in sel], [abs(r[2]) / (kn * LAYER) for r in sel],
               "-" if pair == 0 else "--", lw=1.5,
               label="%s, spring peak %d layers" % ("wall" if pair == 0 else "pair", layers))
    xs = [0, max(LAYERS) * 1.1]
    a.plot(xs, xs, "k:", lw=1, label="linear spring F = kn overlap")
    a.axvline(1.0, color="grey", lw=0.8)
    a.text(1.1, 0.5, "real surfaces\nintersect", fontsize=8)
    a.set_xlabel("overlap / the contact's soft layers (wall: %s, pair: 2 eps)"
                 % ("eps" if LAYER_OF[0] == EPS else "2 eps"))
    a.set_ylabel("normal force / (kn x the layers)")
    a.set_title("undamped impacts: force through the intersection")
    a.legend(fontsize=7)
    a.grid(alpha=0.3)
    a = ax[1]
    for pair, mk in ((0, "o"), (1, "s")):
        for e_t, colour in ((1.0, "C0"), (E_DAMPED, "C1")):
            sel = [r for r in results if r["pair"] == pair and abs(r["e_a"] - e_t) < 0.05]
            LAYER = LAYER_OF[pair]
            a.plot([r["peak"] / LAYER for r in sel], [r["e"] for r in sel], mk, color=colour,
                   mfc="none" if pair else colour,
                   label="%s, analytic e = %.3f" % ("pair" if pair else "wall", sel[0]["e_a"]))
            for r in sel:
                a.plot([r["peak"] / LAYER] * 2, [r["e_a"] * (1 - TOL), r["e_a"] * (1 + TOL)],
                       "-", color=colour, lw=0.6)
    a.set_xlabel("measured peak overlap / the contact's soft layers")
    a.set_ylabel("coefficient of restitution")
    a.set_title("restitution (bars: analytic +- 3 %%); ERROR past %.1f wall, %.1f pair layers" %
                (1.0 + limit / LAYER_OF[0], 1.0 + limit / LAYER_OF[1]))
    a.legend(fontsize=7)
    a.grid(alpha=0.3)
    fig.suptitle("Deep contacts: icosphere (%d triangles, R = %g mm) at %g m/s, eps = %g mm, "
                 "layer %s" % (len(faces), 1e3 * R, V0, 1e3 * EPS, args.layer))
    fig.tight_layout()
    out = os.path.join(HERE, "deep.png" if args.layer == "inside" else "deep_outside.png")
    fig.savefig(out, dpi=110)
    print("plot:", out)
    ok = all(r["ok"] for r in results) and all(e["rc"] != 0 and e["message"] for e in errors)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
