"""One contact case replayed many ways, which must give the same trajectory bit for bit: the
rock cluster (rock-rock and rock-wall contacts, tangential history) with 1 and 2 OpenMP
threads over pairs and over triangles, from a restart in a new process, and on 1 and 2 MPI
ranks together with a colliding pair across the subdomain boundary."""
import os

from decklib import (FLIGHT_PERIODIC, HERE, check, first_frame, last_frame, make_contact_meshes,
                     run_deck, thermo_rows)

CLUSTER_OUT = "cluster_{}.dump"


def cluster_contacts(out):
    rows = thermo_rows(out)
    check(rows, "no thermo rows in the cluster output")
    return max(r["stats.pairs_in_contact"] for r in rows)


def test_threads(ctx):
    """The cluster with 1 and 2 OpenMP threads, parallel pairs and parallel triangles: the
    final dumps (%.17g) must be identical."""
    make_contact_meshes(ctx.work)
    dumps = {}
    for loop in ("pairs", "triangles"):
        for threads in (1, 2):
            phase = f"{loop}_t{threads}"
            _, out = run_deck(ctx, "in.contact_cluster",
                              {"phase": phase, "nsteps": 2000, "pairargs": f"parallel {loop}"},
                              env_extra={"OMP_NUM_THREADS": str(threads)})
            check(cluster_contacts(out) > 0, f"{phase}: no contacts in the cluster")
            step, dumps[phase] = last_frame(os.path.join(ctx.work, CLUSTER_OUT.format(phase)))
            check(step == 2000 and len(dumps[phase]) == 8, f"{phase}: step {step}, "
                  f"{len(dumps[phase])} atoms")
    ref = dumps["pairs_t1"]
    for phase, rows in dumps.items():
        check(set(rows) == set(ref), f"{phase}: atoms {sorted(rows)}, pairs_t1 {sorted(ref)}")
        for tag in ref:
            check(rows[tag] == ref[tag], f"atom {tag}: {phase} differs from pairs_t1:\n "
                  f"{rows[tag]}\n {ref[tag]}")


