"""LIGGGHTS materials on mesh particles (pair_style tri/gran / fix tri/wall `model hooke|hertz`),
`epsilon auto` and the time-step check of fix tri/particles, through real decks (in.materials,
in.timestep_check). Every expected number is computed here from the formulas of
src_plugin/kernel/model/material_mapping.h, independently of the C++. Tests materials_forces,
materials_restitution, materials_epsilon_auto, materials_timestep, materials_bad_input."""
import math
import os
import re
import subprocess
import sys

import decklib
from decklib import MESHGEN, Failure, check, expect_error, run_deck, thermo_rows


# The cube of the decks as read (ASCII STL: doubles, all digits): side 2h, density 2500
# (in.materials).
H = 0.002
VOLUME = (2 * H) ** 3
MASS = 2500.0 * VOLUME
R_EQ = (3 * VOLUME / (4 * math.pi)) ** (1.0 / 3.0)
BOUNDING = math.sqrt(3.0) * H
HERTZ_I = math.gamma(0.4) * math.sqrt(math.pi) / (2.5 * math.gamma(0.9))


def y_eff(y, nu):
    return 1.0 / (2 * (1 - nu * nu) / y)


def g_eff(y, nu):
    return 1.0 / (2 * 2 * (2 - nu) * (1 + nu) / y)


def zeta_for(e, limit_force):
    """Damping ratio of the linear spring-dashpot that restitutes e (zeta < 1 cases only)."""
    le = math.log(e)
    if not limit_force:
        return -le / math.sqrt(math.pi ** 2 + le * le)
    lo, hi = 0.0, 1.0 - 1e-15
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if math.exp(-mid * 2 * math.acos(mid) / math.sqrt(1 - mid * mid)) > e:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def liggghts_hertz_duration(ys, reff, meff, v, e):
    """LIGGGHTS's damped hertz contact (limitForce off), RK4 with 40000 steps per Hertz time."""
    le = math.log(e)
    beta = le / math.sqrt(le * le + math.pi ** 2)

    def acc(x, u):
        if x <= 0:
            return 0.0
        return -(4.0 / 3.0 * ys * math.sqrt(reff) * x ** 1.5
                 - 2 * math.sqrt(5.0 / 6.0) * beta * math.sqrt(2 * ys * math.sqrt(reff * x) * meff) * u) / meff
    delta = (15 * meff * v * v / (16 * ys * math.sqrt(reff))) ** 0.4
    h = 2 * HERTZ_I * delta / v / 40000
    x, u, t = 0.0, v, 0.0
    while True:
        k1x, k1u = u, acc(x, u)
        k2x, k2u = u + h / 2 * k1u, acc(x + h / 2 * k1x, u + h / 2 * k1u)
        k3x, k3u = u + h / 2 * k2u, acc(x + h / 2 * k2x, u + h / 2 * k2u)
        k4x, k4u = u + h * k3u, acc(x + h * k3x, u + h * k3u)
        xn = x + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x)
        un = u + h / 6 * (k1u + 2 * k2u + 2 * k3u + k4u)
        if xn <= 0:
            return t + h * x / (x - xn)
        x, u, t = xn, un, t + h


def mapped(model, y, nu, e, v_c, wall, limit_force=True):
    """(kn, kt, gamman in 1/s, meff, zeta) of the mapping for two cubes (or a cube and a wall)."""
    reff, meff = (R_EQ, MASS) if wall else (R_EQ / 2, MASS / 2)
    ys, gs = y_eff(y, nu), g_eff(y, nu)
    zeta = zeta_for(e, limit_force)
    if model == "hooke":
        kn = 16.0 / 15.0 * math.sqrt(reff) * ys * (15 * meff * v_c ** 2 / (16 * math.sqrt(reff) * ys)) ** 0.2
        kt = kn
    else:  # our contact lasts as long as LIGGGHTS's damped hertz contact at v_c
        factor = (2 * math.acos(zeta) if limit_force else math.pi) / math.sqrt(1 - zeta * zeta)
        kn = meff * (factor / liggghts_hertz_duration(ys, reff, meff, v_c, e)) ** 2
        kt = 6 * gs / ys * kn
    return kn, kt, 2 * zeta * math.sqrt(kn * meff) / meff, meff, zeta


