#!/usr/bin/env python3
"""Renders frames of fix tri/vtk output into one PNG: each particle's triangles, shaded by
their orientation to a light and coloured by shape. Debian python3-vtk9 reads the files,
python3-matplotlib draws (no OpenGL or display needed).

usage: /usr/bin/python3 render.py post/particles.pvd falling.png [N_FRAMES]
"""
import os
import sys
import xml.etree.ElementTree as ET

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from mpl_toolkits.mplot3d.art3d import Poly3DCollection
import numpy as np
from vtk.util.numpy_support import vtk_to_numpy
import vtk

SHAPE_COLOURS = ["#c8553d", "#588b8b", "#f2a541", "#6c5b7b", "#2d6a4f"]


def read_frame(path):
    reader = vtk.vtkXMLPPolyDataReader() if path.endswith(".pvtp") else vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    poly = reader.GetOutput()
    pts = vtk_to_numpy(poly.GetPoints().GetData()).reshape(-1, 3, 3)
    shape = vtk_to_numpy(poly.GetCellData().GetArray("shape"))
    return pts, shape


def main():
    pvd, out = sys.argv[1], sys.argv[2]
    nshow = int(sys.argv[3]) if len(sys.argv) > 3 else 4
    root = ET.parse(pvd).getroot()
    frames = [(float(d.get("timestep")), d.get("file")) for d in root.iter("DataSet")]
    picks = [frames[round(k * (len(frames) - 1) / (nshow - 1))] for k in range(nshow)]
    light = np.array([0.4, -0.5, 0.77])
    light /= np.linalg.norm(light)
    fig = plt.figure(figsize=(3.2 * nshow, 5.0))
    for k, (t, name) in enumerate(picks):
        tris, shape = read_frame(os.path.join(os.path.dirname(pvd), name))
        normals = np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0])
        normals /= np.linalg.norm(normals, axis=1)[:, None]
        shade = 0.35 + 0.65 * np.clip(normals @ light, 0, 1)
        base = np.array([matplotlib.colors.to_rgb(SHAPE_COLOURS[s % len(SHAPE_COLOURS)]) for s in shape])
        ax = fig.add_subplot(1, nshow, k + 1, projection="3d")
        ax.add_collection3d(Poly3DCollection(tris * 1000, facecolors=base * shade[:, None],
                                             edgecolors=(0, 0, 0, 0.25), linewidths=0.2))
        centre = tris.reshape(-1, 3).mean(axis=0) * 1000
        half = max(np.ptp(tris.reshape(-1, 3), axis=0).max() * 500, 12)
        for setlim, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), centre):
            setlim(c - half, c + half)
        ax.set_box_aspect((1, 1, 1))
        ax.view_init(elev=18, azim=-60)
        ax.set_title(f"t = {t * 1000:.0f} ms", fontsize=10)
        ax.set_xlabel("x (mm)", fontsize=7)
        ax.set_zlabel("z (mm)", fontsize=7)
        ax.tick_params(labelsize=6)
    fig.suptitle("examples/falling: rocks of 20 (red) and 40 (teal) triangles and a "
                 "non-convex gear (amber), tumbling in free fall", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