def test_threads_default_shares_a_node(ctx):
    """OMP_NUM_THREADS unset: one rank runs a thread per core it may use, and two ranks on one
    node (not bound to cores) share the node's cores instead of each starting one per core;
    set, it is obeyed. fix tri/particles says which at the first run."""
    cores = len(os.sched_getaffinity(0))
    unbound = {"OMP_NUM_THREADS": None, "OMPI_MCA_hwloc_base_binding_policy": "none"}
    cases = [(1, unbound, cores, True), (2, unbound, max(1, cores // 2), True),
             (2, {"OMP_NUM_THREADS": "3"}, 3, False)]
    for ranks, env, threads, unset in cases:
        _, out = run_deck(ctx, "in.flight_full", dict(FLIGHT_PERIODIC, px=ranks, phase="t"),
                          ranks=ranks, mpirun=True, env_extra=env)
        line = [l for l in out.splitlines() if l.startswith("tri/particles:") and "MPI rank" in l]
        want = f"tri/particles: {ranks} MPI rank(s), {threads} OpenMP thread(s) each"
        check(len(line) == 1 and line[0].startswith(want) and ("unset" in line[0]) == unset,
              f"{ranks} rank(s), environment {env}: {line}, expected `{want}`")


def test_restart_contacts(ctx):
    """2N steps against N + write_restart + (new process) read_restart + N, with rock-rock
    and rock-wall contacts (tangential history) active at the restart step."""
    make_contact_meshes(ctx.work)
    n = 3500  # rock-rock and rock-wall contacts both active at step n (checked below)
    run_deck(ctx, "in.contact_cluster", {"phase": "full", "nsteps": 2 * n})
    _, out = run_deck(ctx, "in.contact_cluster_restart",
                      {"phase": "first", "nsteps": n, "thermo_every": n})
    run_deck(ctx, "in.contact_cluster_resume", {"phase": "second", "nsteps": n})
    at_n = [r for r in thermo_rows(out) if r["Step"] == n]
    check(len(at_n) == 2, f"expected two thermo rows at step {n}, got {at_n}")
    total, pairs_only = at_n[0]["stats.pairs_in_contact"], at_n[1]["stats.pairs_in_contact"]
    print(f"at the restart step: {total:g} contacts, {pairs_only:g} of them rock-rock")
    check(pairs_only > 0, "no rock-rock contact at the restart step: the test would not see "
                          "the pair history")
    check(total - pairs_only > 0, "no rock-wall contact at the restart step")
    step_a, full = last_frame(os.path.join(ctx.work, CLUSTER_OUT.format("full")))
    step_b, resumed = last_frame(os.path.join(ctx.work, CLUSTER_OUT.format("second")))
    check(step_a == step_b == 2 * n, f"last frames at steps {step_a} and {step_b}, "
                                     f"expected {2 * n}")
    check(len(full) == 8 and set(resumed) == set(full),
          f"atoms {sorted(full)} without the restart, {sorted(resumed)} after it")
    first_diff = [t for t in full if full[t] != resumed[t]]
    check(not first_diff, f"atoms {first_diff} differ after the restart, e.g. atom "
          f"{first_diff[:1]}:\n {full[first_diff[0]] if first_diff else ''}\n "
          f"{resumed[first_diff[0]] if first_diff else ''}")


def compare_columns(serial, mpi, tol, what):
    """Largest difference per column relative to the column's largest magnitude; checks tol."""
    worst = 0.0
    ncol = len(next(iter(serial.values())))
    for k in range(ncol):
        scale = max(abs(float(r[k])) for r in serial.values())
        for tag in serial:
            d = abs(float(serial[tag][k]) - float(mpi[tag][k]))
            r = d / scale if scale > 0 else d
            worst = max(worst, r)
            check(r <= tol, f"{what}: atom {tag} column {k + 1}: 1 rank {serial[tag][k]}, "
                            f"2 ranks {mpi[tag][k]} (relative {r:.3g} > {tol:g})")
    return worst


def test_ranks_contacts(ctx):
    """1 and 2 MPI ranks (processors 2 1 1, boundary x = 0): a colliding pair across the
    boundary and the cluster, bitwise equal. Pair tri/gran evaluates every pair as (lower tag,
    higher tag) whichever rank owns which atom, and each atom's pair forces are summed in the
    order of the partners' tags (wall contacts in the order of the wall triangles), so the
    split changes no sum and the final dumps (%.17g) must be identical. Chaotic collisions would
    amplify any last-bit difference (the hybrid kernel's accept/fallback decision can flip on
    one and then move a distance by up to its tolerance 1e-4 eps), so the runs are short and
    the cluster's kernel is brute force; the comparison within 1e-10 of each column's largest
    magnitude runs first, so a failure says how far apart the runs are."""
    make_contact_meshes(ctx.work)
    tol = 1e-10
    outs = {}
    for ranks in (1, 2):
        phase = "serial" if ranks == 1 else "mpi"
        run_deck(ctx, "in.contact_collide", {"px": ranks, "phase": phase}, ranks=ranks)
        with open(os.path.join(ctx.work, f"touch_{phase}.txt")) as f:
            touching = sum(1 for l in f if l.startswith("touch") and float(l.split()[1]) > 0)
        check(touching > 10, f"collide, {ranks} ranks: in contact on {touching} steps only")
        _, outs[("collide", ranks)] = last_frame(os.path.join(ctx.work, f"collide_{phase}.dump"))
        _, out = run_deck(ctx, "in.contact_cluster",
                          {"px": ranks, "phase": phase, "nsteps": 1500, "pairargs": "kernel bf"},
                          ranks=ranks)
        check(cluster_contacts(out) > 0, f"cluster, {ranks} ranks: no contacts")
        _, outs[("cluster", ranks)] = last_frame(os.path.join(ctx.work, CLUSTER_OUT.format(phase)))
    _, first = first_frame(os.path.join(ctx.work, "collide_serial.dump"))
    check(float(first[1][0]) < 0 < float(first[2][0]), "the pair does not start on both ranks")
    for what, natoms in (("collide", 2), ("cluster", 8)):
        serial, mpi = outs[(what, 1)], outs[(what, 2)]
        check(len(serial) == len(mpi) == natoms and set(serial) == set(mpi),
              f"{what}: atoms were lost")
        sides = {float(r[0]) < 0 for r in serial.values()}
        worst = compare_columns(serial, mpi, tol, what)
        different = [t for t in serial if serial[t] != mpi[t]]
        verdict = f"not bitwise (atoms {different})" if different else "bitwise equal"
        print(f"{what}: 1 vs 2 ranks {verdict}, largest relative difference {worst:.3g} "
              f"(tolerance {tol:g}); atoms on {len(sides)} sides of x = 0 at the end")
        check(not different, f"{what}: 1 and 2 ranks are not bitwise equal: atoms {different} "
                             f"differ (largest relative difference {worst:.3g}), e.g. atom "
                             f"{different[:1]}:\n {serial[different[0]] if different else ''}"
                             f"\n {mpi[different[0]] if different else ''}")


def test_threads_periodic_gas(ctx):
    """The granular-gas benchmark deck (validation/performance/pile/in.gas), 512 rocks colliding
    in a periodic box, 1 and 2 OpenMP threads: with newton off a pair across the boundary is in
    both atoms' neighbour lists (each with the other's image), two tasks that may run on two
    threads at once; their kept state must be their own. 512 rocks: enough for fix tri/nve to
    integrate on both threads, each a share of the atoms (FixTriNVE::kAtomsPerThread), and for
    pair tri/gran to list its neighbour rows on both. The final dumps (%.17g) and the counters
    of compute tri/stats averaged over the run must be identical."""
    deck = os.path.join(os.path.dirname(os.path.dirname(HERE)), "validation", "performance",
                        "pile", "in.gas")
    runs = {}
    for threads in (1, 2):
        out = os.path.join(ctx.work, f"gas_t{threads}")
        os.makedirs(out, exist_ok=True)
        run_deck(ctx, deck, {"mode": "free", "n": 8, "ntri": 20, "steps": 2000, "out": out,
                             "dump": 1}, env_extra={"OMP_NUM_THREADS": str(threads)})
        step, atoms = last_frame(os.path.join(out, "final.dump"))
        check(step == 2000 and len(atoms) == 512, f"{threads} threads: step {step}, "
              f"{len(atoms)} atoms")
        with open(os.path.join(out, "counters.txt")) as f:
            counters = [l.split() for l in f if l.strip() and not l.startswith("#")][-1][1:]
        runs[threads] = (atoms, counters)
    (ref, ref_counters), (got, got_counters) = runs[1], runs[2]
    check(float(ref_counters[1]) > 1.0, f"too few contacts in the gas: {ref_counters}")
    check(got_counters == ref_counters, f"counters (pairs checked, in contact, triangle pairs "
          f"tested, ...): 1 thread {ref_counters}, 2 threads {got_counters}")
    differ = [t for t in ref if ref[t] != got[t]]
    check(not differ, f"atoms {differ[:5]} differ between 1 and 2 threads, e.g.\n "
          f"{ref[differ[0]] if differ else ''}\n {got[differ[0]] if differ else ''}")


def test_kept_contacts_replay(ctx):
    """A pile of twelve rocks settling (in.kept_pile) in a box of static walls: many of the
    point-like contacts (face contacts are measured) carry their kept contact points
    (keep_contacts, the default) rather than measure them, particle pairs and walls.
    The run is replayed with 2 OpenMP threads, on 2 MPI ranks (the boundary x = 0 through the
    pile), and from a restart written halfway (the kept points in the file, read by a new
    process): every final dump (%.17g) must be bitwise the plain run's. With keep_contacts no
    the pile is measured every step and carries nothing."""
    make_contact_meshes(ctx.work)
    n = 15000
    finals, carried_share = {}, None

    def final(phase):
        step, atoms = last_frame(os.path.join(ctx.work, CLUSTER_OUT.format(phase)))
        check(step == 2 * n and len(atoms) == 12, f"{phase}: step {step}, {len(atoms)} atoms")
        return atoms

    _, out = run_deck(ctx, "in.kept_pile", {"phase": "full", "nsteps": 2 * n, "dump_every": n,
                                            "thermo_every": 1000})
    rows = [r for r in thermo_rows(out, ("stats", "pstats")) if r["Step"] > n]
    touching = sum(r["pstats.pairs_in_contact"] for r in rows)
    carried = sum(r["pstats.contacts_carried"] for r in rows)
    carried_share = carried / max(touching, 1)
    print(f"second half: {touching:g} particle pairs in contact, {carried:g} carried "
          f"({carried_share:.2f})")
    check(touching > 100 and carried_share > 0.25,
          f"the settled pile carried {carried:g} of {touching:g} particle contacts")
    wall_carried = sum(r["stats.contacts_carried"] - r["pstats.contacts_carried"] for r in rows)
    print(f"second half: {wall_carried:g} wall contacts carried")
    check(wall_carried > 0, f"the settled pile carried {wall_carried:g} wall contacts")
    finals["full"] = final("full")
    run_deck(ctx, "in.kept_pile", {"phase": "t2", "nsteps": 2 * n, "dump_every": n},
             env_extra={"OMP_NUM_THREADS": "2"})
    finals["2 threads"] = final("t2")
    run_deck(ctx, "in.kept_pile", {"phase": "mpi", "nsteps": 2 * n, "dump_every": n, "px": 2},
             ranks=2)
    finals["2 ranks"] = final("mpi")
    run_deck(ctx, "in.kept_pile", {"phase": "first", "nsteps": n, "dump_every": n, "write": "yes"})
    run_deck(ctx, "in.kept_pile_resume", {"phase": "second", "nsteps": n, "dump_every": n})
    finals["restart"] = final("second")
    ref = finals["full"]
    for what, atoms in finals.items():
        differ = [t for t in ref if atoms.get(t) != ref[t]]
        check(not differ, f"{what}: atoms {differ} differ from the plain run, e.g.\n "
              f"{ref[differ[0]] if differ else ''}\n {atoms.get(differ[0]) if differ else ''}")
    _, out = run_deck(ctx, "in.kept_pile", {"phase": "measured", "nsteps": 2 * n, "dump_every": n,
                                            "thermo_every": 1000, "pairargs": "keep_contacts no"})
    carried = sum(r["pstats.contacts_carried"] for r in thermo_rows(out, ("stats", "pstats")))
    check(carried == 0, f"keep_contacts no carried {carried:g} contacts")
