"""Contacts of one evaluation against hand-computed forces and torques (pair tri/gran, fix
tri/wall); compute tri/stats with fix tri/adapt_dt's rule on two approaching cubes, and the
limits of fix tri/adapt_dt (its rate-limited log, dt stuck at dtmin while real surfaces
intersect)."""
import os
import re

from decklib import CUBE_SIDE, EPS, Failure, check, expect_error, last_frame, make_contact_meshes
from decklib import run_deck, thermo_rows

DENSITY = 2500.0
# Material of in.contact_pair / in.contact_wall
MAT = {"kn": 2000.0, "kt": 1000.0, "gamman": 20.0, "gammat": 10.0, "mu": 0.5}


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def test_contact_forces(ctx):
    """Forces and torques of one evaluation (run 0) against hand-computed values."""
    make_contact_meshes(ctx.work)
    h = CUBE_SIDE / 2                   # half side of the mesh as read (ASCII STL: doubles)
    mass = DENSITY * (2 * h) ** 3
    kn, kt, gn, gt, mu = (MAT[k] for k in ("kn", "kt", "gamman", "gammat", "mu"))
    dt = 1e-5
    # bf: exact geometry, so 1e-12 of the normal force. hybrid: distances within its
    # documented tolerance 1e-4 * epsilon (particle_contacts.h), so the normal force within
    # kn * 1e-8 N; the normal is the direction between closest points 1e-4 m apart, each
    # within 1e-8 m, so lateral force and torque within 1e-4 of F (and F * h).
    rel = {"bf": 1e-12, "hybrid": 1e-4}

    # gap: between the meshes as given (< 0: they overlap). With the layer inside the meshes
    # are the contact surfaces (overlap = -gap); with it outside they touch 2 EPS apart.
    def pair_case(name, kernel, gap, yb=0.0, vxa=0.0, vxb=0.0, vzb=0.0, gamman=0.0, gammat=0.0,
                  layer="inside"):
        xa, xb = -(h + gap / 2), h + gap / 2
        v = dict(MAT, xa=repr(xa), xb=repr(xb), yb=repr(yb), vxa=vxa, vxb=vxb, vzb=vzb,
                 gamman=gamman, gammat=gammat, pairargs=f"kernel {kernel}", layer=layer)
        run_deck(ctx, "in.contact_pair", v)
        step, rows = last_frame(os.path.join(ctx.work, "contact.dump"))
        check(step == 0 and set(rows) == {1, 2},
              f"{name}: frame at step {step} with atoms {sorted(rows)}")
        a, b = ([float(x) for x in rows[t]] for t in (1, 2))
        check(len(a) == len(b) == 10, f"{name}: {len(a)} columns, expected 10")
        check(abs(a[9] - mass) <= 1e-12 * mass, f"{name}: mass {a[9]!r}, cube gives {mass!r}")
        fa, fb, ta, tb = a[3:6], b[3:6], a[6:9], b[6:9]
        # Expected (n = +x from a to b): F_n = kn overlap - gamman m_eff v_n on b, friction
        # from b's sliding along z: history spring kt v dt plus damping, capped by mu F_n.
        overlap = (0.0 if layer == "inside" else 2 * EPS) - gap
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

    # A wall's mesh is its contact surface; its own `epsilon` puts a layer outside it; with
    # the particles' layer outside, a wall without one takes the particles' epsilon.
    def wall_case(name, kernel, gap, eps_wall=None, vz=0.0, gamman=0.0, layer="inside"):
        zc = h + gap
        args = f"kernel {kernel}" + (f" epsilon {eps_wall!r}" if eps_wall else "")
        run_deck(ctx, "in.contact_wall", dict(MAT, zc=repr(zc), vz=vz, gamman=gamman,
                                               wallargs=args, layer=layer))
        step, rows = last_frame(os.path.join(ctx.work, "contact.dump"))
        check(step == 0 and set(rows) == {1}, f"{name}: frame at step {step} with atoms "
                                              f"{sorted(rows)}")
        a = [float(x) for x in rows[1]]
        check(len(a) == 10, f"{name}: {len(a)} columns, expected 10")
        f, t = a[3:6], a[6:9]
        if layer == "inside":
            overlap = (eps_wall or 0.0) - gap
        else:
            overlap = EPS + (eps_wall or EPS) - gap
        # n from the particle to the wall is -z; v_n = (v_wall - v) . n = vz; m_eff = m.
        fz = kn * overlap - gamman * mass * vz if overlap > 0 else 0.0
        scale = max(fz, 1e-300)
        tol = rel[kernel] * scale
        check(abs(f[2] - fz) <= tol and abs(f[0]) <= tol and abs(f[1]) <= tol,
              f"{name}: wall force {f}, hand-computed (0, 0, {fz!r}) (tolerance {tol:g} N)")
        check(all(abs(c) <= tol * h for c in t), f"{name}: torque {t} on a centred cube")
        print(f"{name}: f {f} (hand fz {fz!r}), torque {t}")

    pair_case("pair_rest_bf", "bf", gap=-1e-4)
    pair_case("pair_rest_hybrid", "hybrid", gap=-1e-4)
    pair_case("pair_touching_bf", "bf", gap=0.0)
    pair_case("pair_apart_bf", "bf", gap=0.5e-4)
    pair_case("pair_approach_damped_bf", "bf", gap=-1e-4, vxa=0.1, vxb=-0.1, gamman=gn)
    pair_case("pair_offset_bf", "bf", gap=-1e-4, yb=0.001)
    pair_case("pair_sliding_bf", "bf", gap=-0.8e-4, vzb=1.0, gamman=gn, gammat=gt)
    pair_case("pair_sliding_coulomb_bf", "bf", gap=-1e-4, yb=0.0005, vzb=20.0, gammat=gt)
    pair_case("pair_rest_layer_outside_bf", "bf", gap=1e-4, layer="outside")
    pair_case("pair_apart_layer_outside_bf", "bf", gap=2.5e-4, layer="outside")
    wall_case("wall_eps_bf", "bf", gap=0.0, eps_wall=5e-5)
    wall_case("wall_default_eps_bf", "bf", gap=-1e-4)
    wall_case("wall_approach_hybrid", "hybrid", gap=-0.5e-4, vz=-0.1, gamman=gn)
    wall_case("wall_apart_bf", "bf", gap=1e-5)
    wall_case("wall_layer_outside_bf", "bf", gap=1e-4, layer="outside")


