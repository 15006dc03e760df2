#!/usr/bin/env python3
"""How dense the chip is: each particle's local density against the uncut workpiece's.

Usage: /usr/bin/python3 chip_density.py RUN_DIR [RUN_DIR ...] [--png OUT.png] [--labels a,b]

For every particle, d6 = the mean distance to its 6 nearest particles (nearest images along a
periodic width). In an FCC lattice d6 = 2R inside and on a (001) face alike (a face particle still
has 8 neighbours at 2R), so surfaces do not bias it as a count in a sphere would. The relative
density is rho = (d6_bulk / d6)^3, d6_bulk the median over the uncut bulk (more than 0.1 mm below
the tool tip). Printed per region, as medians with the 10th-90th percentiles:
  chip   the particles more than 2 lattice cells above the uncut surface
  ahead  the layer being cut (between the tip's height and the uncut surface), up to 0.5 mm ahead
         of the tip
  bulk   the uncut workpiece (the reference, rho = 1)
the same from a count: particles per cell of a grid in x-z (1.5 lattice cells wide, the whole
width) over the bulk's, for the cells inside the material (a chip that has collapsed into dense
sheets with gaps between them reads high by the 6 nearest and nearer 1 by the cells), and the
rods' mean plastic shift there (results.h5 /bonds: the rods' own account of a volume
change: for an FCC particle the mean plastic rod strain is a third of the plastic volume strain)
and the rods' mean length over the lattice's spacing 2R (intact rods with both ends in the region,
nearest images along a periodic width: where the chip's volume went, whatever the rods' shifts
say; a rod whose rest length is not 2R would make the two differ).
A metal's plastic flow keeps its volume: rho stays within the elastic 1 % everywhere.
With --png, a picture per run of the particles coloured by rho (x along the cut, z up).
"""
import sys

import h5py
import numpy as np
from scipy.spatial import cKDTree


def load(run):
    with h5py.File(run + "/results.h5", "r") as h:
        x = h["particles/position"][:].copy()
        c = h["cutting"]
        out = dict(x=x, tip=c["tool_tip"][:], top=float(c["uncut_surface_z"][0]), radius=float(c["radius"][0]),
                   width=float(c["width"][0]), free=bool(c["free_sides"][0]))
        b = h["bonds"]
        out["pairs"], out["intact"], out["shift"] = b["pairs"][:], b["intact"][:].astype(bool), b["plastic_shift"][:]
    return out


def density(r):
    x = r["x"]
    y0 = x[:, 1].min()
    pts = x.copy()
    if not r["free"] and r["width"] > 0:  # periodic width: a tree with the period along y
        pts[:, 1] = (pts[:, 1] - y0) % r["width"]
        lo = pts.min(0) - 1e-3
        lo[1] = 0.0
        pts -= lo
        box = np.array([pts[:, 0].max() + 1e-3, r["width"], pts[:, 2].max() + 1e-3])
        tree = cKDTree(pts, boxsize=box)
    else:
        tree = cKDTree(pts)
    d, _ = tree.query(pts, k=7)
    return d[:, 1:7].mean(1)


def cell_density(r, reg, size_cells=1.5):
    """The particles per cell of a grid in x-z (cells 'size_cells' lattice cells wide, the whole
    width along y) over the bulk's median count, for the cells whose 8 neighbours all hold at
    least half the bulk's count (inside the material: a surface's partly filled cell does not
    count). Returns {region: array of the interior cells' relative densities}, a cell belonging to
    the region most of its particles belong to."""
    x = r["x"]
    a = 2.0 * np.sqrt(2.0) * r["radius"]
    s = size_cells * a
    ix = np.floor((x[:, 0] - x[:, 0].min()) / s).astype(int)
    iz = np.floor((x[:, 2] - x[:, 2].min()) / s).astype(int)
    nx, nz = ix.max() + 1, iz.max() + 1
    count = np.zeros((nx, nz))
    np.add.at(count, (ix, iz), 1.0)
    bulk_cells = np.zeros((nx, nz))
    np.add.at(bulk_cells, (ix, iz), reg["bulk"].astype(float))
    full_bulk = bulk_cells == count
    ref = np.median(count[full_bulk & (count > 0)])
    pad = np.pad(count, 1)
    inside = np.ones((nx, nz), bool)
    for dx in (-1, 0, 1):
        for dz in (-1, 0, 1):
            inside &= pad[1 + dx:1 + dx + nx, 1 + dz:1 + dz + nz] >= 0.5 * ref
    out = {}
    for name, m in reg.items():
        cm = np.zeros((nx, nz))
        np.add.at(cm, (ix[m], iz[m]), 1.0)
        sel = inside & (cm > 0.5 * count)
        out[name] = count[sel] / ref
    return out


