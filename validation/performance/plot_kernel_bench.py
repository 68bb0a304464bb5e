#!/usr/bin/python3
"""Plots kernel_bench's CSV output (kernel_bench --csv DIR).

usage: /usr/bin/python3 plot_kernel_bench.py DIR [OUT.png]

Left: Newton iterations the penalty needs (the paper's Fig. 2, left), all triangle pairs of
touching 40-triangle particles and the pairs the box cull keeps. Right: time per touching
particle pair for every kernel, with and without the cull, 20 and 40 triangles, beside the
reference code's figures for 40 triangles (DESIGN.md).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    src = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else "kernel_bench.png"
    hist = read(f"{src}/kernel_bench_histogram.csv")
    thr = read(f"{src}/kernel_bench_throughput.csv")

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 4.5))
    sets = sorted({r["set"] for r in hist})
    width = 0.4
    for i, s in enumerate(sets):
        rows = [r for r in hist if r["set"] == s]
        total = sum(int(r["pairs"]) for r in rows)
        its = [int(r["iterations"]) for r in rows if int(r["iterations"]) > 0]
        frac = [100 * int(r["pairs"]) / total for r in rows if int(r["iterations"]) > 0]
        never = [100 * int(r["pairs"]) / total for r in rows if int(r["iterations"]) == 0][0]
        ax1.bar([k + (i - 0.5) * width for k in its], frac, width,
                label=f"{s} (never: {never:.1f}%)")
    ax1.set_xlim(0, 13)
    ax1.set_xlabel("Newton iterations until the step is below the tolerance")
    ax1.set_ylabel("triangle pairs [%]")
    ax1.set_title("Penalty convergence, touching 40-triangle particles")
    ax1.legend()

    kernels = []
    for r in thr:
        if r["kernel"] not in kernels:
            kernels.append(r["kernel"])
    groups = [("40", "0"), ("40", "1"), ("20", "0"), ("20", "1")]
    labels = [f"{n} tri, {'cull' if c == '1' else 'no cull'}" for n, c in groups]
    w = 0.8 / len(kernels)
    for i, k in enumerate(kernels):
        ys = []
        for n, c in groups:
            row = [r for r in thr if r["kernel"] == k and r["triangles"] == n and r["cull"] == c]
            ys.append(float(row[0]["us_per_particle_pair"]) if row else 0)
        ax2.bar([g + (i - len(kernels) / 2 + 0.5) * w for g in range(len(groups))], ys, w,
                label=k)
    ax2.axhline(412, color="gray", ls="--", lw=1)
    ax2.text(3.45, 412, "reference brute force, 40 tri (412 us)", ha="right", va="bottom",
             fontsize=8)
    ax2.axhline(298, color="gray", ls=":", lw=1)
    ax2.text(3.45, 298, "reference batched hybrid, 40 tri (298 us)", ha="right", va="bottom",
             fontsize=8)
    ax2.set_yscale("log")
    ax2.set_xticks(range(len(groups)))
    ax2.set_xticklabels(labels)
    ax2.set_ylabel("us per touching particle pair (one thread)")
    ax2.set_title("Contact detection time")
    ax2.legend(fontsize=8, loc="lower left")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