def make_meshes(work):
    subprocess.run([sys.executable, MESHGEN, "cube", "2", repr(0.004), "cube.stl"], cwd=work,
                   check=True)
    subprocess.run([sys.executable, MESHGEN, "plane", "0.01", "plane.stl"], cwd=work, check=True)


def last_frame(path):
    """The last snapshot of a dump as {id: [floats]}."""
    return {t: [float(x) for x in r] for t, r in decklib.last_frame(path)[1].items()}


# --------------------------------------------------------------------------------------------

def test_materials_forces(ctx):
    """One force evaluation (run 0, brute-force kernel, explicit epsilon 1e-4, the meshes pressed
    1e-4 m into each other or into the wall: overlap 1e-4 m) for hooke and hertz, pair and wall, against F = kn overlap - gamman meff v_n with
    kn, gamman from the mapping computed here (hertz: within 1e-6, LIGGGHTS's damped hertz
    contact integrated here and in the kernel)."""
    make_meshes(ctx.work)
    y, nu, e, gap, v = 1e8, 0.3, 0.5, -1e-4, 0.1
    overlap = -gap  # the meshes are the contact surfaces (the layer inside)
    tolerance = {"hooke": 1e-9, "hertz": 1e-6}  # hertz: two integrations of LIGGGHTS's contact
    for model in ("hooke", "hertz"):
        tol = tolerance[model]
        kn, _, gn, meff, _ = mapped(model, y, nu, e, 1.0, wall=False)
        xa, xb = -(H + gap / 2), H + gap / 2
        run_deck(ctx, "in.materials", {"modelargs": f"model {model}", "xa": repr(xa), "xb": repr(xb),
                                       "vxa": v, "vxb": -v, "Y": y, "nu": nu, "e": e,
                                       "contactargs": "kernel bf"})
        f = last_frame(os.path.join(ctx.work, "materials.dump"))[2][3]
        expected = kn * overlap + gn * meff * 2 * v
        check(abs(f - expected) <= tol * expected,
              f"{model} pair: fx on b {f!r}, mapping gives {expected!r} (kn {kn:.8g} N/m, gamman {gn:.8g} 1/s)")
        print(f"{model} pair: kn {kn:.6g} N/m, gamman {gn:.6g} 1/s: F {f:.10g} N (expected {expected:.10g})")

        kn, _, gn, meff, _ = mapped(model, y, nu, e, 1.0, wall=True)
        run_deck(ctx, "in.materials", {"wall": 1, "modelargs": f"model {model}",
                                       "zc": repr(H + gap), "vz": -v, "Y": y, "nu": nu, "e": e,
                                       "contactargs": "kernel bf"})
        f = last_frame(os.path.join(ctx.work, "materials.dump"))[1][5]
        expected = kn * overlap + gn * meff * v
        check(abs(f - expected) <= tol * expected,
              f"{model} wall: fz {f!r}, mapping gives {expected!r} (kn {kn:.8g} N/m, gamman {gn:.8g} 1/s)")
        print(f"{model} wall: kn {kn:.6g} N/m, gamman {gn:.6g} 1/s: F {f:.10g} N (expected {expected:.10g})")

    # model hooke/stiffness, named or not, is the default: bitwise the same collision.
    dumps = []
    for modelargs in ("tangential history", "model hooke/stiffness"):
        _, out = run_deck(ctx, "in.materials", {"modelargs": modelargs, "xa": -0.0024, "xb": 0.0024,
                                                "vxa": 0.3, "vxb": -0.3, "gamman": 20, "gammat": 10,
                                                "mu": 0.5, "nsteps": 2500})
        rows = thermo_rows(out)
        check(any(r["nc"] > 0 for r in rows) and rows[-1]["nc"] == 0,
              f"{modelargs}: the cubes did not collide and separate")
        with open(os.path.join(ctx.work, "materials.dump")) as fh:
            dumps.append(fh.read())
    check(dumps[0] == dumps[1], "model hooke/stiffness differs from the default")
    print("model hooke/stiffness: bitwise the default over a 2500-step collision")


