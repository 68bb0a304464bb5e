#!/usr/bin/env python3
"""Draws frames of the drum's fix tri/vtk output seen along the drum axis (y): every
particle's triangles projected onto the x-z plane, far ones first, coloured by speed, and the
drum's rim. Debian python3-vtk9 reads the files, python3-matplotlib draws.

usage: /usr/bin/python3 render.py post/particles.pvd drum.png [N_FRAMES] [RADIUS]
"""
import os
import sys
import xml.etree.ElementTree as ET

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection
import numpy as np
from vtk.util.numpy_support import vtk_to_numpy
import vtk


def frames(pvd):
    root = ET.parse(pvd).getroot()
    base = os.path.dirname(pvd)
    return [(float(d.get("timestep")), os.path.join(base, d.get("file")))
            for d in root.iter("DataSet")]


def read(path):
    reader = vtk.vtkXMLPPolyDataReader() if path.endswith(".pvtp") else vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    poly = reader.GetOutput()
    pts = vtk_to_numpy(poly.GetPoints().GetData()).reshape(-1, 3, 3)
    vel = vtk_to_numpy(poly.GetCellData().GetArray("velocity"))
    return pts, np.linalg.norm(vel, axis=1)


def main():
    pvd, png = sys.argv[1], sys.argv[2]
    nframes = int(sys.argv[3]) if len(sys.argv) > 3 else 4
    radius = float(sys.argv[4]) if len(sys.argv) > 4 else 0.03
    all_frames = frames(pvd)
    pick = [all_frames[round(k * (len(all_frames) - 1) / max(nframes - 1, 1))]
            for k in range(nframes)]
    fig, axes = plt.subplots(1, nframes, figsize=(3.2 * nframes, 3.3))
    axes = np.atleast_1d(axes)
    vmax = 0.2  # the rim of a 30 mm drum at one turn a second: 0.19 m/s
    for ax, (t, path) in zip(axes, pick):
        tris, speed = read(path)
        order = np.argsort(tris[:, :, 1].mean(axis=1))[::-1]  # far (large y) first
        polys = tris[order][:, :, [0, 2]] * 1e3
        ax.add_collection(PolyCollection(polys, array=speed[order], cmap="viridis",
                                         norm=plt.Normalize(0, vmax), edgecolors="k",
                                         linewidths=0.1))
        rim = np.linspace(0, 2 * np.pi, 200)
        ax.plot(radius * 1e3 * np.cos(rim), radius * 1e3 * np.sin(rim), color="0.3", lw=1.5)
        ax.set_xlim(-radius * 1.1e3, radius * 1.1e3)
        ax.set_ylim(-radius * 1.1e3, radius * 1.1e3)
        ax.set_aspect("equal")
        ax.set_title(f"t = {t:.2f} s")
        ax.set_xlabel("x (mm)")
    axes[0].set_ylabel("z (mm)")
    sm = plt.cm.ScalarMappable(cmap="viridis", norm=plt.Normalize(0, vmax))
    fig.colorbar(sm, ax=list(axes), shrink=0.8, label="particle speed (m/s)")
    fig.suptitle("Rocks in a drum turning once a second (seen along its axis)")
    fig.savefig(png, dpi=120)


if __name__ == "__main__":
    main()
