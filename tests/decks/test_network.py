"""The contact network: compute tri/contact/local in a dump local and compute tri/contact/atom,
on a known configuration (in.contact_network: two cubes at rest face on face on a plane), on 1
and 2 MPI ranks (the pair split between them), and the computes' bad input."""
import os

from decklib import check, expect_error, last_frame, make_contact_meshes, run_deck

G = 9.81
CUBE_MASS = 2500 * 0.004 ** 3   # cube.stl (4 mm), density 2500
# The flat of the contact surface: the 4 mm face less the edges rounded with radius epsilon.
FACE_AREA = (0.004 - 2 * 1e-4) ** 2
FACE, DEEP = 1, 4               # tri::ContactKind


def local_rows(path):
    """The last snapshot of a dump local: a list of rows of floats."""
    check(os.path.exists(path), f"{path} was not written")
    lines = open(path).read().splitlines()
    starts = [k for k, l in enumerate(lines) if l.startswith("ITEM: NUMBER OF ENTRIES")]
    check(starts, f"{path} holds no snapshot")
    k = starts[-1]
    n = int(lines[k + 1])
    body = lines[k + 7:k + 7 + n]
    check(lines[k + 6].startswith("ITEM: ENTRIES") and len(body) == n,
          f"{path}: malformed snapshot at line {k + 1}")
    return [[float(w) for w in l.split()] for l in body]


def network(ctx, pz=1, phase="network", which=""):
    run_deck(ctx, "in.contact_network", {"pz": pz, "phase": phase, "nsteps": 3000,
                                         "which": which}, ranks=pz)
    rows = local_rows(os.path.join(ctx.work, f"network_{phase}.dump"))
    _, atoms = last_frame(os.path.join(ctx.work, f"peratom_{phase}.dump"))
    return rows, atoms


def check_row(row, what, weight):
    fz, fnz = row[5], row[8]
    check(abs(fnz / weight - 1) < 1e-3 and abs(fz / weight - 1) < 1e-3,
          f"{what}: normal force on i {fnz:g} N (total {fz:g}), the weight it carries {weight:g}")
    check(max(abs(row[3]), abs(row[4]), abs(row[6]), abs(row[7])) < 1e-6 * abs(weight),
          f"{what}: lateral force {row[3:5]} at rest")
    check(row[16] == FACE, f"{what}: kind {row[16]:g}, expected face ({FACE})")
    check(abs(row[12] / FACE_AREA - 1) < 0.01, f"{what}: area {row[12]:g} m^2, the face's "
          f"{FACE_AREA:g}")


def test_network_stack(ctx):
    """Two rows: the pair (ids 1 2, not periodic) and the bottom cube on the plane (id 1, mesh 1,
    a triangle id); both face contacts over the face's area (1 %), the pair's normal force on
    the bottom cube -m g and the wall's +2 m g (0.1 %), their points at z = 0 and at the floor;
    contact/atom 2 and 1. On 2 ranks the same rows (the pair once), to 1e-9 of the force; `pair`
    and `wall` select their rows."""
    make_contact_meshes(ctx.work)
    rows, atoms = network(ctx)
    check(len(rows) == 2, f"{len(rows)} rows, expected 2 (a pair and a wall contact): {rows}")
    pair = [r for r in rows if r[1] > 0]
    wall = [r for r in rows if r[1] < 0]
    check(len(pair) == 1 and len(wall) == 1, f"rows {rows}: expected one pair and one wall row")
    pair, wall = pair[0], wall[0]
    check(pair[0:3] == [1, 2, 0], f"pair ids {pair[0:3]}, expected 1 2 0")
    check(wall[0] == 1 and wall[1] == -1 and wall[2] >= 0, f"wall ids {wall[0:3]}, expected 1 -1 "
          "and a triangle id")
    m_g = CUBE_MASS * G
    check_row(pair, "pair", -m_g)          # the top cube pushes the bottom one down
    check_row(wall, "wall", 2 * m_g)       # the plane carries both
    check(abs(pair[15]) < 2e-4, f"pair contact point z {pair[15]:g}, expected ~0 (the faces)")
    # Midway through the overlap of the bottom face and the plane (z = -4.015 mm; the overlap
    # under two cubes' weight is about 1.6 um).
    check(abs(wall[15] + 0.004015) < 2e-6, f"wall contact point z {wall[15]:g}, expected ~-0.004015")
    print(f"pair: fn {pair[8]:.6e} N (m g {m_g:.6e}), area {pair[12]:.6e}; wall: fn "
          f"{wall[8]:.6e} N, area {wall[12]:.6e} m^2")
    counts = {tag: float(f[1]) for tag, f in atoms.items()}
    check(counts == {1: 2.0, 2: 1.0}, f"contact/atom {counts}, expected 1: 2, 2: 1")
    split, split_atoms = network(ctx, pz=2, phase="ranks")
    check(len(split) == 2, f"2 ranks: {len(split)} rows, expected 2: {split}")
    key = lambda r: r[1]
    for a, b in zip(sorted(rows, key=key), sorted(split, key=key)):
        check(a[0:3] == b[0:3] and a[16] == b[16], f"2 ranks: row {b[0:3]} kind {b[16]}, "
              f"1 rank {a[0:3]} kind {a[16]}")
        check(max(abs(x - y) for x, y in zip(a, b)) <= 1e-9 * 2 * m_g + 1e-12,
              f"2 ranks: row {b}, 1 rank {a}")
    check({t: float(f[1]) for t, f in split_atoms.items()} == counts,
          f"2 ranks: contact/atom {split_atoms}")
    only_pair, _ = network(ctx, phase="pair", which="pair")
    only_wall, _ = network(ctx, phase="wall", which="wall")
    check(len(only_pair) == 1 and only_pair[0][1] == 2, f"`pair`: rows {only_pair}")
    check(len(only_wall) == 1 and only_wall[0][1] == -1, f"`wall`: rows {only_wall}")


def test_network_bad_input(ctx):
    """An unknown keyword, `history`, and the computes without fix tri/particles stop with an
    error that names them."""
    make_contact_meshes(ctx.work)
    expect_error(ctx, "in.contact_network", {"which": "bogus"},
                 r"Compute tri/contact/local: unknown keyword 'bogus'")
    expect_error(ctx, "in.contact_network", {"which": "history"},
                 r"Compute tri/contact/local: 'history' is not available")
    deck = os.path.join(ctx.work, "in.no_particles")
    with open(deck, "w") as f:
        f.write("units si\natom_style sphere\natom_modify map array\nregion b block 0 1 0 1 0 1\n"
                "create_box 1 b\ncompute ${style} all tri/contact/${style}\n"
                "create_atoms 1 single 0.5 0.5 0.5\nset group all density 1000 diameter 0.1\n"
                "dump d all custom 1 d.dump id c_atom\nrun 0\n")
    expect_error(ctx, deck, {"style": "atom"},
                 r"Compute tri/contact/atom requires fix tri/particles")