def collide(ctx, variables, nsteps):
    """Rows before and after the contact, and its duration: the steps with a contact force
    (with limitForce the force ends before the soft layers part)."""
    _, out = run_deck(ctx, "in.materials", dict(variables, nsteps=nsteps))
    rows = thermo_rows(out)
    force = "fz1" if variables.get("wall") else "fx2"
    touching = [k for k, r in enumerate(rows) if r[force] != 0.0]
    check(touching, f"{variables}: no contact")
    k0, k1 = touching[0], touching[-1]
    check(k1 + 1 < len(rows) and len(touching) == k1 - k0 + 1 and rows[-1]["nc"] == 0,
          f"{variables}: the contact did not end cleanly")
    return rows[k0 - 1], rows[k1 + 1], (k1 - k0 + 1) * float(variables["dt"]), out


def test_materials_restitution(ctx):
    """Head-on collisions with epsilon auto: the measured restitution is coefficientRestitution
    (limitForce on, our default) and the duration is the linear spring-dashpot's, pair and wall,
    hooke and hertz."""
    make_meshes(ctx.work)
    y, nu, dt = 1e8, 0.3, 1e-6
    for model, e in (("hooke", 0.5), ("hertz", 0.8)):
        kn, _, _, meff, zeta = mapped(model, y, nu, e, 1.0, wall=False)
        before, after, tc, _ = collide(ctx, {"modelargs": f"model {model}", "eps": "epsilon auto",
                                             "xa": -(H + 2e-4), "xb": H + 2e-4, "vxa": 0.5,
                                             "vxb": -0.5, "Y": y, "nu": nu, "e": e, "dt": dt}, 1000)
        measured = (after["vx2"] - after["vx1"]) / (before["vx1"] - before["vx2"])
        tc_a = 2 * math.acos(zeta) / (math.sqrt(kn / meff) * math.sqrt(1 - zeta * zeta))
        check(abs(measured - e) <= 0.005 * e, f"{model} pair: restitution {measured:.5f}, wanted {e}")
        check(abs(tc - tc_a) <= 0.01 * tc_a, f"{model} pair: contact {tc:.4g} s, analytic {tc_a:.4g} s")
        print(f"{model} pair: e {measured:.5f} (coefficientRestitution {e}), contact {tc * 1e6:.0f} us "
              f"(analytic {tc_a * 1e6:.1f} us)")

        kn, _, _, meff, zeta = mapped(model, y, nu, e, 1.0, wall=True)
        before, after, tc, _ = collide(ctx, {"wall": 1, "modelargs": f"model {model}",
                                             "eps": "epsilon auto", "zc": H + 3e-4, "vz": -0.5,
                                             "Y": y, "nu": nu, "e": e, "dt": dt}, 1000)
        measured = -after["vz1"] / before["vz1"]
        tc_a = 2 * math.acos(zeta) / (math.sqrt(kn / meff) * math.sqrt(1 - zeta * zeta))
        check(abs(measured - e) <= 0.005 * e, f"{model} wall: restitution {measured:.5f}, wanted {e}")
        check(abs(tc - tc_a) <= 0.01 * tc_a, f"{model} wall: contact {tc:.4g} s, analytic {tc_a:.4g} s")
        print(f"{model} wall: e {measured:.5f} (coefficientRestitution {e}), contact {tc * 1e6:.0f} us "
              f"(analytic {tc_a * 1e6:.1f} us)")


def auto_line(out):
    m = re.search(r"tri/particles: epsilon auto = (\S+) m", out)
    check(m, f"no 'epsilon auto' line:\n{out[-2000:]}")
    return float(m.group(1))


