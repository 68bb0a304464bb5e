#!/usr/bin/python3
"""Sphere limit of the packing (issue 4, case 5): 90 icospheres (level 2, 320 triangles)
poured into a box with fix tri/wall against the same pour of LIGGGHTS spheres.

  /usr/bin/python3 validation/contact/sphere_limit/run_sphere_limit.py \
      [--exe liggghts-tri] [--liggghts /usr/bin/liggghts] [--out DIR] \
      [--tri-seeds 3] [--sphere-seeds 20] [--reuse] [--layer inside|outside]

Runs in.tri (liggghts-tri) and in.sphere (LIGGGHTS's own liggghts) from the same lattice, the
same initial velocities (velocity seeds 0, 1, 2), the same material, walls and time step; the
spheres also with seeds 3 to 5. The spread over seeds is the run-to-run noise of a
90-particle packing. Writes sphere_limit.png next to this script and prints the tables of
README.md. About 4 min per icosphere run, 1 s per sphere run, on the 2-core machine.

Particle size. An icosphere's vertices lie at R = 2 mm; its faces at 0.982 R to 0.985 R. With
the soft layer (epsilon = 0.05 mm) inside the mesh (the default) the mesh is the contact
surface (its edges and corners rounded with radius epsilon, a change of its volume of order
1e-5): the body that packs is the icosphere itself. The twin sphere has the mesh's volume,
R_s = (3 V_mesh / 4 pi)^(1/3) = R_mesh,v = 1.9772 mm, so both packings have the same solid
volume per particle and the same mass (the sphere density is set so): their solid fractions
differ exactly as their number densities. A second sphere packing with R_s = R = 2 mm (the
vertices' sphere, the bounding radius) is reported for comparison. Walls: fix tri/wall's mesh
has no layer of its own, so the icospheres touch the walls at the STL box, as the spheres do.
With `--layer outside` (the earlier convention) contact starts where the layers outside the
meshes touch: the body that packs is the icosphere grown by epsilon (its Minkowski sum with a
ball of radius epsilon, the "envelope"), the twin sphere has the envelope's volume,
R_env,v = 2.0274 mm, the comparison sphere R + epsilon, and the walls take the particles'
epsilon, so the spheres' STL is the box shrunk by epsilon on every face.

Solid fraction. Every particle is counted as a sphere of its envelope volume at its centre of
mass (exact for the spheres; for the icospheres the radius varies by +-0.9 % over the surface,
which only affects how a particle cut by the region boundary is split). phi(z) = sum of the
sphere-slab intersection volumes / (box cross-section * slab height); the central measurement
region is the full cross-section between z = 1 and z = 5 sphere diameters above the floor.
"""
import argparse
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "validation", "meshes"))
sys.path.insert(0, os.path.join(ROOT, "validation"))
import meshgen  # noqa: E402
import valtools  # noqa: E402

R, LEVEL, EPS, DENSITY = 0.002, 2, 5e-5, 2500.0
HALF, HEIGHT = 0.008, 0.060       # box: x, y in [-HALF, HALF], z in [0, HEIGHT]
DT, STEPS = 1e-5, 25000           # 0.25 s: fall (0.1 s) and settle
TARGET = 0.02                     # relative difference of the solid fractions


def envelope(level, radius, eps):
    """Mesh volume and the volume of the mesh grown by eps (Steiner: V + S eps + M eps^2 +
    4/3 pi eps^3, M = 1/2 sum over edges of length x exterior angle)."""
    v, f = meshgen.icosphere(level, radius)
    v, f = np.array(v), np.array(f)
    a, b, c = v[f[:, 0]], v[f[:, 1]], v[f[:, 2]]
    n = np.cross(b - a, c - a)
    area = 0.5 * np.linalg.norm(n, axis=1)
    n /= np.linalg.norm(n, axis=1)[:, None]
    vol = np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0
    faces_of = {}
    for k, tri in enumerate(f):
        for e in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])):
            faces_of.setdefault(tuple(sorted(e)), []).append(k)
    m = 0.0
    for (i, j), (p, q) in faces_of.items():
        m += 0.5 * np.linalg.norm(v[i] - v[j]) * math.acos(max(-1.0, min(1.0, n[p] @ n[q])))
    return vol, vol + area.sum() * eps + m * eps ** 2 + 4.0 / 3.0 * math.pi * eps ** 3


def run(exe, deck, variables, log, threads=1):
    cmd = valtools.run_deck(exe, deck, variables, HERE, log, threads, exit_on_error=True)
    return " ".join(cmd), loop_time(log)


