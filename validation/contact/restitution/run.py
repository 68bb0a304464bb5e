#!/usr/bin/python3
"""Coefficient of restitution and contact duration of a normal impact, triangulated icosphere
(liggghts-tri: fix tri/wall, pair tri/gran) and LIGGGHTS's own sphere twin (pair gran / fix
wall/gran, model hooke/stiffness), against the linear spring-dashpot solution.

  /usr/bin/python3 run.py [--exe build/src_plugin/driver/liggghts-tri] [--work /tmp/...]
                         [--layer inside|outside]

The sphere twin has the radius at which the icosphere's contact starts: the mesh's own R with
the soft layer inside the mesh (the default); R + 2 eps against the wall and R + eps in the
pair with `--layer outside` (the layer outside the mesh, the wall taking the particle's eps).

Runs every deck (in.tri, in.sphere) into the scratch folder, prints the table, writes
restitution.png next to this script. Needs Debian's matplotlib (/usr/bin/python3).
"""
import argparse
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(REPO, "validation", "meshes"))
sys.path.insert(0, os.path.join(REPO, "validation"))
import meshgen  # noqa: E402
import valtools  # noqa: E402

R, EPS, KN, RHO, V0, G = 0.002, 1e-4, 2.0e4, 2500.0, 0.5, 9.81
LEVEL = 3                       # 1280 triangles
DT, STEPS = 1e-7, 3000
E_TARGETS = (0.9, 0.7, 0.5, 0.3)  # damping chosen to give these (limitForce off, no gravity)
TOL = 0.02                      # 2 %


def zeta_for(e):
    le = math.log(e)
    return -le / math.sqrt(math.pi ** 2 + le ** 2)


def analytic(kn, meff, gamman, v0, g, limit):
    """Linear spring-dashpot, overlap x >= 0 from x(0) = 0, x'(0) = v0 > 0:
    x'' + gamman x' + (kn/meff) x = g   (gamman * meff is LIGGGHTS's damping coefficient,
    g the acceleration pushing into the contact: gravity for the wall, 0 for the pair).
    Contact ends when x = 0 (limitForce off) or when F_n = kn x + gamman meff x' = 0 (on).
    Returns (duration, e = -x'(t_end) / v0); closed form with a bracketed root."""
    w2 = kn / meff
    a = gamman / 2.0
    wd = math.sqrt(w2 - a * a)
    xs = g / w2
    A = -xs
    B = (v0 + a * A) / wd

    def x(t):
        return xs + math.exp(-a * t) * (A * math.cos(wd * t) + B * math.sin(wd * t))

    def xd(t):
        c, s = math.cos(wd * t), math.sin(wd * t)
        return math.exp(-a * t) * ((-a * A + wd * B) * c + (-a * B - wd * A) * s)

    f = x if limit == "off" else (lambda t: w2 * x(t) + gamman * xd(t))
    n = 20000
    tmax = 2 * math.pi / wd
    lo = None
    for k in range(1, n + 1):
        if f(tmax * k / n) < 0.0:
            lo, hi = tmax * (k - 1) / n, tmax * k / n
            break
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if f(mid) >= 0.0:
            lo = mid
        else:
            hi = mid
    t = 0.5 * (lo + hi)
    return t, -xd(t) / v0


def textbook(kn, meff, gamman):
    """No gravity, limitForce off: e = exp(-pi zeta / sqrt(1 - zeta^2)), t_c = pi / omega_d,
    omega_0 = sqrt(kn / m_eff), zeta = gamman m_eff / (2 sqrt(kn m_eff)) = gamman / (2 omega_0)."""
    w0 = math.sqrt(kn / meff)
    z = gamman / (2 * w0)
    return math.pi / (w0 * math.sqrt(1 - z * z)), math.exp(-math.pi * z / math.sqrt(1 - z * z))


def measure(rows):
    """Contact = the steps with a non-zero contact force. e from the velocities of the step
    before and the step after; duration = number of force steps x dt (+- dt)."""
    idx = [k for k, r in enumerate(rows) if abs(r[2]) > 1e-12]
    i0, i1 = idx[0], idx[-1]
    assert i1 + 1 < len(rows), "run ended during the contact"
    assert len(idx) == i1 - i0 + 1, "contact force vanished inside the contact"
    v_in, v_out = rows[i0 - 1][1], rows[i1 + 1][1]
    return {"v_in": v_in, "e": -v_out / v_in, "tc": (i1 - i0 + 1) * DT, "mass": rows[0][5],
            "contacts": max(r[3] for r in rows)}