def regions(r):
    x, tip, top = r["x"], r["tip"], r["top"]
    a = 2.0 * np.sqrt(2.0) * r["radius"]
    return {
        "chip": x[:, 2] > top + 2 * a,
        "ahead": (x[:, 0] > tip[0]) & (x[:, 0] < tip[0] + 0.5e-3) & (x[:, 2] > tip[2]) & (x[:, 2] < top),
        "bulk": (x[:, 2] < tip[2] - 1e-4) & (x[:, 2] > x[:, 2].min() + 2 * a),
    }


def mean_shift(r, mask):
    p, it, s = r["pairs"], r["intact"], r["shift"]
    n = len(r["x"])
    q = p[it]
    sv = s[it]
    tot = np.bincount(q[:, 0], sv, n) + np.bincount(q[:, 1], sv, n)
    cnt = np.bincount(q.ravel(), minlength=n)
    per = tot / np.maximum(cnt, 1)
    m = mask & (cnt > 0)
    return per[m].mean() if m.any() else float("nan")


def rod_length(r, mask):
    """The mean length of the intact rods with both ends in 'mask', over 2R."""
    p, it, x = r["pairs"], r["intact"], r["x"]
    m = it & mask[p[:, 0]] & mask[p[:, 1]]
    if not m.any():
        return float("nan")
    d = x[p[m, 1]] - x[p[m, 0]]
    if not r["free"] and r["width"] > 0:
        d[:, 1] -= r["width"] * np.round(d[:, 1] / r["width"])
    return float(np.linalg.norm(d, axis=1).mean() / (2.0 * r["radius"]))


def main(argv):
    runs, png, labels = [], None, None
    i = 0
    while i < len(argv):
        if argv[i] == "--png":
            png = argv[i + 1]
            i += 2
        elif argv[i] == "--labels":
            labels = argv[i + 1].split(",")
            i += 2
        else:
            runs.append(argv[i])
            i += 1
    if not runs:
        sys.exit(__doc__)
    labels = labels or runs
    print("| run | region | particles | rho, 6 nearest: median | 10-90 % | rho, cells: median (cells) | "
          "rods' mean plastic shift | rods' mean length / 2R |")
    print("|---|---|---|---|---|---|---|---|")
    fields = []
    for run, label in zip(runs, labels):
        r = load(run)
        d6 = density(r)
        reg = regions(r)
        ref = np.median(d6[reg["bulk"]])
        rho = (ref / d6) ** 3
        fields.append((label, r, rho))
        cells = cell_density(r, reg)
        for name, m in reg.items():
            if not m.any():
                print(f"| {label} | {name} | 0 | - | - | - | - | - |")
                continue
            lo, hi = np.percentile(rho[m], [10, 90])
            c = cells[name]
            cs = f"{np.median(c):.3f} ({len(c)})" if len(c) else "- (0)"
            print(f"| {label} | {name} | {m.sum()} | {np.median(rho[m]):.3f} | {lo:.3f}-{hi:.3f} | {cs} | "
                  f"{mean_shift(r, m):+.4f} | {rod_length(r, m):.4f} |")
    if png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(len(fields), 1, figsize=(8, 3.2 * len(fields)), squeeze=False)
        for ax, (label, r, rho) in zip(axes[:, 0], fields):
            x, tip = r["x"], r["tip"]
            near = (x[:, 0] > tip[0] - 1.2e-3) & (x[:, 0] < tip[0] + 0.8e-3) & (x[:, 2] > tip[2] - 0.3e-3)
            norm = matplotlib.colors.TwoSlopeNorm(vmin=0.5, vcenter=1.0, vmax=2.5)
            sc = ax.scatter(x[near, 0] * 1e3, x[near, 2] * 1e3, c=rho[near], s=4, cmap="coolwarm", norm=norm)
            ax.set_aspect("equal")
            ax.set_title(f"{label}: local density / uncut workpiece's (1 = the metal's, which keeps its volume)",
                         fontsize=9)
            ax.set_xlabel("x, along the cut (mm)")
            ax.set_ylabel("z (mm)")
            fig.colorbar(sc, ax=ax, label="relative density (1)")
        fig.tight_layout()
        fig.savefig(png, dpi=110)
        print(f"picture: {png}")


if __name__ == "__main__":
    main(sys.argv[1:])
