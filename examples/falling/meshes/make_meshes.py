#!/usr/bin/env python3
"""Writes the example particle meshes of examples/falling (standard library only).

gear.stl: a gear-like prism, a closed non-convex particle for `shape gear file
meshes/gear.stl scale 0.001`. Coordinates are in millimetres (hence scale 0.001): 8 teeth,
tip radius 2.0 (4 mm across), root radius 1.4, thickness 1.5, centred on the origin.
128 triangles: each cap is a fan of 32 triangles from a centre vertex (the outline is
star-shaped about the centre), and each of the 32 outline segments gives a side rectangle
of 2 triangles. Triangles are counter-clockwise seen from outside (outward normals), and
every shared corner is printed with the same digits so a reader can merge corners exactly.

Run from anywhere:  python3 make_meshes.py   (rewrites the files beside this script)
"""
import math
import os

TEETH = 8
TIP_RADIUS = 2.0  # mm
ROOT_RADIUS = 1.4  # mm
THICKNESS = 1.5  # mm


def gear_outline():
    """Counter-clockwise outline seen from +z: per tooth, root, tip, tip, root."""
    period = 2.0 * math.pi / TEETH
    points = []
    for i in range(TEETH):
        for fraction, radius in ((0.0, ROOT_RADIUS), (0.25, TIP_RADIUS),
                                 (0.5, TIP_RADIUS), (0.75, ROOT_RADIUS)):
            angle = (i + fraction) * period
            points.append((radius * math.cos(angle), radius * math.sin(angle)))
    return points


def prism(outline, thickness):
    """Vertices and outward triangles of the prism over a star-shaped outline."""
    n = len(outline)
    z0, z1 = -0.5 * thickness, 0.5 * thickness
    vertices = [(x, y, z0) for x, y in outline] + [(x, y, z1) for x, y in outline]
    bottom_centre, top_centre = 2 * n, 2 * n + 1
    vertices += [(0.0, 0.0, z0), (0.0, 0.0, z1)]
    triangles = []
    for i in range(n):
        j = (i + 1) % n
        triangles.append((i, j, n + j))  # side, outward
        triangles.append((i, n + j, n + i))
        triangles.append((top_centre, n + i, n + j))  # top, +z
        triangles.append((bottom_centre, j, i))  # bottom, -z
    return vertices, triangles


def normal(a, b, c):
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    length = math.sqrt(sum(x * x for x in n))
    return tuple(x / length for x in n)


def signed_volume(vertices, triangles):
    total = 0.0
    for t in triangles:
        a, b, c = (vertices[k] for k in t)
        total += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                  + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0
    return total


def write_ascii_stl(path, name, vertices, triangles):
    def fmt(x):
        s = "%.6f" % x
        return "0.000000" if s == "-0.000000" else s

    with open(path, "w") as out:
        out.write("solid %s\n" % name)
        for t in triangles:
            a, b, c = (vertices[k] for k in t)
            out.write("  facet normal %s\n    outer loop\n" % " ".join(fmt(x) for x in normal(a, b, c)))
            for p in (a, b, c):
                out.write("      vertex %s\n" % " ".join(fmt(x) for x in p))
            out.write("    endloop\n  endfacet\n")
        out.write("endsolid %s\n" % name)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    vertices, triangles = prism(gear_outline(), THICKNESS)
    assert signed_volume(vertices, triangles) > 0.0, "triangles must face outward"
    write_ascii_stl(os.path.join(here, "gear.stl"), "gear", vertices, triangles)
    print("gear.stl: %d triangles, volume %.4f mm^3" % (len(triangles), signed_volume(vertices, triangles)))


if __name__ == "__main__":
    main()