def run(exe, deck, work, out, variables):
    valtools.run_deck(exe, os.path.join(HERE, deck), dict(out=out, **variables), work,
                      os.path.join(work, out + ".screen"))
    return valtools.read_rows(os.path.join(work, out))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", default=valtools.default_exe())
    ap.add_argument("--work", default="/tmp/liggghts-tri-validation/restitution")
    ap.add_argument("--layer", default="inside", choices=("inside", "outside"),
                    help="fix tri/particles layer (default inside: the mesh is the contact surface)")
    args = ap.parse_args()
    exe = os.path.abspath(args.exe)
    os.makedirs(args.work, exist_ok=True)
    meshgen.write_stl(os.path.join(args.work, "ico.stl"), *meshgen.icosphere(LEVEL, R))
    meshgen.write_stl(os.path.join(args.work, "plane.stl"), *meshgen.plane(0.01))
    verts, faces = meshgen.icosphere(LEVEL, R)
    vol = sum(
        (verts[a][0] * (verts[b][1] * verts[c][2] - verts[b][2] * verts[c][1])
         - verts[a][1] * (verts[b][0] * verts[c][2] - verts[b][2] * verts[c][0])
         + verts[a][2] * (verts[b][0] * verts[c][1] - verts[b][1] * verts[c][0])) / 6.0
        for a, b, c in faces)
    mass = RHO * vol

    results = []   # dicts
    traces = {}
    for pair in (0, 1):
        meff = mass if pair == 0 else mass / 2
        g = G if pair == 0 else 0.0
        for e_t in E_TARGETS:
            zeta = zeta_for(e_t)
            gamman = 2 * zeta * math.sqrt(KN / meff)
            for limit in ("off", "on"):
                common = {"pair": pair, "R": R, "eps": EPS, "kn": KN, "gamman": "%.10g" % gamman,
                          "limit": limit, "v0": V0, "dt": DT, "steps": STEPS,
                          "layer": args.layer}
                for engine in ("tri", "sphere"):
                    var = dict(common)
                    if engine == "tri":
                        var.update(mesh="ico.stl", plane="plane.stl")
                    else:
                        var.update(plane="plane.stl", mass="%.17g" % mass)
                    name = "%s_%s_e%.1f_%s.txt" % (engine, "pair" if pair else "wall", e_t, limit)
                    rows = run(exe, "in." + engine, args.work, name, var)
                    m = measure(rows)
                    tc_a, e_a = analytic(KN, m["mass"] if pair == 0 else m["mass"] / 2, gamman,
                                         -m["v_in"], g, limit)
                    tc_0, e_0 = textbook(KN, meff, gamman)
                    r = dict(engine=engine, pair=pair, e_target=e_t, zeta=zeta, gamman=gamman,
                             limit=limit, tc=m["tc"], e=m["e"], tc_a=tc_a, e_a=e_a, tc_0=tc_0,
                             e_0=e_0, contacts=m["contacts"])
                    r["err_e"] = r["e"] / e_a - 1
                    r["err_tc"] = r["tc"] / tc_a - 1
                    r["ok"] = abs(r["err_e"]) <= TOL and abs(r["err_tc"]) <= TOL
                    results.append(r)
                    traces[(engine, pair, e_t, limit)] = rows

    print(valtools.machine_line())
    print("icosphere level %d (%d triangles), R = %g m, mass = %.6g kg, eps = %g m (layer %s), "
          "kn = %g N/m, v0 = %g m/s, dt = %g s" % (LEVEL, len(faces), R, mass, EPS, args.layer,
                                                  KN, V0, DT))
    print("| case | engine | limitForce | zeta | gamman (1/s) | e textbook | e analytic | e measured"
          " | error e | t_c textbook (us) | t_c analytic (us) | t_c measured (us) | error t_c |"
          " pass (2%) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in results:
        print("| %s | %s | %s | %.4f | %.1f | %.4f | %.4f | %.4f | %+.2f%% | %.2f | %.2f | %.2f | "
              "%+.2f%% | %s |" % (
                  "pair" if r["pair"] else "wall", r["engine"], r["limit"], r["zeta"], r["gamman"],
                  r["e_0"], r["e_a"], r["e"], 100 * r["err_e"], 1e6 * r["tc_0"], 1e6 * r["tc_a"],
                  1e6 * r["tc"], 100 * r["err_tc"], "PASS" if r["ok"] else "FAIL"))
    worst = max(max(abs(r["err_e"]), abs(r["err_tc"])) for r in results)
    print("worst error: %.3f%%; %d/%d cases pass" % (
        100 * worst, sum(r["ok"] for r in results), len(results)))
    tri_vs_sphere = max(abs(a["e"] - b["e"]) for a in results for b in results
                        if a["engine"] == "tri" and b["engine"] == "sphere"
                        and (a["pair"], a["e_target"], a["limit"]) ==
                        (b["pair"], b["e_target"], b["limit"]))
    print("largest |e_tri - e_sphere| = %.2e" % tri_vs_sphere)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(2, 2, figsize=(11, 8.5))
    for col, pair in enumerate((0, 1)):
        a = ax[0][col]
        for e_t, colour in zip(E_TARGETS, ("C0", "C1", "C2", "C3")):
            for engine, style in (("tri", "-"), ("sphere", ":")):
                rows = traces[(engine, pair, e_t, "off")]
                a.plot([1e6 * r[0] for r in rows], [r[1] for r in rows], style, color=colour,
                       lw=2.2 if engine == "tri" else 1.4,
                       label="%s, e=%.1f" % ("icosphere" if engine == "tri" else "sphere", e_t))
        a.set_xlabel("time (us)")
        a.set_ylabel("normal velocity (m/s)" if pair == 0 else "relative velocity (m/s)")
        a.set_title("%s, limitForce off" % ("drop on plane (tri/wall vs wall/gran)" if pair == 0
                                            else "head-on pair (tri/gran vs gran)"))
        a.legend(fontsize=7, ncol=2)
        a.grid(alpha=0.3)
    zs = [i / 200 * 0.5 for i in range(1, 200)]
    for col, (key, lab) in enumerate((("e", "coefficient of restitution e"),
                                      ("tc", "contact duration (us)"))):
        a = ax[1][col]
        for pair, mk in ((0, "o"), (1, "s")):
            meff = mass if pair == 0 else mass / 2
            gscale = G if pair == 0 else 0.0
            for limit, colour in (("off", "C0"), ("on", "C3")):
                curve = [analytic(KN, meff, 2 * z * math.sqrt(KN / meff), V0, gscale, limit)
                         for z in zs]
                yv = [c[1] if key == "e" else 1e6 * c[0] for c in curve]
                a.plot(zs, yv, "-" if pair == 0 else "--", color=colour, lw=1,
                       label="analytic, %s, limitForce %s" % ("wall" if pair == 0 else "pair",
                                                              limit))
                for engine, fill in (("tri", colour), ("sphere", "none")):
                    sel = [r for r in results if r["pair"] == pair and r["limit"] == limit
                           and r["engine"] == engine]
                    a.plot([r["zeta"] for r in sel],
                           [r[key] if key == "e" else 1e6 * r[key] for r in sel], mk,
                           mfc=fill, mec=colour, ms=8 if engine == "sphere" else 5,
                           label="%s, %s, %s" % ("icosphere" if engine == "tri" else "sphere",
                                                  "wall" if pair == 0 else "pair", limit))
        a.set_xlabel("damping ratio zeta = gamman / (2 sqrt(kn / m_eff))")
        a.set_ylabel(lab)
        a.grid(alpha=0.3)
        a.legend(fontsize=6, ncol=2)
    fig.suptitle("Normal restitution: icosphere (%d triangles) vs LIGGGHTS sphere vs linear "
                 "spring-dashpot" % len(faces))
    fig.tight_layout()
    out = os.path.join(HERE, "restitution.png" if args.layer == "inside"
                       else "restitution_outside.png")
    fig.savefig(out, dpi=110)
    print("plot:", out)
    return 0 if all(r["ok"] for r in results) else 1


if __name__ == "__main__":
    sys.exit(main())
