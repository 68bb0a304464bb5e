#!/usr/bin/python3
"""energy.png (this folder) from a long run's energy.txt (run_longrun.py --out, default
/tmp/longrun): translational and rotational kinetic, potential and total energy, the energy
dissipated so far (total at the first row minus total now; the first row is in free fall,
before any contact), and the number of particles discharged. Works on a run still going.

  /usr/bin/python3 validation/longrun/plot_longrun.py [--out /tmp/longrun] [--png energy.png]

Needs matplotlib (Debian's python3-matplotlib).
"""
import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, ".."))
import valtools  # noqa: E402

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", default="/tmp/longrun")
    ap.add_argument("--png", default=os.path.join(HERE, "energy.png"))
    a = ap.parse_args()
    rows = valtools.read_rows(os.path.join(a.out, "energy.txt"))
    if not rows:
        sys.exit(f"no rows in {a.out}/energy.txt")
    t = [r[1] for r in rows]
    e0 = rows[0][7]
    series = [("translational kinetic", [r[4] for r in rows], "C0"),
              ("rotational kinetic", [r[5] for r in rows], "C1"),
              ("potential (z from the floor)", [r[6] for r in rows], "C2"),
              ("total", [r[7] for r in rows], "k"),
              ("dissipated", [e0 - r[7] for r in rows], "C3")]
    fig, ax = plt.subplots(figsize=(8, 4.8))
    for label, y, colour in series:
        ax.plot(t, [1e3 * v for v in y], label=label, color=colour,
                lw=2 if label == "total" else 1.2)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("energy (mJ)")
    ax.set_xlim(0, max(t))
    ax.grid(alpha=0.3)
    ax2 = ax.twinx()
    ax2.plot(t, [r[3] for r in rows], color="0.5", ls="--", label="discharged (right axis)")
    ax2.set_ylabel("particles discharged")
    ax2.set_ylim(0, rows[0][2])
    lines = ax.get_legend_handles_labels()
    lines2 = ax2.get_legend_handles_labels()
    ax.legend(lines[0] + lines2[0], lines[1] + lines2[1], loc="center right", fontsize=8)
    ax.set_title(f"hopper, {int(rows[0][2])} rocks of 40 triangles, dt 2e-5 s, "
                 f"steps 0..{int(rows[-1][0])}", fontsize=10)
    fig.tight_layout()
    fig.savefig(a.png, dpi=110)
    print(f"wrote {a.png} ({len(rows)} rows, t = {t[0]} .. {t[-1]} s)")
    print_table(rows)


def print_table(rows):
    """The energy history as a Markdown table, at 0.1, 0.2, 0.5, 1, 1.5 and 2 s (those reached)."""
    e0 = rows[0][7]
    print("| t (s) | discharged | kinetic, translational (mJ) | rotational (mJ) | potential (mJ) "
          "| total (mJ) | dissipated (mJ) |")
    print("|---:|---:|---:|---:|---:|---:|---:|")
    marks = [rows[0][1], 0.1, 0.2, 0.5, 1.0, 1.5, 2.0]
    for m in marks:
        r = min(rows, key=lambda r: abs(r[1] - m))
        if abs(r[1] - m) > 1e-9 and m != marks[0]:
            continue
        print(f"| {r[1]:g} | {r[3]:.0f} | {1e3 * r[4]:.4g} | {1e3 * r[5]:.4g} | {1e3 * r[6]:.4g} "
              f"| {1e3 * r[7]:.4g} | {1e3 * (e0 - r[7]):.4g} |")
    rises = [rows[k + 1][7] - rows[k][7] for k in range(len(rows) - 1)]
    print(f"largest rise of the total between rows {max(rises, default=0):.3g} J; rows where it "
          f"rose: {sum(x > 0 for x in rises)} of {len(rises)}")


if __name__ == "__main__":
    main()
