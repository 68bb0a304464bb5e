"""examples/chute (LIGGGHTS's meshGran tutorial converted to rocks) run briefly: the tutorial's
own material fixes (model hooke), epsilon auto and the time-step check at work, 40 rocks fed by
fix insert/stream from the tutorial's template, landing on the chute with no intersecting
surfaces and no error. Also counts the commands the conversion changed against the tutorial."""
import difflib
import os

from decklib import HERE, check, run_deck, thermo_rows

CHUTE = os.path.join(HERE, "..", "..", "examples", "chute", "in.chute")
TUTORIAL = "/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public/meshGran"


def code_lines(path):
    """The deck's commands: comments and blank lines dropped, whitespace normalised."""
    out = []
    with open(path) as f:
        for line in f:
            words = line.split("#")[0].split()
            if words:
                out.append(" ".join(words))
    return out


def test_chute(ctx):
    check(os.path.isfile(os.path.join(TUTORIAL, "in.meshGran")),
          f"{TUTORIAL} is missing: install Debian's liggghts-doc "
          "(apt-get install --no-install-recommends liggghts-doc)")
    _, out = run_deck(ctx, CHUTE, {"tut": TUTORIAL, "n": 40, "steps1": 800, "steps2": 4000},
                      env_extra={"OMP_NUM_THREADS": "1"})
    check("ERROR" not in out, f"an error: {out[-2500:]}")
    rows = thermo_rows(out)
    check(len(rows) >= 5, f"{len(rows)} thermo rows")
    check(rows[-1]["Atoms"] == 40, f"{rows[-1]['Atoms']:g} atoms inserted, expected 40")
    check(any(r["stats.pairs_in_contact"] > 0 for r in rows),
          "the rocks never touched the chute or each other")
    check(all(r["stats.penetrations"] == 0 for r in rows), "real surfaces intersected")
    for what in ("tri/particles: epsilon auto = ", "tri/particles: time-step check: dt 5e-05 s",
                 "tri/particles: template pts1 (radius 0.005 m"):
        check(what in out, f"no line '{what}...'")
    warnings = [l for l in out.splitlines() if "WARNING" in l and "highly skewed" not in l]
    check(not warnings, f"warnings: {warnings}")
    # The conversion: the tutorial's commands that changed, or were added or removed.
    tut, ours = code_lines(os.path.join(TUTORIAL, "in.meshGran")), code_lines(CHUTE)
    changed = added = removed = 0
    for op, i1, i2, j1, j2 in difflib.SequenceMatcher(None, tut, ours).get_opcodes():
        if op == "replace":
            changed += max(i2 - i1, j2 - j1)
        elif op == "insert":
            added += j2 - j1
        elif op == "delete":
            removed += i2 - i1
    check(len(tut) > 30 and changed + added + removed < len(tut),
          f"the conversion changed {changed + added + removed} of {len(tut)} commands")
    print(f"conversion: {len(tut)} tutorial commands; {changed} changed, {added} added, "
          f"{removed} removed (examples/chute/in.chute); 40 rocks on the chute at t = 0.2 s, "
          f"up to {max(int(r['stats.pairs_in_contact']) for r in rows)} pairs in contact, "
          f"no intersection")