ADAPT_LINE = re.compile(r"tri/adapt_dt: step (\d+): dt (\S+) -> (\S+) \((.*)\)")


def test_elastic_energy(ctx):
    """compute tri/stats' elastic_energy is the contacts' potential energy: two spinning rocks
    colliding without damping or friction (in.contact_energy) keep the kinetic energy (compute
    ke + compute tri/erotate) plus it constant at every step, while it takes a quarter of the
    energy at the deepest point. On 2 ranks the pair straddles the subdomain boundary and is
    evaluated on both (newton off): each counts half, so the sums agree."""
    energies = {}
    for ranks in (1, 2):
        phase = f"ranks{ranks}"
        run_deck(ctx, "in.contact_energy", {"px": ranks, "phase": phase}, ranks=ranks)
        with open(os.path.join(ctx.work, f"energy_{phase}.txt")) as f:
            rows = [[float(x) for x in l.split()[1:]] for l in f if l.startswith("energy")]
        touching = [r for r in rows if r[2] > 0]
        check(len(touching) > 100, f"{ranks} ranks: in contact on {len(touching)} steps only")
        check(rows[-1][2] == 0, f"{ranks} ranks: the rocks did not separate")
        e0 = rows[0][0] + rows[0][1]
        peak = max(r[1] for r in rows) / e0
        drift = max(abs(r[0] + r[1] - e0) for r in rows) / e0
        print(f"{ranks} rank(s): elastic energy up to {peak:.3f} of the total, "
              f"kinetic + elastic within {drift:.2e} of the start")
        check(peak > 0.1, f"{ranks} ranks: the elastic energy peaks at {peak:.3g} of the total")
        check(drift < 1e-4, f"{ranks} ranks: kinetic + elastic energy moved by {drift:.3g}")
        energies[ranks] = [r[1] for r in rows]
    worst = max(abs(a - b) for a, b in zip(energies[1], energies[2])) / max(energies[1])
    check(worst < 1e-12, f"1 and 2 ranks: elastic energies differ by {worst:.3g} of the peak")