def loop_time(log):
    """LIGGGHTS's 'Loop time of X' (s) from a run's screen output; nan if absent."""
    sec = float("nan")
    try:
        for l in open(log):
            if l.startswith("Loop time of"):
                sec = float(l.split()[3])
    except (OSError, ValueError, IndexError):
        pass
    return sec


def read_dump(path):
    with open(path) as f:
        lines = f.readlines()
    n = int(lines[3])
    cols = lines[8].split()[2:]
    data = np.array([[float(x) for x in l.split()] for l in lines[9:9 + n]])
    return {c: data[:, i] for i, c in enumerate(cols)}


def slab_volume(zc, r, z1, z2):
    """Volume of the spheres (centres zc, radius r) between the planes z1 < z2."""
    a = np.clip(z1 - zc, -r, r)
    b = np.clip(z2 - zc, -r, r)
    prim = lambda s: r * r * s - s ** 3 / 3.0  # noqa: E731
    return np.pi * (prim(b) - prim(a))


def measure(dump, r_solid, z_lo, z_hi, edges):
    d = read_dump(dump)
    z = d["z"]
    area = (2 * HALF) ** 2
    phi = slab_volume(z, r_solid, z_lo, z_hi).sum() / (area * (z_hi - z_lo))
    prof = np.array([slab_volume(z, r_solid, lo, hi).sum() / (area * (hi - lo))
                     for lo, hi in zip(edges[:-1], edges[1:])])
    speed = np.sqrt(d["vx"] ** 2 + d["vy"] ** 2 + d["vz"] ** 2)
    top = (z + r_solid).max()
    return dict(phi=phi, prof=prof, vmax=speed.max(), top=top, n=len(z))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", default=os.path.join(ROOT, "build-val2", "src_plugin", "driver",
                                                  "liggghts-tri"))
    ap.add_argument("--liggghts", default="/usr/bin/liggghts")
    ap.add_argument("--out", default="/tmp/tri_validation/sphere_limit")
    ap.add_argument("--sphere-seeds", type=int, default=20)
    ap.add_argument("--tri-seeds", type=int, default=3)
    ap.add_argument("--reuse", action="store_true",
                    help="keep the runs whose final.dump is already in --out (deterministic)")
    ap.add_argument("--layer", default="inside", choices=("inside", "outside"),
                    help="fix tri/particles layer (default inside: the mesh is the contact surface)")
    a = ap.parse_args()
    inside = a.layer == "inside"
    if not inside:
        a.out = os.path.join(a.out, "outside")
    os.makedirs(a.out, exist_ok=True)

    box = os.path.join(a.out, "box.stl")
    v, f = meshgen.cube(1, 1.0)
    v = [(2 * HALF * x, 2 * HALF * y, HEIGHT * (z + 0.5)) for x, y, z in v]
    meshgen.write_stl(box, v, f, "box")
    # Layer inside (default): fix tri/wall's mesh has no layer, the icospheres touch the walls
    # at the STL box, as the spheres do. Layer outside: the wall takes the particles' epsilon,
    # so an icosphere's envelope touches a wall when it is epsilon INSIDE the STL; the spheres
    # get the same contact planes from the same box shrunk by epsilon on every face.
    box_sphere = box
    if not inside:
        box_sphere = os.path.join(a.out, "box_sphere.stl")
        v, f = meshgen.cube(1, 1.0)
        v = [((2 * HALF - 2 * EPS) * x, (2 * HALF - 2 * EPS) * y,
              EPS + (HEIGHT - 2 * EPS) * (z + 0.5)) for x, y, z in v]
        meshgen.write_stl(box_sphere, v, f, "box_sphere")
    particle = os.path.join(a.out, "icosphere.stl")
    meshgen.write_stl(particle, *meshgen.icosphere(LEVEL, R), "icosphere")

    v_mesh, v_env = envelope(LEVEL, R, EPS)
    mass = DENSITY * v_mesh
    # the twin sphere (r_env: the volume of the body that packs) and the comparison sphere
    # (r_vertex: the vertices' sphere); the names are the earlier convention's
    if inside:
        r_env = (3.0 * v_mesh / (4.0 * math.pi)) ** (1.0 / 3.0)
        r_vertex = R
        name_v, name_r = "R_mesh,v", "R"
    else:
        r_env = (3.0 * v_env / (4.0 * math.pi)) ** (1.0 / 3.0)
        r_vertex = R + EPS
        name_v, name_r = "R_env,v", "R + eps"
    d_env = 2 * r_env
    z_lo, z_hi = 1.0 * d_env, 5.0 * d_env
    edges = np.arange(0.0, 0.032 + 1e-12, 0.0005)
    common = dict(box=box, dt=DT, steps=STEPS)

    def once(exe, deck, out, variables):
        """Runs a deck into `out` unless --reuse and its final.dump is there already."""
        os.makedirs(out, exist_ok=True)
        dump = os.path.join(out, "final.dump")
        if a.reuse and os.path.exists(dump):
            cmd = [exe, "-in", deck, "-log", "none"] + [f"-var {k} {v}" for k, v in
                                                        variables.items()]
            return " ".join(cmd) + "  (reused)", loop_time(os.path.join(out, "log")), dump
        c, sec = run(exe, deck, variables, os.path.join(out, "log"))
        return c, sec, dump

    runs = []  # (label, seed, r_solid, dump, command, seconds)
    for seed in range(a.tri_seeds):
        c, sec, dump = once(a.exe, "in.tri", os.path.join(a.out, f"tri_seed{seed}"),
                            dict(out=os.path.join(a.out, f"tri_seed{seed}"), particle=particle,
                                 seed=seed, layer=a.layer, **common))
        runs.append(("icospheres (tri/gran)", seed, r_env, dump, c, sec))
    cmd_tri = runs[0][4]
    cmd_sph = None
    for label, rs in (("spheres R_s = " + name_v, r_env), ("spheres R_s = " + name_r, r_vertex)):
        seeds = range(a.sphere_seeds) if rs == r_env else range(1)
        for seed in seeds:
            out = os.path.join(a.out, f"sphere_{rs * 1e6:.0f}um_seed{seed}")
            rho = mass / (4.0 / 3.0 * math.pi * rs ** 3)
            c, sec, dump = once(a.liggghts, "in.sphere", out,
                                dict(out=out, ds=2 * rs, rhos=rho, seed=seed,
                                     **dict(common, box=box_sphere)))
            cmd_sph = cmd_sph or c
            runs.append((label, seed, rs, dump, c, sec))

    res = [(lab, seed, rs, measure(dump, rs, z_lo, z_hi, edges), sec)
           for lab, seed, rs, dump, _, sec in runs]
    tris = [r for r in res if r[0].startswith("icospheres")]
    sph = [r for r in res if r[0] == "spheres R_s = " + name_v]
    tri = tris[0]
    ref = [r for r in sph if r[1] == 0][0]
    spread = np.array([r[3]["phi"] for r in sph])
    tri_phi = np.array([r[3]["phi"] for r in tris])

    print(valtools.machine_line(cores=True))
    print(f"icosphere level {LEVEL}: R = {R * 1e3:g} mm, epsilon = {EPS * 1e3:g} mm (layer "
          f"{a.layer}), mesh volume {v_mesh * 1e9:.4f} mm^3, envelope volume "
          f"{v_env * 1e9:.4f} mm^3, mass {mass:.4g} kg")
    print(f"{name_v} = {r_env * 1e3:.4f} mm, {name_r} = {r_vertex * 1e3:.4f} mm; region z in "
          f"[{z_lo * 1e3:.2f}, {z_hi * 1e3:.2f}] mm, cross-section {2 * HALF * 1e3:g} x "
          f"{2 * HALF * 1e3:g} mm; dt = {DT:g} s, {STEPS} steps")
    print()
    print("| packing | velocity seed | solid radius (mm) | solid fraction phi | bed top (mm) "
          "| max speed at end (m/s) | loop time (s) |")
    print("|---|---|---|---|---|---|---|")
    for lab, seed, rs, m, sec in res:
        print(f"| {lab} | {seed} | {rs * 1e3:.4f} | {m['phi']:.4f} | {m['top'] * 1e3:.2f} | "
              f"{m['vmax']:.2g} | {sec:.1f} |")
    print()
    print("| comparison (solid fractions in the region) | measured | target | result |")
    print("|---|---|---|---|")
    for t in tris:
        twin = [r for r in sph if r[1] == t[1]]
        if not twin:
            continue
        d = t[3]["phi"] / twin[0][3]["phi"] - 1.0
        ok = "pass" if abs(d) <= TARGET else "FAIL"
        print(f"| seed {t[1]}: phi icospheres / phi spheres ({name_v}) - 1 | "
              f"{t[3]['phi']:.4f} / {twin[0][3]['phi']:.4f} - 1 = {100 * d:+.2f} % "
              f"| within +-2 % | {ok} |")
    d = tri_phi.mean() / spread.mean() - 1.0
    ok = "pass" if abs(d) <= TARGET else "FAIL"
    sd = spread.std(ddof=1) if len(spread) > 1 else 0.0
    sd_tri = tri_phi.std(ddof=1) if len(tri_phi) > 1 else 0.0
    se = math.sqrt(sd_tri ** 2 / len(tri_phi) + sd ** 2 / len(spread)) / spread.mean()
    print(f"| mean over seeds: icospheres ({len(tri_phi)}) / spheres {name_v} ({len(spread)}) - 1 | "
          f"{tri_phi.mean():.4f} / {spread.mean():.4f} - 1 = {100 * d:+.2f} % "
          f"(+- {100 * se:.2f} %, 1 standard error) | within +-2 % | {ok} |")
    print(f"| spread of the icosphere packings over {len(tri_phi)} seeds (std / mean) | "
          f"{100 * sd_tri / tri_phi.mean():.2f} % | - | - |")
    print(f"| spread of the sphere packings over {len(spread)} seeds (std / mean) | "
          f"{100 * sd / spread.mean():.2f} % | (noise of a 90-particle bed) | - |")
    rv = [r for r in res if r[0] == "spheres R_s = " + name_r][0]
    d = tri[3]["phi"] / rv[3]["phi"] - 1.0
    print(f"| seed 0: phi icospheres / phi spheres ({name_r}) - 1, each by its own volume | "
          f"{tri[3]['phi']:.4f} / {rv[3]['phi']:.4f} - 1 = {100 * d:+.2f} % "
          f"| (choice of R_s) | - |")
    print()
    print("commands:")
    print("  " + cmd_tri)
    print("  " + cmd_sph)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    zc = 0.5 * (edges[:-1] + edges[1:]) * 1e3
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 5), gridspec_kw=dict(width_ratios=[3, 2]))
    for lab, seed, rs, m, _ in res:
        if lab == "spheres R_s = " + name_v and seed != 0:
            ax.plot(m["prof"], zc, color="0.75", lw=0.7,
                    label=f"spheres {name_v}, other seeds" if seed == 1 else None)
    ax.plot(ref[3]["prof"], zc, color="C0", lw=1.6, label=f"spheres {name_v}, seed 0")
    rv = [r for r in res if r[0] == "spheres R_s = " + name_r][0]
    ax.plot(rv[3]["prof"], zc, color="C2", lw=1.0, ls="--", label=f"spheres {name_r}, seed 0")
    for t in tris[1:]:
        ax.plot(t[3]["prof"], zc, color="C3", lw=0.8, ls=":",
                label=f"icospheres (tri/gran), seed {t[1]}")
    ax.plot(tri[3]["prof"], zc, color="C3", lw=1.6, label="icospheres (tri/gran), seed 0")
    ax.axhspan(z_lo * 1e3, z_hi * 1e3, color="C1", alpha=0.12, label="measurement region")
    ax.set_xlabel("solid fraction (0.5 mm slabs, full cross-section)")
    ax.set_ylabel("height above the floor (mm)")
    ax.set_title(f"90 particles poured in a {2 * HALF * 1e3:g} mm box, seed 0: "
                 f"phi = {tri[3]['phi']:.3f} (icospheres) vs {ref[3]['phi']:.3f} (spheres)",
                 fontsize=10)
    ax.set_xlim(0, 0.8)
    ax.set_ylim(0, 30)
    ax.legend(fontsize=8, loc="upper right")
    # right: the region's solid fraction per velocity seed
    bx.axhspan(spread.mean() * (1 - TARGET), spread.mean() * (1 + TARGET), color="C0",
               alpha=0.12, label="sphere mean +-2 %")
    bx.plot([r[1] for r in sph], [r[3]["phi"] for r in sph], "o", color="C0",
            label=f"spheres {name_v}")
    bx.plot([r[1] for r in tris], [r[3]["phi"] for r in tris], "s", color="C3", mfc="none",
            ms=9, label="icospheres (tri/gran)")
    bx.axhline(spread.mean(), color="C0", lw=0.8, ls="--", label="mean, spheres")
    bx.axhline(tri_phi.mean(), color="C3", lw=0.8, ls="--", label="mean, icospheres")
    bx.set_xlabel("velocity seed")
    bx.set_ylabel("solid fraction in the measurement region")
    bx.set_title("same lattice, same initial velocities per seed", fontsize=10)
    bx.legend(fontsize=8)
    fig.tight_layout()
    png = os.path.join(HERE, "sphere_limit.png" if inside else "sphere_limit_outside.png")
    fig.savefig(png, dpi=110)
    print(f"plot: {png}")


if __name__ == "__main__":
    main()
