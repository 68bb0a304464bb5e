"""The oblique studies' figure (run.py, run_pairs.py): the worst error over the orientations of
vt' and omega' against the icosphere level, one line per (kt/kn series, vt/vn ratio), on a log
scale with the 1 % target. Needs Debian's numpy and matplotlib."""
import numpy as np


def plot_errors(res, levels, series, ratios, tol, ylabel, title, out, means=False):
    """res[level, series name, ratio] holds arrays "ev" and "ew" (one error per orientation);
    `means`: open markers for the mean |error| as well. Writes `out`."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(12, 4.8), sharey=True)
    colours = {q: "C%d" % k for k, q in enumerate(ratios)}
    floor = 1e-6
    for col, (key, name) in enumerate((("ev", "rebound tangential velocity vt'"),
                                       ("ew", "rebound spin omega'"))):
        a = ax[col]
        for sname, _ in series:
            style = "o-" if sname == "2/7" else "s--"
            for ratio in ratios:
                worst = [max(np.abs(res[lv, sname, ratio][key]).max(), floor) for lv in levels]
                a.plot(levels, [100 * w for w in worst], style, color=colours[ratio],
                       label="kt/kn %s, vt/vn %g%s" % (sname, ratio, " (worst)" if means else ""))
                if means:
                    mean = [max(np.abs(res[lv, sname, ratio][key]).mean(), floor)
                            for lv in levels]
                    a.plot(levels, [100 * w for w in mean], style[0], color=colours[ratio],
                           mfc="none", ms=9, alpha=0.6)
        a.axhline(100 * tol, color="k", lw=1, ls=":", label="1 % target")
        a.set_yscale("log")
        a.set_xticks(levels)
        a.set_xticklabels(["%d\n(%d tri)" % (lv, 20 * 4 ** lv) for lv in levels])
        a.set_xlabel("icosphere level")
        a.set_title(name)
        a.grid(alpha=0.3, which="both")
    ax[0].set_ylabel(ylabel)
    ax[1].legend(fontsize=7, ncol=2)
    fig.suptitle(title, fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print("plot:", out)
