"""The twist spring's history (contact_history.h: one twist angle per slot) kept across a
restart and across ranks: two cubes stacked on a plane, the top one spun about the common
normal (in.twist_stack). The pair contact (pair tri/gran) and the wall contact (fix tri/wall)
both twist; only twisting friction brakes the spin (the stack is centred on the z axis, so
sliding friction at the contact points has no lever about z)."""
import os

from decklib import check, first_frame, last_frame, make_contact_meshes, run_deck

N = 800          # steps to the restart: the top cube is still slipping (twist spring capped)
SPIN0 = 20.0     # rad/s, the top cube's initial spin


def stack_frames(ctx, phase):
    return os.path.join(ctx.work, f"twist_{phase}.dump")


def check_braked(rows, what):
    """Twisting friction acted: the top cube (atom 2) lost a quarter of its spin at least, and
    the bottom one was dragged round at some time (checked at the end: it is no longer at
    exactly zero)."""
    top, bottom = float(rows[2][8]), float(rows[1][8])
    check(top < 0.75 * SPIN0, f"{what}: the top cube still spins at {top:g} rad/s "
                              f"(started at {SPIN0:g}): no twisting friction")
    check(bottom != 0.0, f"{what}: the bottom cube never turned")


def test_twist_restart(ctx):
    """2N steps against N + write_restart + (new process) read_restart + N: the twist angles
    of both face contacts (pair and wall) are in the history at the restart step; the final
    dumps (%.17g) must be identical."""
    make_contact_meshes(ctx.work)
    run_deck(ctx, "in.twist_stack", {"phase": "full", "nsteps": 2 * N, "dump_every": N})
    run_deck(ctx, "in.twist_stack_restart", {"phase": "first", "nsteps": N, "dump_every": N})
    run_deck(ctx, "in.twist_stack_resume", {"phase": "second", "nsteps": N, "dump_every": N})
    step_n, at_n = last_frame(stack_frames(ctx, "first"))
    check(step_n == N, f"first half ends at step {step_n}, expected {N}")
    check_braked(at_n, f"at the restart step {N}")
    top = float(at_n[2][8])
    print(f"at the restart step: top cube spins at {top:.6g} rad/s (from {SPIN0:g})")
    step_a, full = last_frame(stack_frames(ctx, "full"))
    step_b, resumed = last_frame(stack_frames(ctx, "second"))
    check(step_a == step_b == 2 * N, f"last frames at steps {step_a} and {step_b}, "
                                     f"expected {2 * N}")
    check(set(full) == set(resumed) == {1, 2}, f"atoms {sorted(full)}, {sorted(resumed)}")
    differ = [t for t in full if full[t] != resumed[t]]
    check(not differ, f"atoms {differ} differ after the restart, e.g. atom {differ[:1]}:\n "
          f"{full[differ[0]] if differ else ''}\n {resumed[differ[0]] if differ else ''}")


def test_twist_ranks(ctx):
    """1 and 2 MPI ranks (processors 1 1 2: the cubes on either side of z = 0, their contact
    on the boundary): the final dumps (%.17g) must be identical."""
    make_contact_meshes(ctx.work)
    frames = {}
    for ranks in (1, 2):
        phase = f"ranks{ranks}"
        run_deck(ctx, "in.twist_stack", {"pz": ranks, "phase": phase, "nsteps": 2 * N,
                                         "dump_every": N}, ranks=ranks)
        _, frames[ranks] = last_frame(stack_frames(ctx, phase))
        check_braked(frames[ranks], f"{ranks} ranks")
    _, first = first_frame(stack_frames(ctx, "ranks2"))
    check(float(first[1][2]) < 0 < float(first[2][2]), "the cubes do not start on both sides "
                                                       "of the subdomain boundary z = 0")
    serial, mpi = frames[1], frames[2]
    check(set(serial) == set(mpi) == {1, 2}, f"atoms {sorted(serial)}, {sorted(mpi)}")
    differ = [t for t in serial if serial[t] != mpi[t]]
    print(f"1 vs 2 ranks: {'bitwise equal' if not differ else 'atoms %s differ' % differ}")
    check(not differ, f"1 and 2 ranks differ: atom {differ[:1]}:\n "
          f"{serial[differ[0]] if differ else ''}\n {mpi[differ[0]] if differ else ''}")
