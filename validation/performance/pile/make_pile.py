#!/usr/bin/env python3
"""Writes the container of the pile benchmark (validation/performance/pile) as ASCII STL, metres.
Standard library only.

  box_n<N>.stl   an open square box for an N x N x N lattice of particles 4.5 mm apart: floor
                 2*W x 2*W at z = 0 and four walls H high, W = N * 4.5 mm / 2 + 1.5 mm, H = 60 mm.
                 Five quads, ten triangles, every normal pointing into the box.

  make_pile.py [DIR]      writes box_n8.stl (512 particles) and box_n10.stl (1000) into DIR
                          (default: meshes/ beside this script)
"""
import os
import sys

SPACING = 0.0045
HEIGHT = 0.06


def half_width(n):
    return n * SPACING / 2 + 0.0015


def quad(a, b, c, d):
    return [(a, b, c), (a, c, d)]


def box(n):
    w, h = half_width(n), HEIGHT
    c = [(-w, -w), (w, -w), (w, w), (-w, w)]
    tris = quad((-w, -w, 0.0), (w, -w, 0.0), (w, w, 0.0), (-w, w, 0.0))  # floor, normal +z
    for k in range(4):
        a, b = c[k], c[(k + 1) % 4]
        # side wall from a to b (counter-clockwise seen from above): normal points inwards
        tris += quad((a[0], a[1], 0.0), (a[0], a[1], h), (b[0], b[1], h), (b[0], b[1], 0.0))
    return tris


def write(path, tris, name):
    with open(path, "w") as f:
        f.write(f"solid {name}\n")
        for a, b, c in tris:
            f.write(" facet normal 0 0 0\n  outer loop\n")
            for p in (a, b, c):
                f.write("   vertex %.9g %.9g %.9g\n" % p)
            f.write("  endloop\n endfacet\n")
        f.write(f"endsolid {name}\n")


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "meshes")
    os.makedirs(out, exist_ok=True)
    for n in (8, 10):
        write(os.path.join(out, f"box_n{n}.stl"), box(n), f"box_n{n}")
    print(f"wrote box_n8.stl, box_n10.stl in {out}")
