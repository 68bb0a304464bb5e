"""An ERROR is printed once, as plain text, on the screen and in the log.

Debian's LIGGGHTS 3.8 follows the ERROR line, two times in ten, with a "tip" it has already
freed: a line of heap bytes and the same (file:line). It picks the tip from rand() seeded with
the time in seconds, so plain liggghts and liggghts-tri erring within the same second make the
same pick. This runs, in turn, a deck that stops with Error::all (an unknown command) or one
that stops with Error::fix_error (fix mesh/surface without a file) through both side by side,
timed to stop within one second, until plain liggghts has printed its freed tip in at least two
such seconds (about ten tries; at most 120 s): there liggghts-tri must print its ERROR line and
nothing after it (src_plugin/driver/error_output.cpp), byte for byte the same ERROR line as
liggghts."""
import os
import re
import threading
import time

from decklib import check, run

DECKS = {
    "unknown_command": "units si\nfoo_bar 1\n",
    "fix_error": "units si\natom_style sphere\nregion b block 0 1 0 1 0 1\ncreate_box 1 b\n"
                 "fix m all mesh/surface type 1\nrun 1\n",
}
SOURCE = re.compile(rb"\([^()]*:\d+\)\s*$")   # LIGGGHTS's trailing " (file.cpp:123)"
MAX_SECONDS = 120


def located_lines(data):
    """The lines that end in a LIGGGHTS source location: ERROR lines, and the freed tip."""
    return [l for l in data.split(b"\n") if SOURCE.search(l)]


def run_both(ctx, name, durations):
    """Runs deck `name` through liggghts and liggghts-tri side by side, started so that both
    should stop in the middle of one second (durations: each one's last run time, s); returns
    their (screen, log) bytes, or None unless both stopped within one second and after its
    first tenth (LIGGGHTS reads the time in its error exit, which ends the process within
    milliseconds)."""
    out, ends = {}, {}

    def one(exe_name, exe, delay):
        time.sleep(delay)
        start = time.time()
        log = os.path.join(ctx.work, f"log.{exe_name}")
        code, screen = run([exe, "-in", f"in.{name}", "-log", log], ctx.work)
        ends[exe_name] = time.time()
        durations[exe_name] = ends[exe_name] - start
        with open(log, "rb") as f:
            out[exe_name] = (code, screen.encode("utf-8", "surrogateescape"), f.read())

    longest = max(durations.values())
    now = time.time()
    # wait so that the longer run ends about half a second into a second
    time.sleep((0.5 - (now + longest) % 1.0) % 1.0)
    threads = [threading.Thread(target=one, args=(n, e, longest - durations[n]))
               for n, e in (("liggghts", ctx.liggghts), ("liggghts-tri", ctx.exe))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for exe_name, (code, _, _) in out.items():
        check(code != 0, f"{exe_name} {name}: exit {code}, the deck must stop with an ERROR")
    seconds = {int(e) for e in ends.values()}
    if len(seconds) != 1 or min(e % 1.0 for e in ends.values()) < 0.1:
        return None
    return {k: v[1:] for k, v in out.items()}


def test_error_printed_once(ctx):
    for name, text in DECKS.items():
        with open(os.path.join(ctx.work, f"in.{name}"), "w") as f:
            f.write(text)
    tip_seconds, tries = 0, 0
    durations = {name: {"liggghts": 0.3, "liggghts-tri": 0.3} for name in DECKS}
    start = time.time()
    while tip_seconds < 2 and time.time() - start < MAX_SECONDS:
        tries += 1
        name = list(DECKS)[tries % len(DECKS)]
        both = run_both(ctx, name, durations[name])
        if both is not None:
            for where, k in (("screen", 0), ("log", 1)):
                plain = located_lines(both["liggghts"][k])
                tri = located_lines(both["liggghts-tri"][k])
                check(len(tri) == 1 and tri[0].startswith(b"ERROR"),
                      f"{name}, {where}: liggghts-tri printed {tri!r}, wanted one ERROR line")
                check(plain[0] == tri[0], f"{name}, {where}: liggghts printed {plain[0]!r}, "
                                          f"liggghts-tri {tri[0]!r}")
                check(all(32 <= b < 127 or b in (9, 10, 13) for b in both["liggghts-tri"][k]),
                      f"{name}, {where}: liggghts-tri printed bytes that are not text")
            if len(located_lines(both["liggghts"][0])) > 1:
                tip_seconds += 1
                print(f"try {tries}: liggghts printed its freed tip after the {name} ERROR; "
                      "liggghts-tri printed the ERROR line alone")
    check(tip_seconds >= 2, f"in {tries} tries liggghts printed its freed tip in "
                            f"{tip_seconds}; the test needs two to show anything (expected: 2 in "
                            "ten tries whose runs ended within one second)")