def test_materials_epsilon_auto(ctx):
    """epsilon auto (and no epsilon at all) = the peak overlap v_c sqrt(meff / kn) of the
    published pairs of types; the radius is the mesh's bounding radius (the layer inside it), or
    with `layer outside` the bounding radius plus epsilon, set before the first neighbour list;
    an explicit epsilon prints no such line."""
    make_meshes(ctx.work)
    y, nu = 1e8, 0.3
    kn_hooke = mapped("hooke", y, nu, 0.5, 1.0, wall=False)[0]
    hertz_overlap = (15 * (MASS / 2) / (16 * y_eff(y, nu) * math.sqrt(R_EQ / 2))) ** 0.4
    cases = [
        ("hooke pair, epsilon auto", {"eps": "epsilon auto"}, math.sqrt(MASS / 2 / kn_hooke)),
        ("hooke pair, no epsilon", {"eps": "assign random 1"}, math.sqrt(MASS / 2 / kn_hooke)),
        ("hooke/stiffness pair, v_c 2 m/s", {"eps": "epsilon auto", "modelargs": "model hooke/stiffness",
                                             "vcfix": "fix p5 all property/global characteristicVelocity scalar 2.0"},
         2.0 * math.sqrt(MASS / 2 / 2000.0)),
        ("hooke/stiffness wall only", {"eps": "epsilon auto", "wall": 1,
                                       "modelargs": "model hooke/stiffness"},
         math.sqrt(MASS / 2000.0)),
        ("hooke pair, epsilon auto, layer outside", {"eps": "epsilon auto", "tpargs": "layer outside"},
         math.sqrt(MASS / 2 / kn_hooke)),
    ]
    for name, variables, expected in cases:
        _, out = run_deck(ctx, "in.materials", variables)
        printed = auto_line(out)
        check(abs(printed - expected) <= 1e-5 * expected, f"{name}: printed {printed}, expected {expected}")
        rows = last_frame(os.path.join(ctx.work, "materials.dump"))
        check(rows, f"{name}: no atoms in the dump")
        grown = expected if "outside" in name else 0.0
        for tag, r in rows.items():
            eps = r[9] - BOUNDING
            check(abs(eps - grown) <= 1e-9 * expected, f"{name}: atom {tag} radius {r[9]!r} = "
                  f"bounding radius + {eps!r}, expected + {grown!r}")
        print(f"{name}: epsilon {printed:g} m (expected {expected:.6g})")
    check(abs(math.sqrt(MASS / 2 / kn_hooke) - hertz_overlap) <= 1e-12 * hertz_overlap,
          "hooke epsilon is not the Hertz peak overlap")
    _, out = run_deck(ctx, "in.materials", {})
    check("epsilon auto" not in out, "an explicit epsilon printed an 'epsilon auto' line")
    rows = last_frame(os.path.join(ctx.work, "materials.dump"))
    check(rows, "explicit epsilon: no atoms in the dump")
    check(all(abs(r[9] - BOUNDING) <= 1e-15 for r in rows.values()),
          "explicit epsilon 1e-4: the radius is not the mesh's bounding radius")
    run_deck(ctx, "in.materials", {"tpargs": "layer outside"})
    rows = last_frame(os.path.join(ctx.work, "materials.dump"))
    check(all(abs(r[9] - BOUNDING - 1e-4) <= 1e-15 for r in rows.values()),
          "explicit epsilon 1e-4, layer outside: not applied to the radius")
    # The collision with epsilon auto is found by the neighbour list (cutoffs sized after it).
    before, after, _, _ = collide(ctx, {"eps": "epsilon auto", "xa": -(H + 2e-4), "xb": H + 2e-4,
                                        "vxa": 0.5, "vxb": -0.5, "dt": 1e-6}, 800)
    check(after["vx1"] < 0 < after["vx2"], "the cubes did not bounce with epsilon auto")


def info_line(out):
    m = re.search(r"tri/particles: time-step check: (.*)", out)
    check(m, f"no time-step line:\n{out[-2000:]}")
    return m.group(1)


