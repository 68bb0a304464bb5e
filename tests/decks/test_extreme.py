"""Extreme input: shapes of 1e5 triangles, particles launched at 100 m/s, particles created
inside each other and inside a wall. Each either runs correctly or stops with a message that
says what to change."""
import math
import os
import re
import time

from decklib import EPS, TAIL, TOO_LARGE, check, expect_error, fine_cube, make_contact_meshes
from decklib import open_box, run_deck, thermo_rows, write_binary_stl, write_stl


def test_extreme_shapes(ctx):
    """1e5-triangle shapes: a file one works (set-up and contacts in seconds, `cull no`
    included); a random rock finer than its soft layer stops with the limit's message; a shape
    larger than the box stops (also in test_bad_input)."""
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
            check(r["stats.pairs_in_contact"] == 1 and r["stats.contacts_after"] == 1
                  and r["stats.penetrations"] == 0,
                  f"{pairstyle}: step {r['Step']:g}: not one clean contact: {r}")
            # kn 2000 N/m, soft-layer overlap 1.5e-4 m: 0.3 N, pushing the cubes apart.
            check(math.isfinite(r["fx1"]) and -0.31 < r["fx1"] < -0.29
                  and r["fx2"] == -r["fx1"], f"{pairstyle}: step {r['Step']:g}: forces "
                  f"{r['fx1']}, {r['fx2']}")
        print(f"101568 + 48 triangles, {pairstyle}: {rows[-1]['stats.triangle_pairs_tested']:g} "
              f"triangle pairs tested per step, {rows[-1]['stats.contacts_before']:g} contacts "
              f"-> 1, fx {rows[-1]['fx1']:.4g} N; {seconds:.1f} s with set-up")
    line = expect_error(ctx, "in.bad_particles",
                        {"args": "shape r random ntri 100000 size 0.004 seed 1 " + TAIL},
                        r"shape r \(100000 triangles\) has a mean edge length of \S+ m, shorter "
                        r"than epsilon \(0\.0001 m\).*coarser mesh \(about \d+ triangles")
    print(f"ntri 100000, size 4 mm: {line}")
    line = expect_error(ctx, "in.bad_particles", {"args": TOO_LARGE},
                        r"does not fit in the simulation box")
    print(f"size 0.5 m in a 0.04 m box: {line}")


def test_extreme_motion(ctx):
    """Two cubes launched at each other at 100 m/s: with fix tri/adapt_dt they bounce (no
    intersection, no tunnelling, no NaN); without it the run stops naming the speed and dt.
    Particles created inside each other and a wall: the first step stops; the same deck with
    the particles apart runs."""
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
        check(r["stats.penetrations"] == 0, f"step {r['Step']:g}: real surfaces intersect")
        # The inner cubes (the meshes less epsilon) meet at centre distance 4 mm - 2 epsilon:
        # beyond it a face went through the soft layers.
        check(r["x2"] - r["x1"] > 0.004 - 2 * EPS, f"step {r['Step']:g}: centres "
              f"{r['x2'] - r['x1']:.6g} m apart: the cubes went into each other")
        check(r["Dt"] <= 1e-5 * (1 + 1e-12), f"step {r['Step']:g}: dt {r['Dt']} > dtmax")
    touching = [r for r in rows if r["stats.pairs_in_contact"] > 0]
    check(touching, "the cubes never touched")
    for r in touching:
        # 0.5 epsilon per step at 200 m/s; the reactive halving may lower it further.
        check(r["Dt"] <= 2.5e-7 * (1 + 1e-9), f"step {r['Step']:g}: dt {r['Dt']} in contact")
    deepest = min(r["dmin"] for r in touching)
    last = rows[-1]
    check(last["stats.pairs_in_contact"] == 0 and last["vx1"] < 0 < last["vx2"],
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

    write_stl(os.path.join(ctx.work, "floorbox.stl"), open_box(0.018, 0.05))
    line = expect_error(ctx, "in.extreme_overlap", {},
                        r"the run starts with intersecting surfaces \(3 particle pair\(s\), "
                        r"e\.g\. particles \d+ and \d+; 1 particle-wall contact\(s\)\).*"
                        r"at least 2 x epsilon apart")
    print(f"created inside each other and a wall: {line}")
    _, out = run_deck(ctx, "in.extreme_overlap", {"apart": 1})
    rows = thermo_rows(out)
    check(len(rows) == 3, f"the control run (particles apart): {len(rows)} thermo rows, "
                          "expected steps 0, 100, 200")
    check(all(r["Atoms"] == 4 and r["stats.penetrations"] == 0 for r in rows),
          "the control run (particles apart) lost atoms or intersected")
    check("ERROR" not in out and "WARNING" not in out, "the control run complained")
