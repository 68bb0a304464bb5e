#!/usr/bin/python3
"""Figures of validation/bulk from a results JSON of run_bulk.py (Debian's matplotlib):

  /usr/bin/python3 validation/bulk/plot_bulk.py validation/bulk/results/bulk_LABEL*.json [--out DIR]

icospheres.png: phi against the triangle count (`layer inside`, and 320 triangles with `layer
outside`), one panel per Young's modulus, the spheres' mean as a line with the +-2 % target band.
platonic.png: the Platonic solids' poured phi against Baker & Kudrolli's loose and dense bands
(PRE 82, 061304, 2010, plastic dice, +-0.01), with the spheres of the same pour; diamonds: the
bed shaken by its floor (run_bulk.py --tap), where run.
"""
import argparse
import json
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def mean(xs):
    return sum(xs) / len(xs)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("results", nargs="+", help="results JSON files of run_bulk.py (merged)")
    ap.add_argument("--out", default=HERE)
    args = ap.parse_args()
    datas = [json.load(open(p)) for p in args.results]
    data = datas[0]
    rs = [r for d in datas for r in d["results"] if not r["failed"]]
    n = data["n"]

    ico = [r for r in rs if r["study"] == "ico"]
    ys = sorted({r["Y"] for r in ico})
    if ys:
        fig, axes = plt.subplots(1, len(ys), figsize=(5.2 * len(ys), 4.2), squeeze=False)
        for ax, y in zip(axes[0], ys):
            sph = [r["phi"] for r in ico if r["Y"] == y and r["name"] == "spheres"]
            if sph:
                s = mean(sph)
                ax.axhline(s, color="k", lw=1.2, label=f"LIGGGHTS spheres ({len(sph)} seeds): {s:.3f}")
                ax.axhspan(0.98 * s, 1.02 * s, color="0.85", label="spheres +-2 %")
                ax.plot([60] * len(sph), sph, "k_", ms=8)
            sphc = [r["phi_cut"] for r in ico if r["Y"] == y and r["name"] == "spheres"]
            if sphc:
                ax.axhline(mean(sphc), color="k", lw=0.8, ls="--",
                           label=f"spheres, phi_cut: {mean(sphc):.3f}")
            for layer, color in (("inside", "tab:blue"), ("outside", "tab:red")):
                mine = [r for r in ico if r["Y"] == y and r.get("layer") == layer]
                counts = sorted({r["ntri"] for r in mine})
                if not counts:
                    continue
                seeds = max(len([r for r in mine if r["ntri"] == c]) for c in counts)
                ax.plot(counts, [mean([r["phi"] for r in mine if r["ntri"] == c]) for c in counts],
                        "o-", color=color, label=f"icospheres, layer {layer} ({seeds} seed(s))")
                ax.plot(counts, [mean([r["phi_cut"] for r in mine if r["ntri"] == c]) for c in counts],
                        "o--", mfc="none", color=color, label=f"  the same, phi_cut")
                ax.plot([r["ntri"] for r in mine], [r["phi"] for r in mine], "x", color=color, ms=5)
            ax.set_xscale("log")
            ax.set_xticks([80, 320, 1280])
            ax.set_xticklabels(["80", "320", "1280"])
            ax.set_xlim(50, 2000)
            lows = [r["phi"] for r in ico if r["Y"] == y] + [r["phi_cut"] for r in ico if r["Y"] == y]
            ax.set_ylim(min(lows) - 0.06, max(lows) + 0.015)
            ax.set_xlabel("triangles per icosphere")
            ax.set_ylabel("solid fraction phi (bulk slab)")
            ax.set_title(f"Y = {y:g} Pa, N = {n}")
            ax.legend(fontsize=6.5, loc="lower left")
            ax.grid(alpha=0.3)
        fig.suptitle("Poured packing: icospheres (volume-equivalent d = 4 mm) vs LIGGGHTS spheres\n"
                     "filled: phi from the centres in the slab (x: single seeds; spheres' seeds at left), "
                     "open: phi_cut", fontsize=8)
        fig.tight_layout()
        path = os.path.join(args.out, "icospheres.png")
        fig.savefig(path, dpi=120)
        print("wrote", path)

    pla = [r for r in rs if r["study"] == "platonic"]
    if pla:
        bk = data["baker_kudrolli"]
        names = list(bk)
        fig, ax = plt.subplots(figsize=(7, 4.2))
        for i, name in enumerate(names):
            lo, de = bk[name]
            ax.add_patch(plt.Rectangle((i - 0.35, lo - 0.01), 0.7, 0.02, color="tab:blue", alpha=0.3,
                                       label="Baker & Kudrolli loose" if i == 0 else None))
            ax.add_patch(plt.Rectangle((i - 0.35, de - 0.01), 0.7, 0.02, color="tab:green", alpha=0.3,
                                       label="Baker & Kudrolli dense" if i == 0 else None))
            mine = [r for r in pla if r["name"] == name]
            if mine:
                p = mean([r["phi"] for r in mine])
                pc = mean([r["phi_cut"] for r in mine])
                ax.plot([i] * len(mine), [r["phi"] for r in mine], "rx", ms=5)
                ax.plot([i], [p], "ro", label="liggghts-tri, poured (centres)" if i == 0 else None)
                ax.plot([i], [pc], "o", mfc="none", color="r", label="the same, phi_cut" if i == 0 else None)
                ax.vlines([i], min(r["lo"] for r in mine), max(r["hi"] for r in mine), color="r",
                          lw=0.8, label="slab ends +-d/4" if i == 0 else None)
                ax.annotate(f"{p:.3f}", (i + 0.08, p), fontsize=8)
                tap = [r["tapped"] for r in mine if "tapped" in r]
                if tap:
                    pt = mean([t["phi"] for t in tap])
                    ax.plot([i + 0.15], [pt], "D", color="darkgreen",
                            label="liggghts-tri, shaken (centres)" if i == 0 else None)
                    ax.plot([i + 0.15], [mean([t["phi_cut"] for t in tap])], "D", mfc="none",
                            color="darkgreen", label="the same, phi_cut" if i == 0 else None)
                    ax.annotate(f"{pt:.3f}", (i + 0.22, pt), fontsize=7, color="darkgreen")
        sph = [r["phi"] for r in pla if r["name"] == "spheres"]
        if sph:
            ax.axhline(mean(sph), color="k", lw=1, ls="--",
                       label=f"LIGGGHTS spheres, same pour: {mean(sph):.3f}")
        ax.set_xticks(range(len(names)))
        ax.set_xticklabels(names)
        ax.set_xlim(-0.6, len(names) - 0.4)
        ax.set_ylim(0.36, 0.72)
        ax.set_ylabel("solid fraction phi")
        y = pla[0]["Y"]
        ax.set_title(f"Platonic solids (volume-equivalent d = 4 mm), Y = {y:g} Pa, N = {n}", fontsize=9)
        ax.legend(fontsize=7, loc="lower center", ncol=2)
        ax.grid(alpha=0.3)
        fig.tight_layout()
        path = os.path.join(args.out, "platonic.png")
        fig.savefig(path, dpi=120)
        print("wrote", path)


if __name__ == "__main__":
    main()