def test_materials_timestep(ctx):
    """The time-step check: the four 1 g particles on kn 5e4 N/m with dt 2e-4 s stop; dt at 12.7 %
    of the contact time warns and runs; 3.2 % only reports; off skips it; every N repeats it;
    fix tri/adapt_dt's dtmin decides the error and its dtmax the warning; the approach and
    overlap warnings when one particle flies at 10 m/s towards another."""
    make_meshes(ctx.work)
    tc = math.pi * math.sqrt(5e-4 / 5e4)
    line = expect_error(ctx, "in.timestep_check", {},
                        r"Fix tri/particles: time step 0\.0002 s cannot resolve a contact: it is "
                        r"63\.7% of the shortest contact time 0\.000314159 s \(pair tri/gran, types 1 "
                        r"and 1: pi sqrt\(meff 0\.0005 kg / kn 50000 N/m\)\), above 20%.*use timestep "
                        r"3\.14159e-05 or smaller")
    print(f"dt 2e-4: {line}")
    _, out = run_deck(ctx, "in.timestep_check", {"dt": 4e-5})
    warnings = [l for l in out.splitlines() if "WARNING" in l and "tri/particles" in l]
    check(len(warnings) == 1 and re.search(r"time step 4e-05 s is 12\.7% of the shortest contact "
                                           r"time 0\.000314159 s .*fewer than 10 steps per contact", warnings[0]),
          f"dt 4e-5: warnings {warnings}")
    print(f"dt 4e-5: {warnings[0].strip()}")
    _, out = run_deck(ctx, "in.timestep_check", {"dt": 1e-5})
    check("WARNING" not in out, "dt 1e-5 warned")
    text = info_line(out)
    check(re.search(r"dt 1e-05 s = 3\.18% of the shortest contact time 0\.000314159 s", text), text)
    print(f"dt 1e-5: {text}")
    _, out = run_deck(ctx, "in.timestep_check", {"tpargs": "check_timestep off"})
    check("time-step check" not in out and "WARNING" not in out, "check_timestep off still checked")
    _, out = run_deck(ctx, "in.timestep_check", {"dt": 4e-5, "tpargs": "check_timestep 5", "nsteps": 20})
    n = sum(1 for l in out.splitlines() if "WARNING" in l and "12.7% of the shortest" in l)
    check(n == 5, f"check_timestep 5 over 20 steps: {n} warnings, expected 5 (setup, 5, 10, 15, 20)")
    line = expect_error(ctx, "in.timestep_check",
                        {"extra": "fix adt all tri/adapt_dt dtmax 2e-4 dtmin 1e-4"},
                        r"the smallest time step of fix tri/adapt_dt, dtmin 0\.0001 s, cannot resolve a "
                        r"contact: it is 31\.8% .*lower dtmin to 3\.14159e-05 s")
    print(f"adapt_dt dtmin 1e-4: {line}")
    _, out = run_deck(ctx, "in.timestep_check", {"extra": "fix adt all tri/adapt_dt dtmax 2e-4 dtmin 1e-6"})
    warnings = [l for l in out.splitlines() if "WARNING" in l and "tri/particles" in l]
    check(len(warnings) == 1 and "fix tri/adapt_dt may raise the time step to dtmax 0.0002 s" in warnings[0],
          f"adapt_dt dtmax 2e-4: warnings {warnings}")
    _, out = run_deck(ctx, "in.timestep_check", {"dt": 1e-5, "v": 10, "nsteps": 2})
    warnings = [l for l in out.splitlines() if "WARNING" in l and "tri/particles" in l]
    check(len(warnings) == 2 and "fastest approach, 10 m/s, a contact closes in by 1 epsilon" in warnings[0]
          and re.search(r"peak overlap .* = 0\.001 m .*exceeds the soft layers \(0\.0002 m\)", warnings[1]),
          f"10 m/s: warnings {warnings}")
    for w in warnings:
        print(f"10 m/s: {w.strip()}")
    # The 100 m/s deck of test_extreme.py (check off there): 0.16 g cubes on kn 2e8 N/m, dt 1e-5 s.
    line = expect_error(ctx, "in.extreme_fast", {"tscheck": "check_timestep setup"},
                        r"time step 1e-05 s cannot resolve a contact: it is 503% of the shortest "
                        r"contact time 1\.98692e-06 s")
    print(f"in.extreme_fast with the check on: {line}")
    print(f"contact time {tc:.6g} s")


