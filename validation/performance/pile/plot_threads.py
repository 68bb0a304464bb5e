#!/usr/bin/env python3
"""Thread scaling of run_pile.py results: the median speed-up over one thread (each repetition
paired with the one-thread run just before it, as run_pile.py's table computes it) against the
thread count, one line per deck, the ideal and Amdahl's law for the serial share that fits the
largest thread count drawn thin.

  /usr/bin/python3 validation/performance/pile/plot_threads.py RESULTS.json [...] --png threads.png

RESULTS: run_pile.py's WORK/results_LABEL.json (any number; every label with more than one
thread count is drawn). Standard library plus Debian's matplotlib.
"""
import os
import sys
from statistics import median

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_pile  # noqa: E402  (summarise: the same pairing as the tables)


def scaling(results):
    """(label, geometry, n, ntri, phase) -> [(threads, median speed-up, all speed-ups)], one
    rank only."""
    out = {}
    for k, e in run_pile.summarise(results).items():
        label, geometry, n, ntri, phase, threads, ranks = k
        if ranks != 1:
            continue
        line = out.setdefault((label, geometry, n, ntri, phase), [])
        if threads == 1:
            line.append((1, 1.0, [1.0]))
        elif e.get("speedups"):
            line.append((threads, median(e["speedups"]), e["speedups"]))
    return {k: sorted(v) for k, v in out.items() if len(v) > 1}


def main():
    a, lines, plt = run_pile.plot_setup(__doc__, scaling, "no label with more than one thread count")
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    top = max(t for line in lines.values() for t, _, _ in line)
    ax.plot([1, top], [1, top], color="0.6", lw=1, ls="--", label="ideal")
    for (label, geometry, n, ntri, phase), line in sorted(lines.items()):
        threads = [t for t, _, _ in line]
        speedup = [s for _, s, _ in line]
        name = f"{geometry} {n ** 3} x {ntri}, {phase} ({label})"
        drawn = ax.plot(threads, speedup, marker="o", label=name)[0]
        for t, _, every in line:  # each repetition, faint: the spread is the host's noise
            ax.scatter([t] * len(every), every, color=drawn.get_color(), alpha=0.25, s=12)
        # Amdahl's law through the largest thread count: the serial share s it implies.
        p, sp = threads[-1], speedup[-1]
        s = (p / sp - 1.0) / (p - 1.0)
        ts = [1 + (top - 1) * i / 60 for i in range(61)]
        ax.plot(ts, [1.0 / (s + (1.0 - s) / t) for t in ts], color=drawn.get_color(), lw=0.8,
                ls=":", label=f"  Amdahl, serial share {100 * s:.0f} %")
        print(f"{name}: " + ", ".join(f"{t} threads {v:.2f}x" for t, v, _ in line)
              + f"; serial share at {p} threads {100 * s:.1f} %")
    ax.set_xscale("log", base=2)
    ax.set_yscale("log", base=2)
    ticks = sorted({t for line in lines.values() for t, _, _ in line})
    ax.set_xticks(ticks)
    ax.set_xticklabels([str(t) for t in ticks])
    ax.set_yticks(ticks)
    ax.set_yticklabels([str(t) for t in ticks])
    ax.set_xlabel("OpenMP threads (1 MPI rank)")
    ax.set_ylabel("speed-up of a step over 1 thread")
    ax.set_title(a.title or "pair tri/gran and fix tri/wall: thread scaling", fontsize=10)
    ax.grid(True, which="major", alpha=0.3)
    ax.legend(fontsize=7, loc="upper left")
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)
    print(f"wrote {a.png}")


if __name__ == "__main__":
    main()
