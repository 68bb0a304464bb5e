"""fix tri/vtk's orientation and torque cell arrays and its wall meshes, read back through VTK
(tri-vtk-dump). Four rocks fall onto a floor that fix move/mesh lifts at 0.05 m/s, under a
static lid; three fix tri/vtk write the same frames with `walls` at its default (every mesh),
`walls lid` and `walls no`. Checked, every 100 steps:
  * orientation (w x y z) and torque of each particle's cells against a dump of f_shapes[2..5]
    and tqx tqy tqz at the same steps (%.17g: equal), with contacts, so torques are not zero;
  * each wall frame: the mesh's triangles (ids ascending) where fix move/mesh has put them
    (floor z = 0.05 t, lid at rest, within 1e-12 m), the cell velocity of the moving floor;
  * the .pvd series: post/p_walls.pvd has one part per mesh and frame, named by the mesh ID;
    walls lid writes only the lid, walls no no wall file;
  * the same deck on 2 MPI ranks writes byte-identical wall files (gathered, ordered by ID).
"""
import glob
import os
import re
import subprocess

from decklib import check, expect_error, run_deck, snapshots, stat, subdir, thermo_rows

DT, EVERY, STEPS, VZ = 1e-5, 100, 600, 0.05
HALF, LID_Z = 0.015, 0.025

DECK = """\
units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
newton          off
communicate     single vel yes
processors      {px} 1 1
region          box block -0.02 0.02 -0.02 0.02 -0.01 0.03 units box
create_box      1 box
neighbor        0.001 bin
neigh_modify    delay 0
timestep        {dt}
create_atoms    1 single -0.005 -0.002 0.0024 units box
create_atoms    1 single 0.005 0.001 0.0026 units box
create_atoms    1 single -0.001 0.004 0.0090 units box
create_atoms    1 single 0.002 -0.004 0.0130 units box
fix shapes all tri/particles shape a random ntri 20 size 0.004 seed 7 &
    shape b random ntri 40 size 0.004 seed 8 assign random 4242 &
    density 2500 epsilon 0.0001 orient random 99
velocity        all set 0.0 0.0 -0.3 units box
fix m1 all property/global kn peratomtypepair 1 2000
fix m2 all property/global kt peratomtypepair 1 1000
fix m3 all property/global gamman peratomtypepair 1 20
fix m4 all property/global gammat peratomtypepair 1 10
fix m5 all property/global coefficientFriction peratomtypepair 1 0.5
pair_style      tri/gran
pair_coeff      * *
fix grav all gravity 9.81 vector 0.0 0.0 -1.0
fix floor all mesh/surface file floor.stl type 1
fix lid all mesh/surface file lid.stl type 1
fix lift all move/mesh mesh floor linear 0.0 0.0 {vz}
fix walls all tri/wall mesh floor lid
fix integr all tri/nve
fix out all tri/vtk every {every} file post/p
fix only_lid all tri/vtk every {every} file post/q walls lid
fix no_walls all tri/vtk every {every} file post/r walls no
compute stats all tri/stats
thermo_style    custom step atoms ke c_stats[{contacts}]
thermo          {every}
dump d all custom {every} spin.dump id tqx tqy tqz f_shapes[2] f_shapes[3] f_shapes[4] f_shapes[5]
dump_modify d sort id format "%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g"
run {steps}
"""


def write_square(path, z, nx=2):
    """A square of side 2 HALF at height z, nx x nx quads, normals up, as ASCII STL."""
    step = 2 * HALF / nx
    with open(path, "w") as f:
        f.write("solid s\n")
        for i in range(nx):
            for j in range(nx):
                x0, y0 = -HALF + i * step, -HALF + j * step
                a, b, c, d = (x0, y0, z), (x0 + step, y0, z), (x0 + step, y0 + step, z), \
                    (x0, y0 + step, z)
                for tri in ((a, b, c), (a, c, d)):
                    f.write(" facet normal 0 0 1\n  outer loop\n")
                    for p in tri:
                        f.write("   vertex %r %r %r\n" % p)
                    f.write("  endloop\n endfacet\n")
        f.write("endsolid s\n")


def write_deck(ctx, work_name, ranks, replace=None):
    """DECK and its meshes in a new folder ctx.work/work_name (with `replace` = (old, new)
    applied to the deck); returns (context of that folder, deck path)."""
    sub = subdir(ctx, work_name)
    write_square(os.path.join(sub.work, "floor.stl"), 0.0)
    write_square(os.path.join(sub.work, "lid.stl"), LID_Z, nx=1)
    deck = DECK.format(px=ranks, dt=DT, vz=VZ, every=EVERY, steps=STEPS,
                       contacts=stat("pairs_in_contact"))
    if replace:
        check(replace[0] in deck, f"no {replace[0]!r} in the deck")
        deck = deck.replace(*replace)
    path = os.path.join(sub.work, "in.walls")
    with open(path, "w") as f:
        f.write(deck)
    return sub, path


def run(ctx, work_name, ranks):
    """Runs DECK on `ranks` ranks in ctx.work/work_name; returns the screen output."""
    sub, deck = write_deck(ctx, work_name, ranks)
    _, out = run_deck(sub, deck, ranks=ranks)
    check("ERROR" not in out, f"{deck}, {ranks} rank(s):\n{out[-3000:]}")
    return out


def cells(vtkdump, path, *arrays):
    p = subprocess.run([vtkdump, path] + list(arrays), stdout=subprocess.PIPE, text=True,
                       check=True)
    return [[float(x) for x in l.split()] for l in p.stdout.splitlines()
            if l and not l.startswith("#")]