BAD = [
    ("pair model", "in.materials", {"modelargs": "model foo"},
     r"Pair tri/gran: 'model' expects hooke/stiffness, hooke or hertz, got 'foo'"),
    ("wall model", "in.materials", {"wall": 1, "modelargs": "model foo"},
     r"Fix tri/wall: 'model' expects hooke/stiffness, hooke or hertz, got 'foo'"),
    ("youngsModulus missing", "in.materials", {"yname": "youngsModulusX"},
     r"Could not locate a fix/property storing value\(s\) for youngsModulus as requested by pair tri/gran \(model hooke\)"),
    ("coefficientRestitution missing", "in.materials", {"modelargs": "model hertz", "ename": "restitution"},
     r"Could not locate a fix/property storing value\(s\) for coefficientRestitution as requested by pair tri/gran \(model hertz\)"),
    ("characteristicVelocity missing", "in.materials", {"vcfix": "variable nothing equal 0"},
     r"Could not locate a fix/property storing value\(s\) for characteristicVelocity as requested by pair tri/gran \(model hooke\)"),
    ("characteristicVelocity 0", "in.materials", {"vcfix": "fix p5 all property/global characteristicVelocity scalar 0"},
     r"pair tri/gran \(model hooke\): characteristicVelocity must be > 0, got 0"),
    ("coefficientRestitution 1.5", "in.materials", {"e": 1.5},
     r"pair tri/gran: material of types 1 and 1: coefficientRestitution must be in \(0, 1\], got 1\.5"),
    ("poissonsRatio 0.7", "in.materials", {"nu": 0.7},
     r"pair tri/gran \(model hooke\): poissonsRatio of type 1 must be in \[0, 0\.5\], got 0\.7"),
    ("youngsModulus -1", "in.materials", {"Y": -1, "wall": 1},
     r"fix tri/wall \(model hooke\): youngsModulus of type 1 must be > 0, got -1"),
    ("epsilon auto without characteristic velocity", "in.materials",
     {"eps": "epsilon auto", "modelargs": "model hooke/stiffness", "vcfix": "variable nothing equal 0"},
     r"Fix tri/particles: 'epsilon auto' needs a characteristic velocity, and the material of pair tri/gran has none"),
    ("epsilon word", "in.materials", {"eps": "epsilon thin"},
     r"Fix tri/particles: 'epsilon' expects a number \(m\) or 'auto', got 'thin'"),
    ("check_timestep word", "in.materials", {"tpargs": "check_timestep sometimes"},
     r"Fix tri/particles: 'check_timestep' expects setup, off or a positive number of steps, got 'sometimes'"),
    ("check_timestep 0", "in.materials", {"tpargs": "check_timestep 0"},
     r"'check_timestep' expects setup, off or a positive number of steps, got '0'"),
    ("no epsilon and no contact style", "in.bad_particles",
     {"args": "shape r random ntri 20 size 0.004 seed 1 density 2500"},
     r"Fix tri/particles: 'epsilon' is required here: 'epsilon auto' \(the default\) sizes the soft layer"),
]


def test_materials_bad_input(ctx):
    make_meshes(ctx.work)
    run_deck(ctx, "in.materials", {})  # the deck with nothing swapped runs
    failures = []
    for name, deck, variables, pattern in BAD:
        try:
            print(f"{name}: {expect_error(ctx, deck, variables, pattern)}")
        except Failure as e:
            failures.append(f"{name}: {e}")
    check(not failures, "\n".join(failures))
