#!/usr/bin/python3
"""Where the chip separates from the workpiece: for each run, the fraction of every initial layer
(by its initial height above the tool's sharp tip) that ends in the chip (final height above the
tip's), in the steady part of the cut (initial x from 1 mm to 0.3 mm behind the tip at the end), and
the height at which half a layer goes to the chip, by linear interpolation between the layers
around it (m; the stagnation point's height on the edge: material below it passes under the edge
into the machined surface).

  separation_height.py RUN_DIR [RUN_DIR ...]
"""
import sys

import h5py
import numpy as np


def separation(run, x_from=1.0e-3, behind=0.3e-3):
    with h5py.File(f"{run}/results.h5", "r") as f:
        r = float(f["cutting/radius"][0])
        n = int(f["cutting/workpiece_particles"][0])
        tip = f["cutting/tool_tip"][:]
        x = f["particles/position"][:n]
        x0 = x - f["particles/displacement"][:n]
    a = 2.0 * np.sqrt(2.0) * r
    sel = (x0[:, 0] >= x_from) & (x0[:, 0] < tip[0] - behind)
    z0 = x0[:, 2] - tip[2]
    # Layers are a/2 apart; a/4 bins hold each layer whether the tip lies on one or between two.
    k = np.round(z0 / (a / 4.0)).astype(int)
    rows = []
    for kk in np.unique(k[sel]):
        m = sel & (k == kk)
        if -2 * a <= kk * a / 4.0 <= 2 * a:
            rows.append((kk * a / 4.0, float((x[m, 2] > tip[2]).mean()), int(m.sum())))
    half = None
    for (z1, f1, _), (z2, f2, _) in zip(rows, rows[1:]):
        if f1 < 0.5 <= f2:
            half = z1 + (0.5 - f1) / (f2 - f1) * (z2 - z1)
    return r, rows, half


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    print("| run | R (um) | layers: initial height above the tip (um): fraction to the chip | half to the chip at (um) |")
    print("|---|---|---|---|")
    for run in sys.argv[1:]:
        r, rows, half = separation(run)
        cells = " ".join(f"{z * 1e6:+.1f}: {f:.2f}" for z, f, _ in rows if -1e-6 - 2 * r < z < 70e-6)
        print(f"| {run} | {r * 1e6:.2f} | {cells} | {'-' if half is None else f'{half * 1e6:.1f}'} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
