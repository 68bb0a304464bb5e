#!/usr/bin/env python3
"""Writes a closed drum (a cylinder about the y axis, with end caps) as an ASCII STL, normals
pointing into the drum (the side the particles are on; LIGGGHTS's mesh walls are two-sided).

usage: python3 make_drum.py OUT.stl [RADIUS LENGTH SEGMENTS]   (metres; default 0.03 0.02 48)
"""
import math
import sys


def drum_triangles(radius, length, segments):
    # Rotated by half a segment, so that a flat facet, not an edge, is at the bottom.
    ring = [(radius * math.cos(2 * math.pi * (k + 0.5) / segments),
             radius * math.sin(2 * math.pi * (k + 0.5) / segments)) for k in range(segments)]
    y0, y1 = -0.5 * length, 0.5 * length
    tris = []
    for k in range(segments):
        (x0, z0), (x1, z1) = ring[k], ring[(k + 1) % segments]
        a, b = (x0, y0, z0), (x1, y0, z1)
        c, d = (x1, y1, z1), (x0, y1, z0)
        tris += [(a, b, c), (a, c, d)]                  # mantle
        tris.append(((0.0, y0, 0.0), a, b))             # cap at y0
        tris.append(((0.0, y1, 0.0), c, d))             # cap at y1
    return tris


def write_stl(path, tris):
    def normal(t):
        u = [t[1][i] - t[0][i] for i in range(3)]
        v = [t[2][i] - t[0][i] for i in range(3)]
        n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        s = math.sqrt(sum(c * c for c in n)) or 1.0
        return [c / s for c in n]
    with open(path, "w") as f:
        f.write("solid drum\n")
        for t in tris:
            f.write("  facet normal %.9g %.9g %.9g\n    outer loop\n" % tuple(normal(t)))
            for p in t:
                f.write("      vertex %.9g %.9g %.9g\n" % p)
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid drum\n")


if __name__ == "__main__":
    out = sys.argv[1]
    radius = float(sys.argv[2]) if len(sys.argv) > 2 else 0.03
    length = float(sys.argv[3]) if len(sys.argv) > 3 else 0.02
    segments = int(sys.argv[4]) if len(sys.argv) > 4 else 48
    write_stl(out, drum_triangles(radius, length, segments))