def test_stats_and_adapt_dt(ctx):
    """compute tri/stats in thermo and fix tri/adapt_dt's rule on two approaching cubes. Thermo
    every step, so that every halving is checked against the closest distance of its step."""
    make_contact_meshes(ctx.work)
    dtmax, dtmin, fraction = 2e-6, 2.5e-7, 0.2
    _, out = run_deck(ctx, "in.contact_adapt")
    rows = thermo_rows(out)
    check(len(rows) > 100, f"{len(rows)} thermo rows")
    for r in rows:
        check(r["stats.contacts_after"] <= r["stats.contacts_before"],
              f"step {r['Step']:g}: {r['stats.contacts_after']:g} contacts after reduction > "
              f"{r['stats.contacts_before']:g} before")
        check(dtmin * (1 - 1e-12) <= r["adt[1]"] <= dtmax * (1 + 1e-12),
              f"step {r['Step']:g}: dt {r['adt[1]']!r} outside [dtmin, dtmax]")
    touching = [r for r in rows if r["stats.pairs_in_contact"] > 0]
    check(touching, "the cubes never touched")
    # a pair in contact is measured (triangle pairs tested) or its kept points carried
    check(all(r["stats.pairs_checked"] > 0 and
              (r["stats.triangle_pairs_tested"] > 0 or r["stats.contacts_carried"] > 0)
              for r in touching),
          "pairs in contact without particle pairs checked, triangle pairs tested or contacts "
          "carried")
    check(max(r["stats.contacts_before"] for r in touching)
          > max(r["stats.contacts_after"] for r in touching) == 1,
          "two touching faces did not reduce to one contact point")
    check(min(r["dmin"] for r in touching) < fraction * EPS,
          "the cubes never came closer than 0.2 epsilon")
    check(rows[-1]["stats.pairs_in_contact"] == 0, "the cubes did not separate")
    lines = ADAPT_LINE.findall(out)
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
            check(r is not None, f"step {step}: halved, but thermo has no row at that step")
            check(r["dmin"] < fraction * EPS,
                  f"step {step}: halved with the closest distance {r['dmin']}")
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
    print(f"{halvings} halvings, {growths} growths (each halving checked against its thermo "
          f"row); closest distance {min(r['dmin'] for r in touching):.4g} m; contacts "
          f"before/after reduction up to {max(r['stats.contacts_before'] for r in touching):g}/"
          f"{max(r['stats.contacts_after'] for r in touching):g}")


ADAPT_SUMMARY = re.compile(r"tri/adapt_dt: steps (\d+)-(\d+): (\d+) more changes not listed "
                           r"\((\d+) halvings, (\d+) growths, (\d+) approach bounds\)")


def write_cube12(path, side=0.004):
    """A closed, outward cube of side `side` centred at 0: 12 triangles, %.9g coordinates."""
    h = 0.5 * side
    v = [(sx * h, sy * h, sz * h) for sz in (-1, 1) for sy in (-1, 1) for sx in (-1, 1)]
    faces = [(0, 2, 3), (0, 3, 1), (4, 5, 7), (4, 7, 6), (0, 1, 5), (0, 5, 4),
             (2, 6, 7), (2, 7, 3), (0, 4, 6), (0, 6, 2), (1, 3, 7), (1, 7, 5)]
    with open(path, "w") as f:
        f.write("solid cube\n")
        for t in faces:
            f.write(" facet normal 0 0 0\n  outer loop\n")
            for i in t:
                f.write("   vertex %.9g %.9g %.9g\n" % v[i])
            f.write("  endloop\n endfacet\n")
        f.write("endsolid cube\n")


