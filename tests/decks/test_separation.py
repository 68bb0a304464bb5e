"""Kept separating axes, kept candidates and the tight cull change no trajectory. in.separation: 27
spinning rocks thrown into an open box (flights, rock-rock and rock-wall contacts, a forming
pile). The default contact settings (kept separating axes and gaps, the travel proof, kept
triangle-pair candidates, cull in two frames and face planes) must give bit for bit the final positions, velocities, spins, forces and orientations of

  * `separation no coherence no cull boxes` (every pair searched, world-frame boxes only: the
    plain search), for pair tri/gran and fix tri/wall alike;
  * 2 OpenMP threads, 2 MPI ranks, and N steps + write_restart + N steps from the file (the
    axes travel in LIGGGHTS's contact history and in the wall fix's per-atom array);

and the axes and candidates must do their work: body pairs proven apart (pairs_separated),
searched among kept candidates (candidates_kept), and fewer triangle pairs tested than without
them."""
import os

from decklib import check, last_frame, open_box, run_deck, thermo_rows, write_stl

STEPS = 1000            # per half: contacts with the walls and between rocks well before 2 N
STATS = ("pstats", "wstats")
PLAIN = "kernel hybrid separation no coherence no cull boxes"


def run_phase(ctx, phase, variables, ranks=1, threads=1):
    """One run of in.separation; returns (its thermo rows, {tag: dump row at its last frame})."""
    write_stl(os.path.join(ctx.work, "box.stl"), open_box(0.008, 0.025))
    values = {"mode": "full", "nsteps": 2 * STEPS, "phase": phase, "px": ranks}
    values.update(variables)
    _, out = run_deck(ctx, "in.separation", values, ranks=ranks,
                      env_extra={"OMP_NUM_THREADS": str(threads)})
    step, rows = last_frame(os.path.join(ctx.work, f"separation_{phase}.dump"))
    expected = values["nsteps"] if values["mode"] != "second" else 2 * STEPS
    check(step == expected and len(rows) == 27, f"{phase}: last frame at step {step} with "
                                                f"{len(rows)} atoms, expected {expected}, 27")
    return thermo_rows(out, stats=STATS), rows


def check_same(ref, got, what):
    diff = [t for t in ref if got.get(t) != ref[t]]
    check(not diff, f"{what} differs from the default run in atoms {diff[:5]}:\n "
                    f"{ref[diff[0]] if diff else ''}\n {got.get(diff[0]) if diff else ''}")


def total(rows, key):
    return sum(r[key] for r in rows)


def test_separation_exact(ctx):
    """Default settings against `separation no coherence no cull boxes`: bitwise equal
    trajectories, while the default proves pairs apart, reuses kept candidates and tests fewer
    triangle pairs."""
    rows, ref = run_phase(ctx, "default", {})
    plain_rows, plain = run_phase(ctx, "plain", {"contact": PLAIN})
    check_same(ref, plain, PLAIN)
    contacts = total(rows, "pstats.pairs_in_contact"), total(rows, "wstats.pairs_in_contact")
    check(contacts[0] > 0 and contacts[1] > 0,
          f"no contacts in the samples (rock-rock {contacts[0]}, rock-wall {contacts[1]})")
    separated = total(rows, "pstats.pairs_separated"), total(rows, "wstats.pairs_separated")
    check(separated[0] > 0 and separated[1] > 0, f"pairs_separated (pair, wall) {separated}")
    plain_separated = (total(plain_rows, "pstats.pairs_separated")
                       + total(plain_rows, "wstats.pairs_separated"))
    check(plain_separated == 0, f"separation no still proves {plain_separated} pairs apart")
    # Most pairs kept apart are passed over by the travel proof while the pairs are listed.
    passed = total(rows, "pstats.pairs_passed")
    check(0 < passed <= separated[0], f"pairs_passed {passed:g} of {separated[0]:g} separated")
    plain_passed = total(plain_rows, "pstats.pairs_passed") + total(plain_rows, "wstats.pairs_passed")
    check(plain_passed == 0, f"separation no still passes over {plain_passed} pairs")
    kept = total(rows, "pstats.candidates_kept"), total(rows, "wstats.candidates_kept")
    check(kept[0] > 0 and kept[1] > 0, f"candidates_kept (pair, wall) {kept}")
    plain_kept = total(plain_rows, "pstats.candidates_kept") + total(plain_rows, "wstats.candidates_kept")
    check(plain_kept == 0, f"coherence no still keeps candidates for {plain_kept} pairs")
    tested = (total(rows, "pstats.triangle_pairs_tested")
              + total(rows, "wstats.triangle_pairs_tested"))
    plain_tested = (total(plain_rows, "pstats.triangle_pairs_tested")
                    + total(plain_rows, "wstats.triangle_pairs_tested"))
    check(tested < plain_tested, f"triangle pairs tested {tested} not below {plain_tested}")
    print(f"bitwise equal after {2 * STEPS} steps; pairs proven apart {separated[0]:g} "
          f"({passed:g} by the travel proof; walls "
          f"{separated[1]:g}), kept candidates {kept[0]:g} (walls {kept[1]:g}) in the samples, triangle pairs tested {tested:g} against "
          f"{plain_tested:g} without the axes")


def test_separation_invariance(ctx):
    """The default settings on 2 threads, on 2 ranks and across a restart: bitwise equal to
    one thread, one rank, one run."""
    _, ref = run_phase(ctx, "default", {})
    _, threads = run_phase(ctx, "threads", {}, threads=2)
    check_same(ref, threads, "2 OpenMP threads")
    _, ranks = run_phase(ctx, "ranks", {}, ranks=2)
    check_same(ref, ranks, "2 MPI ranks")
    run_phase(ctx, "first", {"mode": "first", "nsteps": STEPS})
    _, second = run_phase(ctx, "second", {"mode": "second", "nsteps": STEPS})
    check_same(ref, second, f"{STEPS} steps + restart + {STEPS} steps")


def test_separation_sorted(ctx):
    """LIGGGHTS sorting the atoms every 50 steps (each sort renumbers them, so the travel proof's
    per-atom sums begin a new epoch): the default settings bitwise equal to `separation no
    coherence no cull boxes` with the same sorting, while the travel proof still passes over
    pairs."""
    rows, ref = run_phase(ctx, "sorted", {"sort": 50})
    _, plain = run_phase(ctx, "sorted_plain", {"sort": 50, "contact": PLAIN})
    check_same(ref, plain, PLAIN + " (atoms sorted every 50 steps)")
    passed = total(rows, "pstats.pairs_passed")
    check(passed > 0, f"pairs_passed {passed:g} with sorted atoms")
    print(f"sorted every 50 steps: bitwise equal after {2 * STEPS} steps; {passed:g} pairs passed "
          f"over in the samples")