def check_particles(vtkdump, work):
    frames = dict(snapshots(os.path.join(work, "spin.dump")))
    check(sorted(frames) == list(range(0, STEPS + 1, EVERY)), f"dump steps {sorted(frames)}")
    largest_torque = 0.0
    for step, atoms in frames.items():
        rows = cells(vtkdump, os.path.join(work, "post", f"p_{step}.vtp"), "id", "torque",
                     "orientation")
        check(rows, f"p_{step}.vtp has no cells")
        for r in rows:
            tag = int(r[0])
            want = [float(x) for x in atoms[tag]]    # tqx tqy tqz qw qx qy qz
            check(r[1:8] == want, f"step {step}, atom {tag}: .vtp torque, orientation "
                                  f"{r[1:8]} != dump {want}")
            largest_torque = max(largest_torque, max(abs(x) for x in want[:3]))
    check(largest_torque > 0, "no torque in any frame: the contacts did not happen")
    return largest_torque


def check_walls(vtkdump, work):
    post = os.path.join(work, "post")
    steps = list(range(0, STEPS + 1, EVERY))
    for step in steps:
        t = step * DT
        for mesh, ntri, z in (("floor", 8, VZ * t), ("lid", 2, LID_Z)):
            path = os.path.join(post, f"p_walls_{mesh}_{step}.vtp")
            check(os.path.exists(path), f"{path} was not written")
            rows = cells(vtkdump, path, "id", "velocity", "points")
            check(len(rows) == ntri, f"{path}: {len(rows)} triangles, the mesh has {ntri}")
            ids = [r[0] for r in rows]
            check(ids == sorted(ids) and len(set(ids)) == ntri, f"{path}: ids {ids}")
            for r in rows:
                # LIGGGHTS sets the node velocities of a moving mesh at its first step: at
                # step 0 (setup) they are still 0.
                vz = VZ if mesh == "floor" and step > 0 else 0.0
                check(all(abs(a - b) < 1e-12 for a, b in zip(r[1:4], (0.0, 0.0, vz))),
                      f"{path}: triangle velocity {r[1:4]}, the mesh moves at (0, 0, {vz})")
                for k in range(3):
                    x, y, zc = r[4 + 3 * k: 7 + 3 * k]
                    check(abs(zc - z) < 1e-12, f"{path}: corner z {zc!r}, mesh at {z!r}")
                    grid = [-HALF + k * 2 * HALF / (ntri // 2) ** 0.5 for k in range(3)]
                    check(min(abs(x - g) for g in grid) < 1e-9 and
                          min(abs(y - g) for g in grid) < 1e-9,
                          f"{path}: corner ({x}, {y}) is not a corner of the mesh file")
    pvd = open(os.path.join(post, "p_walls.pvd")).read()
    entries = re.findall(r'<DataSet timestep="([^"]+)" group="" part="(\d+)" name="(\w+)" '
                         r'file="([^"]+)"/>', pvd)
    want = [(s, part, mesh) for s in steps for part, mesh in ((0, "floor"), (1, "lid"))]
    got = [(round(float(ts) / DT), int(part), name) for ts, part, name, _ in entries]
    check(got == want, f"p_walls.pvd lists {got}, expected {want}")
    check(all(f == f"p_walls_{n}_{round(float(ts) / DT)}.vtp" for ts, _, n, f in entries),
          "p_walls.pvd names other files")
    check(sorted(glob.glob(os.path.join(post, "q_walls_*.vtp"))) ==
          sorted(os.path.join(post, f"q_walls_lid_{s}.vtp") for s in steps),
          "walls lid: wall files other than the lid's")
    check(not glob.glob(os.path.join(post, "r_walls*")), "walls no: wall files were written")
    check(os.path.exists(os.path.join(post, "r.pvd")), "walls no: no particle series")


def test_vtk_walls(ctx):
    out = run(ctx, "np1", 1)
    rows = [r for r in thermo_rows(out) if r["Atoms"] == 4]
    check(rows, "no thermo rows with the 4 particles")
    contacts = max(r["stats.pairs_in_contact"] for r in rows)
    torque = check_particles(ctx.vtkdump, os.path.join(ctx.work, "np1"))
    check_walls(ctx.vtkdump, os.path.join(ctx.work, "np1"))
    print(f"1 rank: orientation and torque equal to the dump in {STEPS // EVERY + 1} "
          f"frames (largest torque {torque:.3g} N m, up to {contacts:.0f} contacts); floor "
          f"and lid frames where move/mesh put them")
    run(ctx, "np2", 2)
    check_walls(ctx.vtkdump, os.path.join(ctx.work, "np2"))
    names = sorted(os.path.basename(p) for p in
                   glob.glob(os.path.join(ctx.work, "np1", "post", "*_walls_*.vtp")))
    check(names, "no wall files on 1 rank")
    for n in names:
        one = open(os.path.join(ctx.work, "np1", "post", n), "rb").read()
        two = open(os.path.join(ctx.work, "np2", "post", n), "rb").read()
        check(one == two, f"{n} differs between 1 and 2 ranks")
    print(f"2 ranks: {len(names)} wall files byte-identical to 1 rank's")
    sub, deck = write_deck(ctx, "bad", 1, ("walls lid", "walls lid grav"))
    line = expect_error(sub, deck, {}, re.escape("Fix tri/vtk: 'walls' expects yes, no or IDs "
                                                 "of fix mesh/surface, got 'grav'"))
    print(f"walls lid grav: {line}")
