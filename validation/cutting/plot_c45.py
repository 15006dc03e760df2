#!/usr/bin/python3
"""C45 cutting forces against Kienzle's law (validation/cutting/README.md, "A chip").

usage: plot_c45.py OUT.png RUN_DIR:h_mm:rake_deg [...]
Each RUN_DIR holds a swarf run's summary.json; h in mm, rake in degrees. Writes a PNG of the
steady cutting and thrust forces per width (kN/m, with their 95 % confidence intervals)
against the depth of cut, with Kienzle's Fc/w = kc1.1 h^(1 - mc) (kc1.1 = 1500 N/mm^2,
mc = 0.22, 1 % less per degree of rake above 6 deg; docs/cutting-data.md).
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def kienzle(h_mm, rake_deg):
    return 1500.0 * h_mm ** (1 - 0.22) * (1 - (rake_deg - 6.0) / 100.0)  # N/mm = kN/m


def main():
    out, runs = sys.argv[1], sys.argv[2:]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for rake, marker in ((10.0, "o"), (0.0, "s")):
        pts = []
        for spec in runs:
            d, h, a = spec.split(":")
            if float(a) != rake:
                continue
            c = json.load(open(f"{d}/summary.json"))["cutting"]
            pts.append((float(h), c["cutting_force_per_width_mean_N_per_m"] / 1e3,
                        c["cutting_force_per_width_ci95_N_per_m"] / 1e3, c["thrust_force_per_width_mean_N_per_m"] / 1e3,
                        c["thrust_force_per_width_ci95_N_per_m"] / 1e3))
        if not pts:
            continue
        pts.sort()
        h, fc, fce, ft, fte = map(np.array, zip(*pts))
        ax.errorbar(h, fc, yerr=fce, fmt=marker, color="C0", capsize=3, label=f"swarf Fc/w, rake {rake:g} deg")
        ax.errorbar(h, ft, yerr=fte, fmt=marker, color="C3", mfc="none", capsize=3, label=f"swarf Ft/w, rake {rake:g} deg")
        hh = np.linspace(0.05, 0.35, 50)
        ax.plot(hh, kienzle(hh, rake), "--", color="C0" if rake == 10 else "C2", label=f"Kienzle Fc/w, rake {rake:g} deg")
    ax.set_xlabel("depth of cut h [mm]")
    ax.set_ylabel("force per width [kN/m] (= N/mm)")
    ax.set_title("C45, plane strain, 10 m/s: swarf against Kienzle\n(kc1.1 = 1500 N/mm^2, mc = 0.22, 1 %/deg of rake)", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
