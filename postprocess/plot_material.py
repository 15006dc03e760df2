#!/usr/bin/python3
"""Plots of 'swarf material' (PNG): for each test the true stress against its strain (tau against
gamma in shear, with the normal stresses) beside the small-strain mapping, and the von Mises
equivalent stress against the equivalent strain with the volume ratio; with more than one test,
material.png: every test's equivalent stress against the equivalent plastic strain.
Usage: plot_material.py DIR TEST [TEST ...]. Reads DIR/TEST.csv; prints 'wrote FILE' for each
file written. Draws only columns swarf computed."""
import csv, os, sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    cols = {h: [] for h in rows[0]}
    for r in rows[1:]:
        for h, v in zip(rows[0], r):
            cols[h].append(float(v))
    return cols


def first(xs, cond):
    return next((x for x, c in zip(xs, cond) if c), None)


def marks(ax, c, x):
    """Vertical lines at the first rod break and where unbonded neighbours come within 2R."""
    b = first(x, [v > 0 for v in c["broken_rods_1"]])
    if b is not None:
        ax.axvline(b, color="k", ls=":", lw=1, label="first rod breaks")
    k = first(x, [v < 1 for v in c["closest_unbonded_over_2R_1"]])
    if k is not None:
        ax.axvline(k, color="C7", ls="-.", lw=1, label="unbonded neighbours within 2R (contacts)")


def plot_test(d, name):
    c = read(os.path.join(d, name + ".csv"))
    shear = name.startswith("shear")
    mpa = lambda v: [x / 1e6 for x in v]
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(12, 4.6), dpi=110)
    x = c["strain_1"]
    ax.plot(x, mpa(c["stress_Pa"]), color="C0", lw=1.4,
            label="lattice: tau = sigma_12" if shear else "lattice: true axial stress sigma_11")
    ax.plot(x, mpa(c["small_strain_stress_Pa"]), color="C1", lw=1, ls="--",
            label="small-strain mapping of the rod law")
    if shear:
        for col, lab, colr in (("sigma_11_Pa", "sigma_11 (along s)", "C2"), ("sigma_22_Pa", "sigma_22 (along m)", "C3"),
                               ("sigma_33_Pa", "sigma_33", "C4")):
            ax.plot(x, mpa(c[col]), lw=0.9, color=colr, label=lab)
    marks(ax, c, x)
    ax.set_xlabel("shear gamma [1]" if shear else "log axial strain [1]")
    ax.set_ylabel("stress [MPa]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    ax.set_title("%s: stress against strain" % name)
    cyclic = name.startswith("cyclic")
    # (a reversal folds the equivalent measures onto themselves: the cyclic test keeps its own strain)
    ex = x if cyclic else c["equivalent_strain_1"]
    if not cyclic:
        bx.plot(ex, mpa(c["equivalent_stress_Pa"]), color="C0", lw=1.4, label="von Mises equivalent stress")
        bx.set_xlabel("equivalent strain [1] (" + ("gamma/sqrt3" if shear else "|log strain|") + ")")
        bx.set_ylabel("equivalent stress [MPa]")
    else:
        bx.plot(ex, mpa(c["mean_stress_Pa"]), color="C0", lw=1.2, label="mean stress")
        bx.set_xlabel("log axial strain [1]")
        bx.set_ylabel("mean stress [MPa]")
    bx.grid(alpha=0.3)
    cx = bx.twinx()
    cx.plot(ex, c["volume_ratio_1"], color="C5", lw=1, label="volume ratio det F")
    cx.plot(ex, [1 + v for v in c["plastic_volume_strain_1"]], color="C5", lw=0.8, ls="--",
            label="1 + plastic volume strain")
    cx.set_ylabel("volume ratio [1]", color="C5")
    h1, l1 = bx.get_legend_handles_labels()
    h2, l2 = cx.get_legend_handles_labels()
    bx.legend(h1 + h2, l1 + l2, fontsize=7, loc="lower right")
    bx.set_title("%s: %s" % (name, "volume" if cyclic else "von Mises equivalents"))
    fig.tight_layout()
    out = os.path.join(d, name + ".png")
    fig.savefig(out)
    plt.close(fig)
    print("wrote " + out)
    return c


def plot_all(d, curves):
    fig, ax = plt.subplots(figsize=(8, 5), dpi=110)
    for name, c in curves.items():
        if name.startswith("cyclic"):
            continue
        ax.plot(c["plastic_strain_1"], [v / 1e6 for v in c["equivalent_stress_Pa"]], lw=1.2, label=name)
    ax.set_xlabel("equivalent plastic strain [1]")
    ax.set_ylabel("von Mises equivalent stress [MPa]")
    ax.set_xlim(left=0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title("The lattice as a material: every test in von Mises equivalents")
    fig.tight_layout()
    out = os.path.join(d, "material.png")
    fig.savefig(out)
    plt.close(fig)
    print("wrote " + out)


def main():
    if len(sys.argv) < 3:
        sys.exit("usage: plot_material.py DIR TEST [TEST ...]")
    d = sys.argv[1]
    curves = {name: plot_test(d, name) for name in sys.argv[2:]}
    if len(curves) > 1:
        plot_all(d, curves)


if __name__ == "__main__":
    main()
