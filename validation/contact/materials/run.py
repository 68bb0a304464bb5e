#!/usr/bin/python3
"""LIGGGHTS materials on a triangulated icosphere (pair tri/gran, fix tri/wall `model hooke|hertz`,
epsilon auto) beside LIGGGHTS's own spheres (pair gran / fix wall/gran, model hooke|hertz) of the
icosphere's volume-equivalent radius and mass: restitution and contact duration against impact
speed, head-on pairs and a plane.

  /usr/bin/python3 run.py [--exe build/src_plugin/driver/liggghts-tri] [--work /tmp/...]
                         [--layer inside|outside]

epsilon auto is the peak overlap of an undamped contact at the characteristic velocity, and
fills the contact's soft layers at half: 2 eps = 2 x that overlap for a pair; against a wall
(whose mesh has no layer of its own) the particle's layer alone, eps = that overlap, with the
layer inside the mesh (the default), and 2 eps with `--layer outside` (the wall's layer).

Runs in.tri and in.sphere into the scratch folder, prints the README table, writes
materials.png next to this script. Needs Debian's matplotlib (/usr/bin/python3).
"""
import argparse
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(REPO, "validation", "meshes"))
sys.path.insert(0, os.path.join(REPO, "validation"))
import meshgen  # noqa: E402
import valtools  # noqa: E402

R, RHO, LEVEL = 0.002, 2500.0, 3
Y, NU, E, VC = 1e8, 0.3, 0.5, 1.0
SPEEDS = (0.25, 0.5, 1.0, 1.5)   # x VC; above 2 VC (a wall, layer inside: 1 VC) the peak overlap
                                 # exceeds epsilon auto's layers (a deep contact)
DT, STEPS = 2e-7, 4000
HERTZ_I = math.gamma(0.4) * math.sqrt(math.pi) / (2.5 * math.gamma(0.9))


def y_eff():
    return 1.0 / (2 * (1 - NU * NU) / Y)


def hertz_overlap(reff, meff, v):
    return (15 * meff * v * v / (16 * y_eff() * math.sqrt(reff))) ** 0.4


def zeta_clamped(e):
    lo, hi = 0.0, 1.0 - 1e-15
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if math.exp(-mid * 2 * math.acos(mid) / math.sqrt(1 - mid * mid)) > e:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def zeta_liggghts(e):
    le = math.log(e)
    return -le / math.sqrt(math.pi ** 2 + le * le)


def liggghts_hertz(reff, meff, v):
    """LIGGGHTS's damped hertz contact (limitForce off) at v: (duration, restitution); RK4."""
    le = math.log(E)
    beta = le / math.sqrt(le * le + math.pi ** 2)
    ys = y_eff()

    def acc(x, u):
        if x <= 0:
            return 0.0
        return -(4.0 / 3.0 * ys * math.sqrt(reff) * x ** 1.5
                 - 2 * math.sqrt(5.0 / 6.0) * beta * math.sqrt(2 * ys * math.sqrt(reff * x) * meff) * u) / meff
    h = 2 * HERTZ_I * hertz_overlap(reff, meff, v) / v / 20000
    x, u, t = 0.0, v, 0.0
    while True:
        k1x, k1u = u, acc(x, u)
        k2x, k2u = u + h / 2 * k1u, acc(x + h / 2 * k1x, u + h / 2 * k1u)
        k3x, k3u = u + h / 2 * k2u, acc(x + h / 2 * k2x, u + h / 2 * k2u)
        k4x, k4u = u + h * k3u, acc(x + h * k3x, u + h * k3u)
        xn = x + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x)
        un = u + h / 6 * (k1u + 2 * k2u + 2 * k3u + k4u)
        if xn <= 0:
            s = x / (x - xn)
            return t + s * h, -(u + s * (un - u)) / v
        x, u, t = xn, un, t + h


def tri_kn(model, reff, meff, limit="on"):
    """kn of material_mapping.h: hooke = LIGGGHTS's hooke at VC (meff VC^2 / delta_H^2); hertz =
    the linear spring whose contact (damped for E, with or without limitForce) lasts as long as
    LIGGGHTS's damped hertz contact at VC."""
    if model == "hooke":
        d = hertz_overlap(reff, meff, VC)
        return meff * VC * VC / (d * d)
    z = tri_zeta(limit)
    factor = (2 * math.acos(z) if limit == "on" else math.pi) / math.sqrt(1 - z * z)
    return meff * (factor / liggghts_hertz(reff, meff, VC)[0]) ** 2


def tri_zeta(limit):
    return zeta_clamped(E) if limit == "on" else zeta_liggghts(E)


