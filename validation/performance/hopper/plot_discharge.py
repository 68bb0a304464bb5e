#!/usr/bin/env python3
"""Discharge of the hopper (examples/hopper): mass through the outlet over time for spheres and
20- and 40-triangle rocks, and the flow rates fitted over the steady part.

Reads the `<out>/discharge.txt` files the decks write (time, particles out, mass out), either
the main runs of run_study.py (results.json in its --out folder) or files given by hand:

  /usr/bin/python3 validation/performance/hopper/plot_discharge.py [--study /tmp/hopper_study]
  /usr/bin/python3 validation/performance/hopper/plot_discharge.py --file spheres=post_s/discharge.txt \
      --file rocks40=post/discharge.txt --particles 343

Steady part: from the time 30 % of the particles have left (after the first burst of the
particles that fall straight through the outlet) to the time 85 % have (or the end
of the run if it comes first); the rate is the least-squares slope of mass out against time
there (kg/s) and of particles out (1/s). Also reports the longest pause (no particle leaving)
before the hopper empties, a sign of arching. Prints a markdown table; writes discharge.png.
"""
import argparse
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", ".."))
import valtools  # noqa: E402

LABELS = {"spheres20": "spheres, 20-tri volume", "spheres40": "spheres, 40-tri volume",
          "tri20": "rocks, 20 triangles", "tri40": "rocks, 40 triangles"}


def analyse(rows, particles, lo=0.30, hi=0.85):
    t = [r[0] for r in rows]
    n = [r[1] for r in rows]
    m = [r[2] for r in rows]
    first = next((i for i, v in enumerate(n) if v > 0), None)
    i0 = next((i for i, v in enumerate(n) if v >= lo * particles), None)
    i1 = next((i for i, v in enumerate(n) if v >= hi * particles), len(n) - 1)
    out = {"t_first": t[first] if first is not None else None, "final_n": n[-1],
           "final_m": m[-1], "t_end": t[-1]}
    if i0 is None or i1 - i0 < 3:
        return out
    k, c, rms = valtools.fit(t[i0:i1 + 1], m[i0:i1 + 1])
    kn, cn, _ = valtools.fit(t[i0:i1 + 1], n[i0:i1 + 1])
    # longest pause with particles still inside, after the first has left
    pause, since = 0.0, None
    for i in range(first, len(n)):
        if n[i] >= particles:
            break
        if i > first and n[i] == n[i - 1]:
            since = since if since is not None else t[i - 1]
            pause = max(pause, t[i] - since)
        else:
            since = None
    empty = next((t[i] for i, v in enumerate(n) if v >= particles), None)
    out.update(rate=k, intercept=c, rms=rms, rate_n=kn, window=(t[i0], t[i1]),
               longest_pause=pause, t_empty=empty)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--study", default="/tmp/hopper_study", help="run_study.py --out folder")
    ap.add_argument("--file", action="append", default=[], help="LABEL=discharge.txt (repeatable)")
    ap.add_argument("--particles", type=int, help="particles per run (with --file)")
    ap.add_argument("--png", default=os.path.join(HERE, "discharge.png"))
    a = ap.parse_args()

    series, caption = [], ""
    if a.file:
        for spec in a.file:
            label, path = spec.split("=", 1)
            series.append((label, valtools.read_discharge(path), a.particles))
    else:
        with open(os.path.join(a.study, "results.json")) as f:
            data = json.load(f)
        M = data["machine"]
        for name in ("spheres20", "spheres40", "tri20", "tri40"):
            r = data["runs"].get(name)
            if r and r.get("discharge"):
                series.append((LABELS[name], r["discharge"], r["n"] ** 3))
        r = data["runs"].get("tri40") or next(iter(data["runs"].values()))
        caption = (f"{r['n'] ** 3} particles per run, dt 2e-5 s, outlet 16 mm square; "
                   f"{M['cpu']}, {M['compiler'].split(' (')[0]} {M['compiler'].split()[-1]}, "
                   "1 thread x 1 rank")

    res = [(label, rows, N, analyse(rows, N)) for label, rows, N in series]
    print("| particles | first out (s) | steady window (s) | flow rate (g/s) | particles/s | "
          "fit rms (g) | empty at (s) | out at end | longest pause (s) |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for label, rows, N, s in res:
        if "rate" not in s:
            print(f"| {label} | {s['t_first']} | – | – | – | – | – | {s['final_n']}/{N} | – |")
            continue
        empty = f"{s['t_empty']:.2f}" if s["t_empty"] is not None else f"> {s['t_end']:.2f}"
        print(f"| {label} | {s['t_first']:.2f} | {s['window'][0]:.2f} – {s['window'][1]:.2f} | "
              f"{1e3 * s['rate']:.2f} | {s['rate_n']:.0f} | {1e3 * s['rms']:.3f} | {empty} | "
              f"{s['final_n']}/{N} | {s['longest_pause']:.2f} |")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not found: no figure (use Debian's /usr/bin/python3)")
        return
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.4))
    styles = {"spheres": "--", "rocks": "-"}
    for k, (label, rows, N, s) in enumerate(res):
        t = [r[0] for r in rows]
        ls = styles["spheres" if label.startswith("spheres") else "rocks"]
        line, = a1.plot(t, [1e3 * r[2] for r in rows], ls, label=label)
        if "rate" in s:
            w0, w1 = s["window"]
            a1.plot([w0, w1], [1e3 * (s["intercept"] + s["rate"] * w) for w in (w0, w1)], ":",
                    color="k", lw=1)
            line.set_label(f"{label}: {1e3 * s['rate']:.1f} g/s")
        a2.plot(t, [r[1] / N for r in rows], ls, color=line.get_color(), label=label)
    a1.set_xlabel("time (s)")
    a1.set_ylabel("mass out (g)")
    a1.set_title("mass discharged (dotted: fitted steady rate)", fontsize=10)
    a1.legend(fontsize=8)
    a2.set_xlabel("time (s)")
    a2.set_ylabel("fraction of particles out")
    a2.set_title("fraction discharged", fontsize=10)
    a2.legend(fontsize=8)
    fig.suptitle("Hopper discharge: spheres and triangulated rocks", fontsize=10)
    if caption:
        fig.text(0.01, 0.01, caption, fontsize=7)
    fig.tight_layout(rect=(0, 0.03, 1, 0.96))
    fig.savefig(a.png, dpi=110)
    print("wrote", a.png)


if __name__ == "__main__":
    main()
