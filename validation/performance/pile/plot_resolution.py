#!/usr/bin/env python3
"""Mesh resolution of run_pile.py results: the settled pile's ratio to its spheres against the
triangles per rock (one thread, one rank), each repetition a dot, the median a line, with the
40x floor and the 10x goal of issue 12; beside it the rocks' and the spheres' ms per step.

  /usr/bin/python3 validation/performance/pile/plot_resolution.py RESULTS.json [...] --png resolution.png

RESULTS: run_pile.py's WORK/results_LABEL.json (every label with more than one mesh size of
the settled pile is drawn). Standard library plus Debian's matplotlib.
"""
import os
import sys
from statistics import median

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_pile  # noqa: E402  (summarise: the same pairing as the tables)


def by_resolution(results):
    """(label, n) -> [(ntri, ratios, rock ms, sphere ms)] of the settled pile, 1 thread, 1 rank."""
    out = {}
    for k, e in run_pile.summarise(results).items():
        label, geometry, n, ntri, phase, threads, ranks = k
        if geometry != "pile" or phase != "settled" or (threads, ranks) != (1, 1):
            continue
        if e["ratios"]:
            out.setdefault((label, n), []).append(
                (ntri, e["ratios"], min(e["rocks"]), min(e["spheres"])))
    return {k: sorted(v) for k, v in out.items() if len(v) > 1}


def main():
    a, lines, plt = run_pile.plot_setup(__doc__, by_resolution, "no label with more than one mesh size of the settled pile")
    fig, (left, right) = plt.subplots(1, 2, figsize=(10.0, 4.2))
    top = 0.0
    for (label, n), line in sorted(lines.items()):
        ntri = [t for t, _, _, _ in line]
        drawn = left.plot(ntri, [median(r) for _, r, _, _ in line], marker="o",
                          label=f"{n ** 3} rocks ({label})")[0]
        for t, ratios, _, _ in line:
            left.plot([t] * len(ratios), ratios, ls="none", marker=".", color=drawn.get_color(),
                      alpha=0.5)
            top = max(top, max(ratios))
        right.plot(ntri, [rock for _, _, rock, _ in line], marker="o", color=drawn.get_color(),
                   label=f"rocks ({label})")
        right.plot(ntri, [sphere for _, _, _, sphere in line], marker="s", ls="--",
                   color=drawn.get_color(), label=f"spheres of equal mass ({label})")
    left.axhline(40.0, color="tab:red", lw=1, ls="--")
    left.text(left.get_xlim()[0], 40.5, " floor 40x", color="tab:red", fontsize=8, va="bottom")
    left.axhline(10.0, color="tab:green", lw=1, ls=":")
    left.text(left.get_xlim()[0], 10.5, " goal 10x", color="tab:green", fontsize=8, va="bottom")
    left.set_ylim(0.0, max(45.0, 1.1 * top))
    left.set_xlabel("triangles per rock")
    left.set_ylabel("rock step / sphere step (1 thread)")
    left.set_title("settled pile: ratio to spheres")
    left.legend(fontsize=8, loc="lower right")
    right.set_yscale("log")
    right.set_xlabel("triangles per rock")
    right.set_ylabel("ms per step (best repetition)")
    right.set_title("settled pile: time per step")
    right.legend(fontsize=8)
    for ax in (left, right):
        ax.set_xticks(sorted({t for line in lines.values() for t, _, _, _ in line}))
        ax.grid(alpha=0.3)
    if a.title:
        fig.suptitle(a.title, fontsize=10)
    fig.tight_layout()
    fig.savefig(a.png, dpi=110)
    print(a.png)


if __name__ == "__main__":
    main()
