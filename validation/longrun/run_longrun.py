#!/usr/bin/env python3
"""Long run (issue 6, item 7): the full hopper of examples/hopper (n = 10: 1000 rocks of 40
triangles, the paper's size) for 1e5 steps of 2e-5 s (2 s simulated), with

  * every `--every` steps: time, atoms, particles discharged, translational kinetic energy
    (compute ke), rotational kinetic energy (compute tri/erotate), gravitational potential
    energy sum m g (z - z_floor) and their total, into energy.txt;
  * checks: exit status 0, the atom count constant (the deck has `thermo_modify lost error`,
    and every thermo line and energy row is read), no nan/inf anywhere;
  * peak memory (maximum resident set of the process, /usr/bin/time -v; LIGGGHTS's own
    "Memory usage per processor"), wall time and ms per step;
  * bytes per particle: the peak resident set less that of the same deck with n = 2 (8 rocks,
    --baseline-steps steps: the program, its libraries and LIGGGHTS's fixed arrays), divided
    by the difference in particles (--baseline-n 0 skips it).

Raw output goes to --out (default /tmp/longrun, never into the repository): screen.txt,
energy.txt, discharge.txt, results.json. The figure (energy.png, here) comes from
plot_longrun.py, which needs matplotlib: Debian's /usr/bin/python3.

  nice python3 validation/longrun/run_longrun.py [--exe build/src_plugin/driver/liggghts-tri] \
      [--steps 100000] [--n 10] [--ntri 40] [--threads 2] [--every 1000] [--out /tmp/longrun] \
      [--baseline-n 2] [--baseline-steps 2000]
  /usr/bin/python3 validation/longrun/plot_longrun.py [--out /tmp/longrun]

Standard library only. One rank and OpenMP threads (`parallel pairs`, bitwise the same as one
thread), so that /usr/bin/time measures the one process that holds all particles.
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.abspath(os.path.join(HERE, "..", ".."))
HOPPER = os.path.join(REPO, "examples", "hopper")
DT = 2e-5          # in.hopper's time step (s)
G = 9.81           # in.hopper's fix gravity (m/s^2)
Z_FLOOR = -0.08    # the tray's floor (make_hopper.py FLOOR_Z): potential energy reference

sys.path.insert(0, os.path.join(REPO, "validation"))
import valtools  # noqa: E402

ENERGY_COLUMNS = ["step", "time", "atoms", "discharged", "ke_trans", "ke_rot", "pe", "total"]


def make_deck(out, every):
    """in.hopper as it is, plus the energy output, inserted before its run command."""
    with open(os.path.join(HOPPER, "in.hopper")) as f:
        lines = f.read().splitlines()
    runs = [k for k, l in enumerate(lines) if re.match(r"\s*run\s", l)]
    if len(runs) != 1:
        sys.exit(f"expected one run command in in.hopper, found {len(runs)}")
    extra = [
        "compute ket all ke",
        "compute erot all tri/erotate",
        "variable step equal step",
        "variable natoms equal atoms",
        "variable ekt equal c_ket",
        "variable ekr equal c_erot",
        f"variable pe equal {G}*mass(all)*(xcm(all,z)-({Z_FLOOR}))",
        "variable etot equal c_ket+c_erot+v_pe",
        f'fix energy all print {every} "${{step}} ${{t}} ${{natoms}} ${{nout}} ${{ekt}} '
        f'${{ekr}} ${{pe}} ${{etot}}" file energy.txt screen no title "# '
        + " ".join(ENERGY_COLUMNS) + ' (J; pe = sum m g (z - z_floor))"',
        "thermo_modify format float %.10g",
    ]
    lines[runs[0]:runs[0]] = extra
    path = os.path.join(out, "in.hopper_longrun")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return path


def parse_time_v(text):
    """Maximum resident set (kB) and elapsed seconds from /usr/bin/time -v's report."""
    rss = wall = None
    for line in text.splitlines():
        line = line.strip()
        if line.startswith("Maximum resident set size"):
            rss = int(line.split(":")[1])
        elif line.startswith("Elapsed (wall clock) time"):
            parts = [float(p) for p in line.rsplit(" ", 1)[1].split(":")]
            wall = sum(p * 60 ** (len(parts) - 1 - k) for k, p in enumerate(parts))
    return rss, wall


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", default=valtools.default_exe())
    ap.add_argument("--steps", type=int, default=100000)
    ap.add_argument("--n", type=int, default=10)
    ap.add_argument("--ntri", type=int, default=40)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--every", type=int, default=1000)
    ap.add_argument("--out", default="/tmp/longrun")
    ap.add_argument("--baseline-n", type=int, default=2)
    ap.add_argument("--baseline-steps", type=int, default=2000)
    a = ap.parse_args()
    os.makedirs(os.path.join(a.out, "post"), exist_ok=True)
    for name in ("energy.txt", "results.json"):
        if os.path.exists(os.path.join(a.out, name)):
            os.remove(os.path.join(a.out, name))
    deck = make_deck(a.out, a.every)
    natoms = a.n ** 3
    variables = {"dir": HOPPER, "n": a.n, "ntri": a.ntri, "tend": repr(a.steps * DT),
                 "vtk": 0, "out": "post"}
    cmd = ["/usr/bin/time", "-v", "-o", "time.txt"] + valtools.deck_command(a.exe, deck, variables)
    print(valtools.machine_line(cores=True).replace("OMP_NUM_THREADS=1",
                                                    f"OMP_NUM_THREADS={a.threads}"))
    print("command (in %s): %s" % (a.out, " ".join(cmd)), flush=True)
    start = time.time()
    with open(os.path.join(a.out, "screen.txt"), "w") as screen:
        p = subprocess.run(cmd, cwd=a.out, env=valtools.run_env(a.threads), stdout=screen,
                           stderr=subprocess.STDOUT)
    elapsed = time.time() - start

    with open(os.path.join(a.out, "screen.txt"), errors="replace") as f:
        out = f.read()
    with open(os.path.join(a.out, "time.txt")) as f:
        rss_kb, wall = parse_time_v(f.read())
    failures = []
    if p.returncode != 0:
        failures.append(f"exit status {p.returncode} (see {a.out}/screen.txt)")
    if "ERROR" in out:
        failures.append("ERROR in the output")
    if re.search(r"\b(nan|inf)\b", out, re.IGNORECASE):
        failures.append("nan or inf in the output")
    energy = valtools.read_rows(os.path.join(a.out, "energy.txt"))
    if any(not math.isfinite(v) for r in energy for v in r):
        failures.append("non-finite energy")
    thermo_atoms = [int(l.split()[2]) for l in out.splitlines()
                    if len(l.split()) == 12 and l.split()[0].isdigit()]
    if not thermo_atoms or set(thermo_atoms) != {natoms} or \
            {int(r[2]) for r in energy} != {natoms}:
        failures.append(f"atom count not constant at {natoms}")
    if not energy or int(energy[-1][0]) != a.steps:
        failures.append("the run did not reach its last step")

    loop = re.search(r"Loop time of ([\d.eE+-]+) on (\d+) procs for (\d+) steps", out)
    mem = re.search(r"Memory usage per processor = ([\d.]+) Mbytes", out)
    loop_s = float(loop.group(1)) if loop else None
    res = {
        "machine": valtools.machine_line(cores=True),
        "command": cmd, "threads": a.threads, "ranks": 1, "n": a.n, "ntri": a.ntri,
        "particles": natoms, "steps": a.steps, "dt": DT,
        "exit_status": p.returncode, "failures": failures,
        "wall_s": wall if wall is not None else elapsed, "loop_s": loop_s,
        "ms_per_step": 1e3 * loop_s / a.steps if loop_s else None,
        "max_rss_kB": rss_kb, "liggghts_memory_MB": float(mem.group(1)) if mem else None,
        "energy_columns": ENERGY_COLUMNS, "energy": energy,
        "lost_atoms": natoms - min(thermo_atoms) if thermo_atoms else None,
    }
    if energy:
        e0, e1 = energy[0], energy[-1]
        res["energy_budget"] = {
            "pe_start": e0[6], "pe_end": e1[6], "ke_end": e1[4] + e1[5],
            "total_start": e0[7], "total_end": e1[7],
            # Nothing else stores energy at the end but the contact springs, whose energy is
            # not counted here (at rest: the pile's weight on stiff springs, small).
            "dissipated": e0[7] - e1[7],
            "largest_rise_of_total": max(
                (energy[k + 1][7] - energy[k][7] for k in range(len(energy) - 1)), default=0.0),
            "discharged": e1[3],
        }
    if a.baseline_n > 0:
        base = os.path.join(a.out, "baseline")
        bcmd = [sys.executable, os.path.abspath(__file__), "--exe", a.exe, "--n", str(a.baseline_n),
                "--ntri", str(a.ntri), "--steps", str(a.baseline_steps), "--threads",
                str(a.threads), "--every", str(min(a.every, a.baseline_steps)), "--out", base,
                "--baseline-n", "0"]
        subprocess.run(bcmd, stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)
        try:
            with open(os.path.join(base, "results.json")) as f:
                b = json.load(f)
            res["baseline"] = {"particles": b["particles"], "max_rss_kB": b["max_rss_kB"],
                               "command": b["command"]}
            if rss_kb and b["max_rss_kB"]:
                res["bytes_per_particle"] = (1024 * (rss_kb - b["max_rss_kB"])
                                             / (natoms - b["particles"]))
        except (OSError, KeyError, ValueError):
            failures.append(f"the baseline run failed (see {base})")
    with open(os.path.join(a.out, "results.json"), "w") as f:
        json.dump(res, f, indent=1)

    print(f"exit {p.returncode}; wall {res['wall_s']:.0f} s; loop {loop_s} s; "
          f"{res['ms_per_step']} ms/step; max RSS {rss_kb} kB; LIGGGHTS memory "
          f"{res['liggghts_memory_MB']} MB")
    if "bytes_per_particle" in res:
        print(f"peak resident set less that of {res['baseline']['particles']} particles "
              f"({res['baseline']['max_rss_kB']} kB): {res['bytes_per_particle']:.0f} bytes "
              f"per particle")
    if energy:
        b = res["energy_budget"]
        print(f"energy (J): potential {b['pe_start']:.6g} -> {b['pe_end']:.6g}, kinetic at the "
              f"end {b['ke_end']:.6g}, total {b['total_start']:.6g} -> {b['total_end']:.6g}, "
              f"dissipated {b['dissipated']:.6g}; largest rise of the total between rows "
              f"{b['largest_rise_of_total']:.3g}; discharged {b['discharged']:.0f} of {natoms}")
    if failures:
        print("FAIL long run:\n  " + "\n  ".join(failures))
        return 1
    print(f"PASS long run: {a.steps} steps, {natoms} particles, none lost, no NaN")
    return 0


if __name__ == "__main__":
    sys.exit(main())
