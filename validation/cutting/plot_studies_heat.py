#!/usr/bin/python3
"""The refinement and depth-of-cut studies of the default cut with heat, beside Oxley's theory.

  validation/cutting/plot_studies_heat.py REFINE_DIR DEPTH_DIR [--out DIR]

REFINE_DIR, DEPTH_DIR: the study directories of validation/studies/refinement.toml and
depth_of_cut.toml (swarf sweep ... --out DIR). Reads their study.csv (the steady means, their 95 %
intervals and the oxley.* columns every cutting run writes) and draws
  refinement_heat.png: Fc/w and Ft/w against the particle radius R with their intervals, the
                       least-squares line in R and Oxley's figure for the same cut;
  depth_of_cut_heat.png: Fc/w and Ft/w against h in log-log with the Kienzle fit and Oxley's.
"""
import argparse
import csv
import json
import os
import sys

import numpy as np

FC = "cutting.cutting_force_per_width_mean_N_per_m"
FT = "cutting.thrust_force_per_width_mean_N_per_m"
FC_CI = "cutting.cutting_force_per_width_ci95_N_per_m"
FT_CI = "cutting.thrust_force_per_width_ci95_N_per_m"
OX_FC = "oxley.cutting_force_per_width_N_per_m"
OX_FT = "oxley.thrust_force_per_width_N_per_m"


def rows(directory):
    with open(os.path.join(directory, "study.csv"), newline="") as f:
        table = [r for r in csv.DictReader(f) if r.get("status") == "completed"]
    # A study swept before study.csv had the oxley.* columns: read them from each case's summary.
    for r in table:
        if r.get(OX_FC) in (None, ""):
            with open(os.path.join(directory, "cases", r["case"], "summary.json")) as f:
                ox = json.load(f).get("oxley", {})
            for key in (OX_FC, OX_FT):
                r[key] = str(ox.get(key.split(".", 1)[1], "nan"))
    return table


def col(table, name):
    return np.array([float(r[name]) if r.get(name) not in (None, "", "nan") else np.nan for r in table])


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("refine")
    p.add_argument("depth")
    p.add_argument("--out", default=os.path.dirname(os.path.abspath(__file__)))
    a = p.parse_args()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    t = rows(a.refine)
    R = col(t, "workpiece.radius") * 1e6
    order = np.argsort(R)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for name, ci, ox, colour, label in ((FC, FC_CI, OX_FC, "C0", "Fc/w"), (FT, FT_CI, OX_FT, "C1", "Ft/w")):
        y = col(t, name)[order] / 1e3
        e = col(t, ci)[order] / 1e3
        ax.errorbar(R[order], y, yerr=e, fmt="o", color=colour, capsize=3, label=f"swarf {label} (95 % CI)")
        c = np.polyfit(R[order], y, 1)
        rr = np.linspace(0, R.max() * 1.05, 50)
        ax.plot(rr, np.polyval(c, rr), "--", color=colour, lw=0.8,
                label=f"line in R: {c[1]:.0f} kN/m at R -> 0")
        oxv = np.nanmean(col(t, ox)) / 1e3
        ax.axhline(oxv, color=colour, ls=":", lw=1.2, label=f"Oxley, same cut: {oxv:.0f} kN/m")
    ax.set_xlabel("particle radius R (um)")
    ax.set_ylabel("force per width (kN/m)")
    ax.set_xlim(0, R.max() * 1.08)
    ax.set_ylim(0, None)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="center right")
    ax.set_title("Default C45 cut with heat, h = 0.2 mm, 10 m/s: refinement")
    fig.tight_layout()
    out = os.path.join(a.out, "refinement_heat.png")
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")

    t = rows(a.depth)
    h = col(t, "chip.depth_of_cut_m") * 1e3
    order = np.argsort(h)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    hh = np.linspace(h.min() * 0.9, h.max() * 1.1, 50)
    for name, ci, ox, colour, label in ((FC, FC_CI, OX_FC, "C0", "Fc/w"), (FT, FT_CI, OX_FT, "C1", "Ft/w")):
        y = col(t, name)[order] / 1e3
        e = col(t, ci)[order] / 1e3
        ax.errorbar(h[order], y, yerr=e, fmt="o", color=colour, capsize=3, label=f"swarf {label} (95 % CI)")
        b, lnk = np.polyfit(np.log(h[order]), np.log(y), 1)
        ax.plot(hh, np.exp(lnk) * hh ** b, "--", color=colour, lw=0.8,
                label=f"Kienzle fit: {np.exp(lnk):.0f} h^{b:.2f}")
        oy = col(t, ox)[order] / 1e3
        bo, _ = np.polyfit(np.log(h[order]), np.log(oy), 1)
        ax.plot(h[order], oy, "s:", color=colour, mfc="none", label=f"Oxley, same cuts (exponent {bo:.2f})")
    kv = 1500.0 * (1 - (10 - 6) / 100.0)
    ax.plot(hh, kv * hh ** 0.78, "k-", lw=0.8, label="VDI 3323 C45: 1440 h^0.78 (rake 10 deg)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("uncut chip thickness h (mm)")
    ax.set_ylabel("force per width (kN/m = N/mm)")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7)
    ax.set_title("Default C45 cut with heat, R = 14.1 um, 10 m/s: depth of cut")
    fig.tight_layout()
    out = os.path.join(a.out, "depth_of_cut_heat.png")
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
