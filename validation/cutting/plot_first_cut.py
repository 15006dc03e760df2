#!/usr/bin/python3
"""Side view (x-z) of a cutting run's final state, particles coloured by their broken-rod
fraction, with the tool's faces drawn; a stop-gap until the rendered picture of issue 5.
Usage: plot_first_cut.py RUN_DIR OUT.png (reads RUN_DIR/results.h5 and RUN_DIR/summary.json)"""
import json, math, sys
import h5py, numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

run, out = sys.argv[1], sys.argv[2]
f = h5py.File(run + "/results.h5", "r")
x = f["/particles/position"][:]
pairs = f["/bonds/pairs"][:]
intact = f["/bonds/intact"][:]
t_end = f.attrs["time_s"]
n = len(x)
count = np.bincount(pairs[:, 0], minlength=n) + np.bincount(pairs[:, 1], minlength=n)
broken = pairs[intact == 0]
nb = np.bincount(broken[:, 0], minlength=n) + np.bincount(broken[:, 1], minlength=n)
frac = nb / np.maximum(count, 1)
case = json.load(open(run + "/summary.json"))["case"]
tool = [m for m in case.get("mesh", []) if "rake_angle" in m][0]
tip = np.array(tool["origin"]) + np.array(tool.get("velocity", [0, 0, 0])) * t_end
a, g, L = math.radians(tool["rake_angle"]), math.radians(tool.get("clearance_angle", 7.0)), tool["face_length"]
front = x[:, 1] < np.median(x[:, 1])  # one half of the width
fig, ax = plt.subplots(figsize=(9, 4.5), dpi=110)
sc = ax.scatter(x[front, 0] * 1e3, x[front, 2] * 1e3, c=frac[front], s=5, cmap="viridis", vmin=0, vmax=1)
plt.colorbar(sc, label="broken-rod fraction [1]")
for d in ((-math.sin(a), math.cos(a)), (-math.cos(g), math.sin(g))):
    ax.plot([tip[0] * 1e3, (tip[0] + L * d[0]) * 1e3], [tip[2] * 1e3, (tip[2] + L * d[1]) * 1e3], "r-", lw=2)
ax.set_aspect("equal")
ax.set_xlabel("x [mm]")
ax.set_ylabel("z [mm]")
ax.set_title("t = %.3g s" % t_end)
fig.tight_layout()
fig.savefig(out)
