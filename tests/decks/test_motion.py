"""Motion without contacts: free fall against the parabola, free flight resumed from a restart
and split over two MPI ranks, bit for bit."""
import math
import os

from decklib import FLIGHT_PERIODIC, check, first_frame, last_frame, run_deck


def test_freefall(ctx):
    run_deck(ctx, "in.freefall")
    step, rows = last_frame(os.path.join(ctx.work, "freefall.dump"))
    check(step == 10000, f"last frame at step {step}")
    check(set(rows) == {1}, f"atoms {sorted(rows)} in the last frame, expected atom 1")
    f = [float(v) for v in rows[1]]
    t = step * 1e-5
    x0, v0, g = (0.001, -0.002, 0.03), (0.1, -0.05, 0.2), (0.0, 0.0, -9.81)
    for k in range(3):
        exact = x0[k] + v0[k] * t + 0.5 * g[k] * t * t
        check(abs(f[k] - exact) < 1e-12, f"x[{k}] = {f[k]!r}, parabola gives {exact!r}")
        check(abs(f[3 + k] - (v0[k] + g[k] * t)) < 1e-12, f"v[{k}] off the analytic value")
    q = f[10:14]
    check(len(q) == 4, f"{len(f)} columns in the dump")
    check(abs(math.sqrt(sum(c * c for c in q)) - 1.0) < 1e-12, "quaternion lost its norm")
    # The particle must really spin: the orientation differs from the initial one and the
    # space-frame angular momentum is conserved (no torque) to round-off.
    _, first = first_frame(os.path.join(ctx.work, "freefall.dump"))
    q0 = [float(v) for v in first[1][10:14]]
    check(abs(sum(a * b for a, b in zip(q, q0))) < 0.999, "the particle did not rotate")
    L0 = [float(v) for v in first[1][14:17]]
    L = f[14:17]
    check(len(L0) == len(L) == 3, f"{len(f)} columns in the dump")
    normL = math.sqrt(sum(c * c for c in L0))
    check(normL > 0, "no angular momentum was set from omega")
    for k in range(3):
        check(abs(L[k] - L0[k]) < 1e-12 * normL, f"L[{k}] drifted: {L0[k]!r} -> {L[k]!r}")


def test_restart(ctx):
    run_deck(ctx, "in.flight_full", dict(FLIGHT_PERIODIC, px=1, phase="full"))
    run_deck(ctx, "in.flight_first", dict(FLIGHT_PERIODIC, px=1, phase="first"))
    run_deck(ctx, "in.flight_resume", {"phase": "second"})
    step_a, full = last_frame(os.path.join(ctx.work, "flight_full.dump"))
    step_b, resumed = last_frame(os.path.join(ctx.work, "flight_second.dump"))
    check(step_a == step_b == 4000, f"frames at steps {step_a} and {step_b}")
    check(len(full) == 15, f"{len(full)} atoms, expected 15")
    check(set(resumed) == set(full), f"atoms {sorted(resumed)} after the restart, "
                                     f"{sorted(full)} without")
    for tag in full:
        check(full[tag] == resumed[tag],
              f"atom {tag} differs after restart:\n {full[tag]}\n {resumed[tag]}")


def test_ranks(ctx):
    run_deck(ctx, "in.flight_full", dict(FLIGHT_PERIODIC, px=1, phase="serial"))
    run_deck(ctx, "in.flight_full", dict(FLIGHT_PERIODIC, px=2, phase="mpi"), ranks=2)
    _, first = first_frame(os.path.join(ctx.work, "flight_serial.dump"))
    _, serial = last_frame(os.path.join(ctx.work, "flight_serial.dump"))
    _, mpi = last_frame(os.path.join(ctx.work, "flight_mpi.dump"))
    check(len(serial) == len(mpi) == 15, "atoms were lost")
    check(set(serial) == set(mpi) == set(first), "the runs hold different atoms")
    crossed = sum(1 for t in serial if (float(first[t][0]) < 0) != (float(serial[t][0]) < 0))
    check(crossed >= 3, f"only {crossed} particles crossed the subdomain boundary x = 0")
    # Free flight involves no sums over atoms, so the split cannot change a single bit.
    for tag in serial:
        check(serial[tag] == mpi[tag], f"atom {tag}: 1 rank {serial[tag]} != 2 ranks {mpi[tag]}")
