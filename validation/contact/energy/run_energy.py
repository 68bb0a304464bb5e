#!/usr/bin/python3
"""Energy conservation of tumbling rocks without damping or friction (issue 4, case 4).

Runs in.energy (32 rocks in a closed box of mesh/surface walls, 1e5 steps) for the default
contact reduction and for the two others, plus a time-step check, and the one-rock reproducer
in.single; writes energy.png next to this script and prints the tables of README.md.

  /usr/bin/python3 validation/contact/energy/run_energy.py [--exe PATH] [--out DIR]

Energy is sampled every 10 steps from a dump; E = E_trans + E_rot with E_rot = 1/2 omega . L
(L from f_shapes[6..8]). The elastic energy of the soft layers is not available from the styles, so
the drift is measured at the samples without any contact (compute tri/stats, column 2 = 0),
where the stored elastic energy is exactly zero.
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "validation", "meshes"))
sys.path.insert(0, os.path.join(ROOT, "validation"))
import meshgen  # noqa: E402
import valtools  # noqa: E402

TARGET = 0.01  # max relative drift of the total energy
KN = 2000.0
EPS = 1e-4

# (label, reduction, dt, steps, every)
CASES = [
    ("clusters (default)", "clusters", 2e-6, 100000, 10),
    ("clusters, dt/2", "clusters", 1e-6, 200000, 20),
    ("paper", "paper", 2e-6, 100000, 10),
    ("none", "none", 2e-6, 100000, 10),
]


def run(exe, deck, variables, log):
    return " ".join(valtools.run_deck(exe, deck, variables, HERE, log, exit_on_error=True))


def read_energy_dump(path):
    """Per frame: step, E_trans, E_rot (J) and the masses of the first frame, from the dump
    written by in.energy (id mass vx vy vz omegax omegay omegaz Lx Ly Lz)."""
    steps, rows = [], []
    with open(path) as f:
        lines = f.read().split("\n")
    k = 0
    while k < len(lines) and lines[k].startswith("ITEM: TIMESTEP"):
        steps.append(int(lines[k + 1]))
        n = int(lines[k + 3])
        rows.append(lines[k + 9:k + 9 + n])
        k += 9 + n
    data = np.array([[float(x) for x in l.split()] for frame in rows for l in frame])
    data = data.reshape(len(steps), -1, data.shape[1])
    m, v, w, L = data[:, :, 1], data[:, :, 2:5], data[:, :, 5:8], data[:, :, 8:11]
    etr = 0.5 * (m * (v * v).sum(axis=2)).sum(axis=1)
    erot = 0.5 * (w * L).sum(axis=2).sum(axis=1)
    return np.array(steps), etr, erot, m[0]


def analyse(out, dt):
    step, etr, erot, mass = read_energy_dump(os.path.join(out, "energy.dump"))
    c = np.loadtxt(os.path.join(out, "contacts.txt"), comments="#")
    # contact state per dump frame (the fix print starts one interval after step 0, when the
    # lattice has no contact yet)
    state = {int(r[0]): r for r in c}
    zero = np.zeros(c.shape[1])
    cs = np.array([state.get(int(s), zero) for s in step])
    npair = cs[:, 1]
    e = etr + erot
    free = npair == 0
    e0 = e[0]
    rel = (e - e0) / e0
    return dict(t=step * dt, etr=etr, erot=erot, e=e, free=free, rel=rel,
                drift=np.abs(rel[free]).max(), final=rel[free][-1],
                free_frac=free.mean(), max_overlap=cs[:, 3].max(), pen=int(cs[:, 4].max()),
                max_pairs=int(npair.max()), mass=mass)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", default=os.path.join(ROOT, "build-val2", "src_plugin", "driver",
                                                  "liggghts-tri"))
    ap.add_argument("--out", default="/tmp/tri_validation/energy")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    box = os.path.join(a.out, "box.stl")
    meshgen.write_stl(box, *meshgen.cube(1, 0.03), "box")

    results, commands = [], []
    for label, red, dt, steps, every in CASES:
        out = os.path.join(a.out, f"{red}_{dt:g}")
        os.makedirs(out, exist_ok=True)
        commands.append(run(a.exe, "in.energy", dict(out=out, dt=dt, steps=steps, every=every,
                                                     kn=KN, box=box, red=red),
                            os.path.join(out, "log")))
        results.append((label, red, dt, steps, analyse(out, dt)))

    # contact time from the masses (shortest: two of the lightest rocks; walls: m_eff = m)
    m = results[0][4]["mass"]
    tc_pp = np.pi * np.sqrt(0.5 * m.min() / KN)
    tc_pw = np.pi * np.sqrt(m.min() / KN)

    # the one-rock reproducer: one bounce off the floor, energy after / before - 1
    single = []
    for seed in (4, 8):
        row = []
        for red in ("clusters", "paper", "none"):
            for dt, steps in ((1e-6, 8000), (2.5e-7, 32000)):
                if red != "clusters" and dt != 1e-6:
                    continue
                log = os.path.join(a.out, f"single_{red}_{seed}_{dt:g}.log")
                run(a.exe, "in.single", dict(red=red, seed=seed, dt=dt, steps=steps, box=box),
                    log)
                with open(log) as f:
                    lines = f.read().splitlines()
                k = next(i for i, l in enumerate(lines) if l.split()[:2] == ["Step", "v_etot"]
                         or l.split()[:2] == ["Step", "etot"])
                e0, e1 = float(lines[k + 1].split()[1]), float(lines[k + 2].split()[1])
                row.append((red, dt, e1 / e0 - 1.0))
        single.append((seed, row))

    # ---- tables
    print(valtools.machine_line(cores=True))
    print(f"contact time t_c = pi sqrt(m_eff/kn): rock-rock {tc_pp:.3g} s, rock-wall "
          f"{tc_pw:.3g} s (kn = {KN:g} N/m, lightest rock {m.min():.3g} kg)")
    print()
    print("| reduction | dt (s) | t_c/dt | steps | contact-free samples | max |E-E0|/E0 "
          "| final (E-E0)/E0 | target | result |")
    print("|---|---|---|---|---|---|---|---|---|")
    for label, red, dt, steps, r in results:
        ok = "pass" if r["drift"] <= TARGET else "FAIL"
        print(f"| {label} | {dt:g} | {tc_pp / dt:.0f} | {steps} | {100 * r['free_frac']:.0f} % "
              f"| {100 * r['drift']:.3f} % | {100 * r['final']:+.3f} % | <= 1 % | {ok} |")
    print()
    # the soft layers of a contact: 2 eps between two rocks, eps against a wall (the rock's layer
    # lies inside its mesh; the wall's mesh has none)
    print("| reduction | max soft-layer overlap (m) | layers: pair 2 eps, wall eps (m) "
          "| penetrations | most pairs in contact at once |")
    print("|---|---|---|---|---|")
    for label, red, dt, steps, r in results:
        print(f"| {label} | {r['max_overlap']:.3g} | {2 * EPS:g}, {EPS:g} | {r['pen']} "
              f"| {r['max_pairs']} |")
    print()
    print("One rock, one bounce off the floor (in.single): E_after / E_before - 1")
    print()
    print("| orient seed | " + " | ".join(f"{red}, dt {dt:g}" for red, dt, _ in single[0][1])
          + " |")
    print("|---|" + "---|" * len(single[0][1]))
    for seed, row in single:
        print(f"| {seed} | " + " | ".join(f"{100 * x:+.4f} %" for _, _, x in row) + " |")
    print()
    print("commands:")
    for c in commands[:1]:
        print("  " + c)

    # ---- plot
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(12, 4.6))
    _, _, dt, _, r = results[0]
    ax[0].plot(r["t"], 1e6 * r["etr"], lw=0.6, label="translational")
    ax[0].plot(r["t"], 1e6 * r["erot"], lw=0.6, label="rotational")
    ax[0].plot(r["t"], 1e6 * r["e"], lw=0.6, color="k", label="kinetic total (all samples)")
    ax[0].plot(r["t"][r["free"]], 1e6 * r["e"][r["free"]], ".", ms=1.5, color="C3",
               label="total, contact-free samples")
    ax[0].set_xlabel("time (s)")
    ax[0].set_ylabel("energy (uJ)")
    ax[0].set_title("32 rocks, default reduction (clusters), dt = 2e-6 s")
    ax[0].legend(fontsize=8, loc="center right")
    for label, red, dt, steps, r in results:
        ax[1].plot(r["t"][r["free"]], 100 * r["rel"][r["free"]], lw=0.8, label=label)
    ax[1].axhspan(-100 * TARGET, 100 * TARGET, color="0.9", zorder=0, label="target +-1 %")
    ax[1].set_xlabel("time (s)")
    ax[1].set_ylabel("(E - E0) / E0 at contact-free samples (%)")
    ax[1].set_title("total energy drift by contact reduction")
    ax[1].legend(fontsize=8)
    fig.tight_layout()
    png = os.path.join(HERE, "energy.png")
    fig.savefig(png, dpi=110)
    print(f"plot: {png}")


if __name__ == "__main__":
    main()
