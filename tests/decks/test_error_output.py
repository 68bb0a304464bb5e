"""An ERROR is printed once, as plain text, on the screen and in the log.

Debian's LIGGGHTS 3.8 follows the ERROR line, two times in ten, with a "tip" it has already
freed: a line of heap bytes and the same (file:line). It picks the tip from rand() seeded with
the time in seconds, so plain liggghts and liggghts-tri started within the same second make the
same pick. At the start of each second this runs, in turn, a deck that stops with Error::all (an
unknown command) or one that stops with Error::fix_error (fix mesh/surface without a file)
through both, until plain liggghts has printed its freed tip in at least two seconds (about ten
seconds; at most 120 s): in those very seconds liggghts-tri must print its ERROR line and nothing
after it (src_plugin/driver/error_output.cpp), byte for byte the same ERROR line as liggghts."""
import os
import re
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


def run_both(ctx, name):
    """Runs deck `name` through liggghts, then liggghts-tri, within one second; returns their
    (screen + log) bytes, or None if the second turned over between them."""
    out = {}
    second = int(time.time())
    for exe_name, exe in (("liggghts", ctx.liggghts), ("liggghts-tri", ctx.exe)):
        log = os.path.join(ctx.work, f"log.{exe_name}")
        code, screen = run([exe, "-in", f"in.{name}", "-log", log], ctx.work)
        check(code != 0, f"{exe_name} {name}: exit {code}, the deck must stop with an ERROR")
        with open(log, "rb") as f:
            out[exe_name] = (screen.encode("utf-8", "surrogateescape"), f.read())
    return out if int(time.time()) == second else None


def test_error_printed_once(ctx):
    for name, text in DECKS.items():
        with open(os.path.join(ctx.work, f"in.{name}"), "w") as f:
            f.write(text)
    tip_seconds, seconds = 0, 0
    start = time.time()
    while tip_seconds < 2 and time.time() - start < MAX_SECONDS:
        time.sleep(1.0 - time.time() % 1.0 + 0.01)   # the start of the next second
        seconds += 1
        name = list(DECKS)[seconds % len(DECKS)]   # one deck a second: both runs fit in it
        both = run_both(ctx, name)
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
                print(f"second {seconds}: liggghts printed its freed tip after the {name} ERROR; "
                      "liggghts-tri printed the ERROR line alone")
    check(tip_seconds >= 2, f"in {seconds} seconds liggghts printed its freed tip in "
                            f"{tip_seconds}; the test needs two to show anything (expected 2 in "
                            "ten seconds)")
