#!/usr/bin/env python3
"""Writes the seed corpus of the fuzz targets into tests/fuzz/corpus/<target>/.

Run again after changing an input encoding (fuzz_common.h and the targets' headers); the
files are committed, so run-fuzz.sh needs no Python. Standard library only.
"""
import os
import random
import struct

HERE = os.path.dirname(os.path.abspath(__file__))

# A tetrahedron and a unit cube, counter-clockwise seen from outside.
TET_V = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TET_F = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
CUBE_V = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
CUBE_F = [(0, 2, 1), (1, 2, 3), (4, 5, 6), (5, 7, 6), (0, 1, 4), (1, 5, 4),
          (2, 6, 3), (3, 6, 7), (0, 4, 2), (2, 4, 6), (1, 3, 5), (3, 7, 5)]


def normal(v, f):
    a, b, c = (v[i] for i in f)
    u = [b[k] - a[k] for k in range(3)]
    w = [c[k] - a[k] for k in range(3)]
    return (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])


def ascii_stl(v, f, name="seed"):
    lines = [f"solid {name}"]
    for t in f:
        lines.append("  facet normal %g %g %g" % normal(v, t))
        lines.append("    outer loop")
        for i in t:
            lines.append("      vertex %g %g %g" % v[i])
        lines.append("    endloop")
        lines.append("  endfacet")
    lines.append(f"endsolid {name}")
    return ("\n".join(lines) + "\n").encode()


def binary_stl(v, f, header=b"binary seed"):
    out = header.ljust(80, b" ")[:80] + struct.pack("<I", len(f))
    for t in f:
        out += struct.pack("<3f", *normal(v, t))
        for i in t:
            out += struct.pack("<3f", *v[i])
        out += b"\0\0"
    return out


def obj(v, f):
    text = "# seed\n" + "".join("v %g %g %g\n" % p for p in v)
    text += "".join("f %d %d %d\n" % tuple(i + 1 for i in t) for t in f)
    return text.encode()


def ascii_ply(v, f):
    head = ("ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
            "property float z\nelement face %d\nproperty list uchar int vertex_indices\n"
            "end_header\n" % (len(v), len(f)))
    body = "".join("%g %g %g\n" % p for p in v) + "".join("3 %d %d %d\n" % t for t in f)
    return (head + body).encode()


def binary_ply(v, f):
    head = ("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\n"
            "property float y\nproperty float z\nelement face %d\n"
            "property list uchar int vertex_indices\nend_header\n" % (len(v), len(f)))
    body = b"".join(struct.pack("<3f", *p) for p in v)
    body += b"".join(struct.pack("<B3i", 3, *t) for t in f)
    return head.encode() + body


