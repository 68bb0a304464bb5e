#!/usr/bin/env python3
"""Closed, outward-oriented triangle meshes for the validation decks, written as ASCII STL.
Standard library only, so every validation script (and plain python3) can import it.

  python3 meshgen.py icosphere LEVEL RADIUS out.stl   # 20 * 4**LEVEL triangles
  python3 meshgen.py cube N SIDE out.stl              # N x N squares per face: 12 N^2 triangles
  python3 meshgen.py plane HALF_WIDTH out.stl [N]     # a square at z = 0, normal +z: 2 N^2 triangles
  python3 meshgen.py platonic NAME D out.stl          # tetrahedron cube octahedron dodecahedron
                                                      # icosahedron, volume-equivalent diameter D
  python3 meshgen.py icosphere_eq LEVEL D out.stl     # an icosphere of volume-equivalent diameter D
"""
import math
import sys


def icosphere(level, radius):
    t = (1.0 + math.sqrt(5.0)) / 2.0
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t),
         (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    v = [tuple(c / math.sqrt(sum(x * x for x in p)) for c in p) for p in v]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
         (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(level):
        mid = {}

        def midpoint(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                p = [(x + y) / 2 for x, y in zip(v[a], v[b])]
                n = math.sqrt(sum(x * x for x in p))
                v.append(tuple(x / n for x in p))
                mid[key] = len(v) - 1
            return mid[key]

        nf = []
        for a, b, c in f:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            nf += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        f = nf
    return [tuple(radius * x for x in p) for p in v], f


def mass_inertia(verts, faces, density):
    """Mass and the mean of the three moments of inertia about the origin's axes (for an
    icosphere centred at the origin: about any axis through its centre) of the closed mesh
    (verts, faces) of uniform density: signed tetrahedra from the origin."""
    volume, second = 0.0, [0.0, 0.0, 0.0]  # integral of x_k^2 dV
    for f in faces:
        a, b, c = (verts[i] for i in f)
        vol = (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
               a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0
        volume += vol
        for k in range(3):
            x0, x1, x2 = a[k], b[k], c[k]
            second[k] += vol / 10.0 * (x0 * x0 + x1 * x1 + x2 * x2 + x0 * x1 + x1 * x2 + x0 * x2)
    inertia = (2.0 * sum(second)) / 3.0  # mean of I_xx, I_yy, I_zz = (sum of pairs) / 3
    return density * volume, density * inertia


def cube(n, side):
    """Each face an n x n grid of squares, two triangles each; centred at the origin."""
    verts, index, faces = [], {}, []

    def vid(p):
        key = tuple(round(c * 2 * n) for c in p)  # exact grid coordinates in units of side/2n
        if key not in index:
            index[key] = len(verts)
            verts.append(tuple(side * c for c in p))
        return index[key]

    h = 0.5
    for axis in range(3):
        for sign in (-1, 1):
            u, w = (axis + 1) % 3, (axis + 2) % 3
            for i in range(n):
                for j in range(n):
                    def corner(a, b):
                        p = [0.0, 0.0, 0.0]
                        p[axis] = sign * h
                        p[u] = -h + (i + a) / n
                        p[w] = -h + (j + b) / n
                        return vid(p)
                    faces += _square(corner, sign)
    return verts, faces


def _square(corner, sign):
    """Two triangles of the square corner(0, 0) .. corner(1, 1) in the (u, w) plane of an
    axis-aligned face, facing +axis for sign > 0: (u, w, axis) is right-handed, so u x w points
    along +axis."""
    c00, c10, c11, c01 = corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)
    if sign > 0:
        return [(c00, c10, c11), (c00, c11, c01)]
    return [(c00, c11, c10), (c00, c01, c11)]


def plane(half, n=1):
    """A square [-half, half]^2 at z = 0, normal +z: an n x n grid of squares, 2 n^2 triangles."""
    if n == 1:
        v = [(-half, -half, 0.0), (half, -half, 0.0), (half, half, 0.0), (-half, half, 0.0)]
        return v, [(0, 1, 2), (0, 2, 3)]
    v = [(-half + 2 * half * i / n, -half + 2 * half * j / n, 0.0)
         for j in range(n + 1) for i in range(n + 1)]
    f = []
    for j in range(n):
        for i in range(n):
            c00, c10 = j * (n + 1) + i, j * (n + 1) + i + 1
            c01, c11 = c00 + n + 1, c10 + n + 1
            f += [(c00, c10, c11), (c00, c11, c01)]
    return v, f


def voxels(cells, side):
    """The boundary of a union of cubes of edge `side` at integer cells (i, j, k): each exposed
    cube face two triangles, outward. Cells that touch only along an edge or at a corner would
    make it non-manifold; the shapes here (jacks, U shapes) share whole faces."""
    cells = set(map(tuple, cells))
    verts, index, faces = [], {}, []

    def vid(p):
        if p not in index:
            index[p] = len(verts)
            verts.append(tuple(side * c for c in p))
        return index[p]

    for cell in sorted(cells):
        for axis in range(3):
            for sign in (-1, 1):
                nb = list(cell)
                nb[axis] += sign
                if tuple(nb) in cells:
                    continue
                u, w = (axis + 1) % 3, (axis + 2) % 3

                def corner(a, b):
                    p = list(cell)
                    p[axis] += 1 if sign > 0 else 0
                    p[u] += a
                    p[w] += b
                    return vid(tuple(p))
                faces += _square(corner, sign)
    return verts, faces


def volume(verts, faces):
    """Volume of a closed, outward-oriented mesh (signed tetrahedra from the origin)."""
    return mass_inertia(verts, faces, 1.0)[0]


def volume_equivalent(verts, faces, diameter):
    """The mesh scaled about the origin to the volume of a sphere of the given diameter."""
    k = (math.pi / 6.0 * diameter ** 3 / volume(verts, faces)) ** (1.0 / 3.0)
    return [tuple(k * c for c in p) for p in verts], faces


def _outward(verts, faces):
    """Faces of a convex mesh containing the origin, each turned so its normal points away from
    the origin."""
    out = []
    for a, b, c in faces:
        pa, pb, pc = verts[a], verts[b], verts[c]
        e1 = [pb[k] - pa[k] for k in range(3)]
        e2 = [pc[k] - pa[k] for k in range(3)]
        n = (e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
             e1[0] * e2[1] - e1[1] * e2[0])
        cen = [(pa[k] + pb[k] + pc[k]) / 3.0 for k in range(3)]
        out.append((a, b, c) if sum(n[k] * cen[k] for k in range(3)) > 0 else (a, c, b))
    return out


def platonic(name, circumradius=1.0):
    """A Platonic solid centred at the origin with its vertices at `circumradius`: tetrahedron
    (4 triangles), cube (12), octahedron (8), dodecahedron (12 pentagons, fanned: 36),
    icosahedron (20)."""
    if name == "tetrahedron":
        v = [(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]
        f = [(0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)]
    elif name == "cube":
        v, f = cube(1, 2.0)
    elif name == "octahedron":
        v = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
        f = [(x, y, z) for x in (0, 1) for y in (2, 3) for z in (4, 5)]
    elif name == "icosahedron":
        v, f = icosphere(0, 1.0)
    elif name == "dodecahedron":
        # the dual of the icosahedron: a vertex at each face centre, a pentagon around each vertex
        iv, iface = icosphere(0, 1.0)
        v = [tuple(sum(iv[i][k] for i in tri) / 3.0 for k in range(3)) for tri in iface]
        f = []
        for j, p in enumerate(iv):
            ring = [k for k, tri in enumerate(iface) if j in tri]
            # order the 5 face centres by angle about the axis p
            u = [v[ring[0]][k] - p[k] for k in range(3)]
            w = (p[1] * u[2] - p[2] * u[1], p[2] * u[0] - p[0] * u[2], p[0] * u[1] - p[1] * u[0])
            ring.sort(key=lambda k: math.atan2(sum((v[k][i] - p[i]) * w[i] for i in range(3)),
                                               sum((v[k][i] - p[i]) * u[i] for i in range(3))))
            f += [(ring[0], ring[i], ring[i + 1]) for i in range(1, 4)]
    else:
        raise ValueError("unknown Platonic solid " + name)
    r = max(math.sqrt(sum(c * c for c in p)) for p in v)
    v = [tuple(circumradius * c / r for c in p) for p in v]
    return v, _outward(v, f)


def write_stl(path, verts, faces, name="mesh"):
    with open(path, "w") as out:
        out.write(f"solid {name}\n")
        for a, b, c in faces:
            pa, pb, pc = verts[a], verts[b], verts[c]
            e1 = [pb[k] - pa[k] for k in range(3)]
            e2 = [pc[k] - pa[k] for k in range(3)]
            nrm = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                   e1[0] * e2[1] - e1[1] * e2[0]]
            ln = math.sqrt(sum(x * x for x in nrm)) or 1.0
            out.write(" facet normal %.9g %.9g %.9g\n  outer loop\n" % tuple(x / ln for x in nrm))
            for p in (pa, pb, pc):
                out.write("   vertex %.17g %.17g %.17g\n" % p)
            out.write("  endloop\n endfacet\n")
        out.write(f"endsolid {name}\n")


if __name__ == "__main__":
    kind = sys.argv[1]
    if kind == "icosphere":
        write_stl(sys.argv[4], *icosphere(int(sys.argv[2]), float(sys.argv[3])), "icosphere")
    elif kind == "cube":
        write_stl(sys.argv[4], *cube(int(sys.argv[2]), float(sys.argv[3])), "cube")
    elif kind == "plane":
        write_stl(sys.argv[3], *plane(float(sys.argv[2]),
                                      int(sys.argv[4]) if len(sys.argv) > 4 else 1), "plane")
    elif kind == "platonic":
        write_stl(sys.argv[4], *volume_equivalent(*platonic(sys.argv[2]), float(sys.argv[3])),
                  sys.argv[2])
    elif kind == "icosphere_eq":
        write_stl(sys.argv[4], *volume_equivalent(*icosphere(int(sys.argv[2]), 1.0),
                                                  float(sys.argv[3])), "icosphere")
    else:
        sys.exit(__doc__)
