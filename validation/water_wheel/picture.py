#!/usr/bin/python3
"""Draws ParaView frames of a water-wheel run seen along the axis (y): particles coloured by
speed, the wheel's triangles at their pose (as the paper's figure 4). Writes wheel_frames.png.

Usage: /usr/bin/python3 picture.py RUN_DIR [FRAME ...]   (default: four frames spread over the run)
"""
import glob
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from vtk.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLUnstructuredGridReader

run = sys.argv[1]
n = len(glob.glob(os.path.join(run, "frames", "particles_*.vtu")))
frames = [int(a) for a in sys.argv[2:]] or [n // 8, n // 3, n // 2, n - 1]
fig, axes = plt.subplots(1, len(frames), figsize=(3.2 * len(frames), 3.6))
for ax, k in zip(np.atleast_1d(axes), frames):
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(os.path.join(run, "frames", f"particles_{k:05d}.vtu"))
    r.Update()
    g = r.GetOutput()
    x = vtk_to_numpy(g.GetPoints().GetData())
    v = np.linalg.norm(vtk_to_numpy(g.GetPointData().GetArray("velocity")), axis=1)
    m = vtkXMLPolyDataReader()
    m.SetFileName(os.path.join(run, "frames", f"mesh_wheel_{k:05d}.vtp"))
    m.Update()
    p = m.GetOutput()
    pts = vtk_to_numpy(p.GetPoints().GetData())
    tris = vtk_to_numpy(p.GetPolys().GetData()).reshape(-1, 4)[:, 1:]
    for t in tris:
        q = pts[list(t) + [t[0]]]
        ax.plot(1e3 * q[:, 0], 1e3 * q[:, 2], color="0.3", lw=0.3)
    sc = ax.scatter(1e3 * x[:, 0], 1e3 * x[:, 2], c=v, s=9, cmap="viridis", vmin=0, vmax=2.5)
    ax.set_xlim(-14, 14)
    ax.set_ylim(-22, 16)
    ax.set_aspect("equal")
    ax.set_title(f"frame {k}", fontsize=9)
    ax.set_xlabel("x (mm)")
axes[0].set_ylabel("z (mm)")
fig.colorbar(sc, ax=axes, label="particle speed (m/s)", shrink=0.8)
fig.savefig(os.path.join(run, "wheel_frames.png"), dpi=110)
print("wrote", os.path.join(run, "wheel_frames.png"))