def write(target, name, data):
    d = os.path.join(HERE, "corpus", target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as fh:
        fh.write(data)


def mesh_seeds():
    cube_ascii = ascii_stl(CUBE_V, CUBE_F)
    cube_binary = binary_stl(CUBE_V, CUBE_F)
    write("fuzz_stl", "tet_ascii", ascii_stl(TET_V, TET_F))
    write("fuzz_stl", "cube_ascii", cube_ascii)
    write("fuzz_stl", "tet_binary", binary_stl(TET_V, TET_F))
    write("fuzz_stl", "cube_binary", cube_binary)
    write("fuzz_stl", "binary_header_says_solid", binary_stl(TET_V, TET_F, b"solid but binary"))
    write("fuzz_stl", "ascii_truncated", cube_ascii[: len(cube_ascii) // 2])
    write("fuzz_stl", "binary_truncated", cube_binary[:-20])
    write("fuzz_stl", "ascii_open_mesh", ascii_stl(TET_V, TET_F[:3]))
    write("fuzz_stl", "ascii_big_numbers", ascii_stl([(1e30, 0, 0)] + TET_V[1:], TET_F))

    write("fuzz_obj", "tet", obj(TET_V, TET_F))
    write("fuzz_obj", "cube", obj(CUBE_V, CUBE_F))
    quads = ("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
             "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n")
    write("fuzz_obj", "cube_quads", quads.encode())
    write("fuzz_obj", "slashes_and_normals",
          b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\nvt 0 0\n"
          b"f 1/1/1 3/1/1 2/1/1\nf 1//1 2//1 4//1\nf 1 4 3\nf 2 3 4\n")
    write("fuzz_obj", "negative_indices", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
          b"f -4 -2 -3\nf -4 -3 -1\nf -4 -1 -2\nf -3 -2 -1\n")
    write("fuzz_obj", "missing_vertex", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")
    write("fuzz_obj", "truncated", obj(CUBE_V, CUBE_F)[:150])

    write("fuzz_ply", "tet_ascii", ascii_ply(TET_V, TET_F))
    write("fuzz_ply", "cube_binary", binary_ply(CUBE_V, CUBE_F))
    write("fuzz_ply", "truncated_binary", binary_ply(CUBE_V, CUBE_F)[:-7])
    write("fuzz_ply", "missing_vertex", ascii_ply(TET_V, [(0, 1, 7)] + TET_F[1:]))


def distance_seeds():
    rng = random.Random(7)
    # fuzz_triangle_distance: head (scale | mode << 2 | iterations << 4), cutoff, batch, coords.
    def coarse(p):  # int8 grid: value / 128 of the scale
        return b"".join(struct.pack("<b", max(-128, min(127, round(c * 128)))) for c in p)

    tri_a = [0, 0, 0, 0.5, 0, 0, 0, 0.5, 0]
    cases = {
        "parallel_faces": tri_a + [0.1, 0.1, 0.25, 0.6, 0.1, 0.25, 0.1, 0.6, 0.25],
        "touching_vertex": tri_a + [0.1, 0.1, 0, 0.4, 0.4, 0.5, 0.2, 0.1, 0.5],
        "crossing": tri_a + [0.1, 0.1, -0.3, 0.2, 0.1, 0.3, 0.1, 0.3, 0.3],
        "coplanar_overlap": tri_a + [0.1, 0.1, 0, 0.6, 0.1, 0, 0.1, 0.6, 0],
        "sliver": tri_a + [0.2, 0.2, 0.1, 0.4, 0.4, 0.1, 0.3, 0.3, 0.1],
        "point_triangle": tri_a + [0.2, 0.1, 0.2] * 3,
    }
    for k, (name, c) in enumerate(sorted(cases.items())):
        head = (k % 4) | (0 << 2) | ((k % 8) << 4)
        write("fuzz_triangle_distance", name, bytes([head, 16, k]) + coarse(c))
    for k in range(3):  # 1/32768 grid and raw doubles
        c = [rng.uniform(-1, 1) for _ in range(18)]
        fine = b"".join(struct.pack("<h", round(x * 32767)) for x in c)
        write("fuzz_triangle_distance", f"random_fine_{k}", bytes([2 | 1 << 2 | 3 << 4, 255, 7]) + fine)
        raw = b"".join(struct.pack("<d", x) for x in c)
        write("fuzz_triangle_distance", f"random_raw_{k}", bytes([1 | 2 << 2 | 4 << 4, 32, 3]) + raw)
    near = bytes([2 | 3 << 2 | 3 << 4, 8, 0]) + b"".join(
        struct.pack("<h", round(x * 32767)) for x in tri_a)
    near += bytes([0, 3, 250, 1, 2, 0, 255, 2, 1, 1, 0, 2])
    write("fuzz_triangle_distance", "near_touching", near)

    # fuzz_particle_contacts: head, counts, eps, eps ratio, kernel, coords (int8 grid).
    for k in range(4):
        na, nb = 2 + k, 3 + k
        coords = [rng.uniform(-0.3, 0.3) + (0.15 if i % 3 == 0 and i >= 9 * na else 0)
                  for i in range(9 * (na + nb))]
        head = bytes([2 | 0 << 2, (na - 1) | (nb - 1) << 4, 20 + 40 * k, 16 * k, k | (k + 1) << 2])
        write("fuzz_particle_contacts", f"soup_{k}", head + coarse(coords))
    tet = [c for f in TET_F for i in f for c in (0.4 * x for x in TET_V[i])]
    moved = [c + (0.4 if i % 3 == 0 else 0.05) for i, c in enumerate(tet)]
    write("fuzz_particle_contacts", "tetrahedra_touching",
          bytes([1, 3 | 3 << 4, 60, 0, 1 | 7 << 2]) + coarse(tet + moved))


if __name__ == "__main__":
    mesh_seeds()
    distance_seeds()