def test_adapt_dt_limits(ctx):
    """fix tri/adapt_dt's limits: (1) its log is rate-limited, at most 10 lines of changes per
    window of `log N` steps and one summary line for the rest, which together account for every
    change that `log all` lists; (2) the first intersection of real surfaces in a run is a
    WARNING, once; sitting at dtmin while they intersect (two soft cubes driven 12 times through
    their soft layers) stops with an error naming the pair, the depth and the remedy."""
    write_cube12(os.path.join(ctx.work, "cube.stl"))

    # (1) The same run with every change listed and with a 200-step window.
    _, out_all = run_deck(ctx, "in.contact_adapt", {"adtlog": "all"})
    _, out_lim = run_deck(ctx, "in.contact_adapt", {"adtlog": 200})
    every = ADAPT_LINE.findall(out_all)
    listed = ADAPT_LINE.findall(out_lim)
    summaries = ADAPT_SUMMARY.findall(out_lim)
    quiet = sum(int(s[2]) for s in summaries)
    check(len(every) > 10, f"only {len(every)} changes with 'log all': nothing to limit")
    check(summaries, "no summary line with 'log 200'")
    check(listed, "'log 200' lists no change")
    check(len(listed) + quiet == len(every), f"'log 200' lists {len(listed)} changes and sums "
                                             f"up {quiet}, 'log all' lists {len(every)}")
    for s in summaries:
        check(int(s[2]) == int(s[3]) + int(s[4]) + int(s[5]),
              f"summary {s}: the counts do not add up")
    # Per window of 200 steps (windows start at a change), at most 10 lines.
    count, start = 0, None
    for step, *_ in listed:
        step = int(step)
        if start is None or step >= start + 200:
            start, count = step, 0
        count += 1
        check(count <= 10, f"more than 10 lines in the window starting at step {start}")
    print(f"log all: {len(every)} changes; log 200: {len(listed)} lines + {len(summaries)} "
          f"summaries of {quiet} more")

    # (2) A deep bounce is not stuck: cubes (kn 2000 N/m, 8e-5 kg effective, contact time
    # 0.63 ms) meeting at 2 x 1.5 m/s, which a linear spring stops at 0.6 mm of overlap, 3 x
    # the combined layer of 0.2 mm, with dt pinned at dtmin = dtmax = 1e-6 s. The real surfaces
    # intersect for hundreds of steps (the first-intersection WARNING, once), the contact force
    # pushes them apart through the intersection, and the run ends without an error.
    code, out = run_deck(ctx, "in.contact_adapt", {"vx": 1.5, "dtmax": 1e-6, "dtmin": 1e-6,
                                                   "adtlog": "all", "nsteps": 1500})
    warnings = re.findall(r"WARNING: tri/particles: step \d+: real surfaces intersect for the "
                          r"first time in this run \(1 interaction\(s\), e\.g\. particles 1 and "
                          r"2; deepest overlap", out)
    check(len(warnings) == 1, f"{len(warnings)} first-intersection warnings, expected 1")
    rows = thermo_rows(out)
    last = rows[-1]
    check(last["stats.pairs_in_contact"] == 0,
          "the cubes of the deep bounce are still in contact at the end")
    print(f"deep bounce at dtmin: {len(rows)} rows, no error, apart at the end")

    # (3) Cubes pressed together by 1 N each, critically damped (gamman 1e4 1/s): they settle
    # at the overlap F / kn = 0.5 mm, 2.5 x the combined layer, so the real surfaces intersect
    # 0.3 mm deep and stay so. dt pinned at dtmin = dtmax: once they have intersected for two
    # contact times (1257 steps), the run stops with an error naming the pair, the depth and
    # the remedy.
    want = (r"Fix tri/adapt_dt: step \d+: dt has been at dtmin \(1e-06 s\) for (\d+) steps "
            r"\(\S+ s, two contact times \S+ s: longer than any bounce\) while real surfaces "
            r"intersect \(1 interaction\(s\), e\.g\. particles 1 and 2; deepest overlap \S+ m = "
            r"(\S+) x the combined soft layer 2 epsilon\): the contact force cannot push them "
            r"apart at this stiffness; use a stiffer kn, a wider epsilon, or a lower dtmin")
    line = expect_error(ctx, "in.contact_adapt", {"vx": 0.0, "press": 1.0, "gn": 1e4,
                                                  "dtmax": 1e-6, "dtmin": 1e-6, "adtlog": "all"},
                        want)
    m = re.search(want, line)
    steps, layers = int(m.group(1)), float(m.group(2))
    check(1257 <= steps <= 1258, f"stopped after {steps} steps, not after two contact times")
    check(2.3 < layers < 2.7, f"deepest overlap {layers} layers, expected about 2.5")
    print(line)

    # (4) A bad log window.
    expect_error(ctx, "in.contact_adapt", {"adtlog": 2.5},
                 re.escape("Fix tri/adapt_dt: 'log' expects a number of steps or 'all', got "
                           "'2.5'"))