def measure(rows):
    idx = [k for k, r in enumerate(rows) if abs(r[2]) > 1e-12]
    i0, i1 = idx[0], idx[-1]
    assert i1 + 1 < len(rows), "run ended during the contact"
    v_in, v_out = rows[i0 - 1][1], rows[i1 + 1][1]
    return -v_out / v_in, (i1 - i0 + 1) * DT, max(r[4] for r in rows)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", default=valtools.default_exe())
    ap.add_argument("--work", default="/tmp/liggghts-tri-validation/materials")
    ap.add_argument("--layer", default="inside", choices=("inside", "outside"),
                    help="fix tri/particles layer (default inside: the mesh is the contact surface)")
    args = ap.parse_args()
    exe = os.path.abspath(args.exe)
    os.makedirs(args.work, exist_ok=True)
    verts, faces = meshgen.icosphere(LEVEL, R)
    meshgen.write_stl(os.path.join(args.work, "ico3.stl"), verts, faces)
    meshgen.write_stl(os.path.join(args.work, "plane.stl"), *meshgen.plane(0.01))
    vol = sum(
        (verts[a][0] * (verts[b][1] * verts[c][2] - verts[b][2] * verts[c][1])
         - verts[a][1] * (verts[b][0] * verts[c][2] - verts[b][2] * verts[c][0])
         + verts[a][2] * (verts[b][0] * verts[c][1] - verts[b][1] * verts[c][0])) / 6.0
        for a, b, c in faces)
    mass = RHO * vol
    r_eq = (3 * vol / (4 * math.pi)) ** (1.0 / 3.0)
    # epsilon auto of the hooke pair (the wall deck has one particle: its wall sets it)
    eps = VC * math.sqrt((mass / 2) / tri_kn("hooke", r_eq / 2, mass / 2))

    results = []
    engines = (("tri", "on"), ("tri", "off"), ("sphere", "off"))
    for model in ("hooke", "hertz"):
        for pair in (1, 0):
            reff, meff = (r_eq / 2, mass / 2) if pair else (r_eq, mass)
            for s in SPEEDS:
                v0 = s * VC
                row = dict(model=model, pair=pair, speed=s)
                for engine, limit in engines:
                    var = dict(pair=pair, model=model, Y=Y, nu=NU, e=E, vc=VC, v0=v0, dt=DT,
                               steps=STEPS, plane="plane.stl")
                    key = engine if engine == "sphere" else "tri_" + limit
                    if engine == "tri":  # eps only places the icosphere: at least epsilon auto
                        var.update(mesh="ico3.stl", R=R, eps=1e-4, limit=limit,
                                   layer=args.layer)
                    else:
                        var.update(r="%.17g" % r_eq, mass="%.17g" % mass)
                    name = "%s_%s_%s_v%.2f.txt" % (key, model, "pair" if pair else "wall", v0)
                    valtools.run_deck(exe, os.path.join(HERE, "in." + engine), dict(out=name, **var),
                                      args.work, os.path.join(args.work, name + ".screen"))
                    e, tc, ov = measure(valtools.read_rows(os.path.join(args.work, name)))
                    row[key] = (e, tc, ov)
                    if engine == "tri":
                        kn = tri_kn(model, reff, meff, limit)
                        z = tri_zeta(limit)
                        row["kn_" + limit] = kn
                        row["tc_" + key] = (2 * math.acos(z) if limit == "on" else math.pi) / (
                            math.sqrt(kn / meff) * math.sqrt(1 - z * z))
                        # epsilon auto: the deck's only pair of types sets it (the wall deck has
                        # one particle), v_c sqrt(meff / kn)
                        eps_auto = VC * math.sqrt(meff / kn)
                        with open(os.path.join(args.work, name + ".screen")) as f:
                            printed = float(re.search(r"epsilon auto = (\S+) m", f.read()).group(1))
                        assert abs(printed / eps_auto - 1) < 1e-5, (name, printed, eps_auto)
                        # the contact's layers: 2 eps (pair; wall, layer outside), eps (wall)
                        layers = eps_auto if (not pair and args.layer == "inside") else 2 * eps_auto
                        row["ov_" + key] = ov / layers
                if model == "hooke":   # LIGGGHTS hooke: same kn, its own zeta, limitForce off
                    zl = zeta_liggghts(E)
                    kl = tri_kn("hooke", reff, meff)
                    row["tc_sphere"] = math.pi / (math.sqrt(kl / meff) * math.sqrt(1 - zl * zl))
                else:                  # LIGGGHTS's damped hertz at this speed (integrated)
                    row["tc_sphere"] = liggghts_hertz(reff, meff, v0)[0]
                results.append(row)

    print(valtools.machine_line())
    print("icosphere level %d (%d triangles), R = %g m, mass = %.6g kg, volume-equivalent radius "
          "%.6g m; Y = %g Pa, nu = %g, e = %g, characteristicVelocity = %g m/s; epsilon auto = "
          "%.4g m (hooke pair), dt = %g s" % (LEVEL, len(faces), R, mass, r_eq, Y, NU, E, VC, eps, DT))
    print()
    print("| model | contact | v / v_c | kn tri (N/m) | e tri | e tri, limitForce off | e LIGGGHTS "
          "sphere | t_c tri (us) | t_c tri, limitForce off (us) | t_c LIGGGHTS sphere (us) | "
          "t_c sphere reference (us) | peak overlap tri / layers (%s) |"
          % ("pair 2 eps, wall eps" if args.layer == "inside" else "2 eps"))
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in results:
        print("| %s | %s | %.2f | %.0f | %.4f | %.4f | %.4f | %.1f (%.1f) | %.1f (%.1f) | %.1f | "
              "%.1f %s | %.2f |" % (
                  r["model"], "pair" if r["pair"] else "wall", r["speed"], r["kn_on"],
                  r["tri_on"][0], r["tri_off"][0], r["sphere"][0],
                  1e6 * r["tri_on"][1], 1e6 * r["tc_tri_on"], 1e6 * r["tri_off"][1],
                  1e6 * r["tc_tri_off"], 1e6 * r["sphere"][1], 1e6 * r["tc_sphere"],
                  "(pi/omega_d)" if r["model"] == "hooke" else "(hertz ODE)", r["ov_tri_on"]))
    worst_e = max(abs(r[k][0] / E - 1) for r in results for k in ("tri_on", "tri_off"))
    worst_t = max(abs(r[k][1] / r["tc_" + k] - 1) for r in results for k in ("tri_on", "tri_off"))
    print("\ntri: worst |e / coefficientRestitution - 1| = %.2f%%, worst |t_c / analytic - 1| = "
          "%.2f%% (the analytic duration in brackets)" % (100 * worst_e, 100 * worst_t))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(2, 2, figsize=(11, 8.5))
    for col, model in enumerate(("hooke", "hertz")):
        for pair, colour in ((1, "C0"), (0, "C3")):
            sel = [r for r in results if r["model"] == model and r["pair"] == pair]
            xs = [r["speed"] for r in sel]
            label = "pair" if pair else "wall"
            for key, style, name in (("tri_on", "o-", "icosphere"),
                                     ("tri_off", "^-.", "icosphere, limitForce off"),
                                     ("sphere", "s--", "LIGGGHTS sphere")):
                kw = dict(mfc="none", ms=8) if key == "sphere" else dict(ms=5)
                ax[0][col].plot(xs, [r[key][0] for r in sel], style, color=colour,
                                label="%s, %s" % (name, label), **kw)
                ax[1][col].plot(xs, [1e6 * r[key][1] for r in sel], style, color=colour,
                                label="%s, %s" % (name, label), **kw)
            ax[1][col].plot(xs, [1e6 * r["tc_sphere"] for r in sel], ":", color="k", lw=1,
                            label=("pi / omega_d, " if model == "hooke" else "hertz ODE, ") + label)
        ax[0][col].axhline(E, color="k", lw=0.8, label="coefficientRestitution")
        ax[0][col].set_ylim(E - 0.02, E + 0.02)
        ax[0][col].set_title("model %s: restitution" % model)
        ax[1][col].set_title("model %s: contact duration" % model)
        for a in (ax[0][col], ax[1][col]):
            a.set_xlabel("impact speed / characteristicVelocity")
            a.grid(alpha=0.3)
            a.legend(fontsize=6, ncol=2)
        ax[0][col].set_ylabel("e")
        ax[1][col].set_ylabel("contact duration (us)")
    fig.suptitle("Icosphere (%d triangles; pair tri/gran, fix tri/wall; epsilon auto) vs LIGGGHTS "
                 "spheres of its volume-equivalent radius\nY = %g Pa, nu = %g, "
                 "coefficientRestitution %g, characteristicVelocity %g m/s"
                 % (len(faces), Y, NU, E, VC), fontsize=10)
    fig.tight_layout()
    out = os.path.join(HERE, "materials.png" if args.layer == "inside" else "materials_outside.png")
    fig.savefig(out, dpi=110)
    print("plot:", out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
