#!/usr/bin/env python3
"""Writes the hopper geometry of examples/hopper as ASCII STL files in meshes/ (metres).
Standard library only.

  funnel.stl   a square funnel: top opening 2*TOP x 2*TOP at z = HEIGHT, outlet 2*OUT x 2*OUT
               at z = 0 (walls at atan((TOP-OUT)/HEIGHT) from the vertical), with a vertical
               square bin of the top opening's size from z = HEIGHT up to z = HEIGHT + BIN
  floor.stl    a square tray that catches the discharge: floor 2*FLOOR x 2*FLOOR at z = FLOOR_Z
               with a rim RIM high, so nothing rolls out of the simulation box
  outlet.stl   the outlet square at z = 0 (for fix massflow/mesh; not a wall)

Dimensions (defaults, metres; particles are about 4 mm across):
  TOP = 0.032, OUT = 0.008 (outlet 16 mm: 4 particle sizes), HEIGHT = 0.06, BIN = 0.07,
  FLOOR = 0.09, FLOOR_Z = -0.08, RIM = 0.02 (the deck's box is 0.2 x 0.2 x 0.23 m).
All wall triangles face the particles (normals pointing into the hopper and up from the floor).
"""
import os
import sys

TOP, OUT, HEIGHT, BIN, FLOOR, FLOOR_Z, RIM = 0.032, 0.008, 0.06, 0.07, 0.09, -0.08, 0.02


def quad(a, b, c, d):
    return [(a, b, c), (a, c, d)]


def funnel():
    tris = []
    corners_top = [(-TOP, -TOP), (TOP, -TOP), (TOP, TOP), (-TOP, TOP)]
    corners_out = [(-OUT, -OUT), (OUT, -OUT), (OUT, OUT), (-OUT, OUT)]
    for k in range(4):
        o0, o1 = corners_out[k], corners_out[(k + 1) % 4]
        t0, t1 = corners_top[k], corners_top[(k + 1) % 4]
        # the funnel walls, seen from inside (counter-clockwise from the axis)
        tris += quad((o0[0], o0[1], 0.0), (t0[0], t0[1], HEIGHT), (t1[0], t1[1], HEIGHT),
                     (o1[0], o1[1], 0.0))
        # the bin walls above
        tris += quad((t0[0], t0[1], HEIGHT), (t0[0], t0[1], HEIGHT + BIN),
                     (t1[0], t1[1], HEIGHT + BIN), (t1[0], t1[1], HEIGHT))
    return tris


def square(half, z):
    return quad((-half, -half, z), (half, -half, z), (half, half, z), (-half, half, z))


def tray():
    tris = square(FLOOR, FLOOR_Z)
    c = [(-FLOOR, -FLOOR), (FLOOR, -FLOOR), (FLOOR, FLOOR), (-FLOOR, FLOOR)]
    for k in range(4):
        a, b = c[k], c[(k + 1) % 4]
        tris += quad((a[0], a[1], FLOOR_Z), (b[0], b[1], FLOOR_Z), (b[0], b[1], FLOOR_Z + RIM),
                     (a[0], a[1], FLOOR_Z + RIM))
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
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "meshes")
    os.makedirs(out, exist_ok=True)
    write(os.path.join(out, "funnel.stl"), funnel(), "funnel")
    write(os.path.join(out, "floor.stl"), tray(), "floor")
    write(os.path.join(out, "outlet.stl"), square(OUT, 0.0), "outlet")
    print(f"wrote funnel.stl, floor.stl, outlet.stl in {out}")
