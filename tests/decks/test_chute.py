"""examples/chute (LIGGGHTS's meshGran tutorial converted to rocks) run briefly: the tutorial's
own material fixes (model hooke), epsilon auto and the time-step check at work, 40 rocks fed by
fix insert/stream from the tutorial's template, landing on the chute with no intersecting
surfaces and no error. Also counts the commands the conversion changed against the tutorial."""
import difflib
import os
import re

from decklib import HERE, check, run_deck, thermo_rows

ROOT = os.path.join(HERE, "..", "..")
CHUTE = os.path.join(ROOT, "examples", "chute", "in.chute")
TUTORIAL = "/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public/meshGran"
# The manual's page on the conversion, which states the command counts.
FROM_SPHERES = os.path.join("src_plugin", "doc", "from_spheres.md")


def code_lines(path):
    """The deck's commands: comments and blank lines dropped, whitespace normalised."""
    out = []
    with open(path) as f:
        for line in f:
            words = line.split("#")[0].split()
            if words:
                out.append(" ".join(words))
    return out


def readme_quotes(path):
    """The lines of fix tri/particles a README quotes (`tri/particles: ...`), each without a
    closing "(...)" and with its whitespace normalised."""
    with open(path) as f:
        text = " ".join(f.read().split())
    return [re.sub(r"\s*\(\.\.\.\)$", "", q) for q in re.findall(r"`(tri/particles: [^`]*)`", text)]


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
    # What examples/chute/README.md says the deck prints, figure for figure.
    printed = " ".join(out.split())
    quotes = readme_quotes(os.path.join(ROOT, "examples", "chute", "README.md"))
    check(len(quotes) >= 3, f"examples/chute/README.md quotes {len(quotes)} lines")
    for quote in quotes:
        check(quote in printed, f"examples/chute/README.md quotes `{quote}`, not in the output")
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
    with open(os.path.join(ROOT, FROM_SPHERES)) as f:
        said = re.search(r"Of the tutorial's (\d+) commands, the conversion changes (\d+) and adds "
                         r"(\d+)", " ".join(f.read().split()))
    check(said and [int(g) for g in said.groups()] == [len(tut), changed, added],
          f"{FROM_SPHERES} says {said and said.group(0)!r}; the decks give {len(tut)} commands, "
          f"{changed} changed, {added} added, {removed} removed")
    print(f"conversion: {len(tut)} tutorial commands; {changed} changed, {added} added, "
          f"{removed} removed (examples/chute/in.chute); 40 rocks on the chute at t = 0.2 s, "
          f"up to {max(int(r['stats.pairs_in_contact']) for r in rows)} pairs in contact, "
          f"no intersection")
