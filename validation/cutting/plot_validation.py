#!/usr/bin/python3
"""Plots of the cutting validation from the three studies' study.csv files (swarf sweep):
depth of cut (forces per width with least-squares lines), rake angle (forces; shear angle
measured from the chip against Merchant's), refinement (forces, compression ratio and shear
angle against the particle radius). Usage:
  plot_validation.py STUDIES_DIR OUT_DIR
with STUDIES_DIR holding depth_of_cut/, rake_angle/, refinement/ (the --out folders).
Prints each PNG written and a table of the numbers on stdout (Markdown)."""
import csv, os, sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

FC, FT = "cutting.cutting_force_per_width_mean_N_per_m", "cutting.thrust_force_per_width_mean_N_per_m"
FCS, FTS = "cutting.cutting_force_per_width_std_N_per_m", "cutting.thrust_force_per_width_std_N_per_m"


def read(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    # (study.csv files before 2026-12-05 have the units on line 2: its status cell is "-")
    head = rows[0]
    units_row = len(rows) > 1 and dict(zip(head, rows[1])).get("status") == "-"
    body = [r for r in rows[2 if units_row else 1:] if r]
    out = []
    for r in body:
        d = dict(zip(head, r))
        if d.get("status") != "completed":
            continue
        for k, v in list(d.items()):
            try:
                d[k] = float(v)
            except ValueError:
                pass
        out.append(d)
    return out


def num(row, key):
    """The row's number for key, NaN where it is missing or not a number (e.g. no chip thickness)."""
    v = row.get(key)
    return v if isinstance(v, float) else np.nan


def col(rows, key):
    return np.array([num(r, key) for r in rows])


def forces(ax, x, rows, xlabel):
    ax.errorbar(x, col(rows, FC) / 1e3, yerr=col(rows, FCS) / 1e3, fmt="o", color="C0", capsize=3,
                label="cutting Fc/w (mean +- std over the steady part)")
    ax.errorbar(x, col(rows, FT) / 1e3, yerr=col(rows, FTS) / 1e3, fmt="s", color="C3", capsize=3,
                label="thrust Ft/w")
    # The 95 % confidence interval of each mean (batch means; older study.csv files lack the column): thick bars.
    for key, c in ((FC, "C0"), (FT, "C3")):
        ci = col(rows, key.replace("_mean_", "_ci95_")) / 1e3
        if np.isfinite(ci).any():
            ax.errorbar(x, col(rows, key) / 1e3, yerr=ci, fmt="none", ecolor=c, elinewidth=4, alpha=0.45,
                        label="95 % CI of the mean" if c == "C0" else None)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("force per width [kN/m]")
    ax.grid(alpha=0.3)


def main():
    src, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    table = []
    p = os.path.join(src, "depth_of_cut", "study.csv")
    if os.path.exists(p):
        rows = sorted(read(p), key=lambda r: r["chip.depth_of_cut_m"])
        h = col(rows, "chip.depth_of_cut_m") * 1e3
        fig, ax = plt.subplots(figsize=(7, 4.8), dpi=120)
        forces(ax, h, rows, "depth of cut h [mm]")
        for key, c in ((FC, "C0"), (FT, "C3")):
            y = col(rows, key) / 1e3
            k, b = np.polyfit(h, y, 1)
            r2 = 1 - np.sum((y - (k * h + b)) ** 2) / max(np.sum((y - y.mean()) ** 2), 1e-300)
            xs = np.linspace(0, h.max() * 1.05, 50)
            ax.plot(xs, k * xs + b, "--", color=c, lw=1,
                    label="fit: %.1f kN/m per mm %+.1f kN/m (R^2 %.2f)" % (k, b, r2))
            table.append("| depth study, %s | slope %.4g kN/m per mm = %.4g MPa, intercept %.4g kN/m, R^2 %.3f |"
                         % ("Fc/w" if key == FC else "Ft/w", k, k, b, r2))
        ax.set_xlim(0, None)
        ax.legend(fontsize=7)
        ax.set_title("Depth of cut (rake 10 deg, R = 0.05 mm, 10 m/s)")
        fig.tight_layout()
        fig.savefig(os.path.join(out, "depth_of_cut.png"))
        print("wrote depth_of_cut.png")
        for r in rows:
            table.append("| h = %.3f mm | Fc/w %.1f +- %.1f kN/m, Ft/w %.1f +- %.1f kN/m, r %.3f, phi %.1f deg, Merchant %.1f deg, broken %.1f %% |" % (
                r["chip.depth_of_cut_m"] * 1e3, r[FC] / 1e3, r[FCS] / 1e3, r[FT] / 1e3, r[FTS] / 1e3,
                num(r, "chip.compression_ratio"),
                num(r, "chip.shear_angle_deg"),
                r["chip.merchant_shear_angle_deg"], 100 * r["results.broken_fraction"]))
    p = os.path.join(src, "rake_angle", "study.csv")
    if os.path.exists(p):
        rows = sorted(read(p), key=lambda r: r["mesh.0.rake_angle"])
        a = col(rows, "mesh.0.rake_angle")
        fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.5), dpi=120)
        forces(ax, a, rows, "rake angle gamma [deg]")
        ax.legend(fontsize=7)
        ax.set_title("Forces (h = 0.5 mm)")
        bx.plot(a, col(rows, "chip.shear_angle_deg"), "o-", label="measured from the chip: tan phi = r cos a / (1 - r sin a)")
        bx.plot(a, col(rows, "chip.merchant_shear_angle_deg"), "s--", label="Merchant 45 + a/2 - b/2 (b from Fc, Ft)")
        bx.plot(a, 45 + a / 2 - np.degrees(np.arctan(0.3)) / 2, ":", color="k", label="Merchant with b = atan(mu = 0.3)")
        bx.set_xlabel("rake angle gamma [deg]")
        bx.set_ylabel("shear angle phi [deg]")
        bx.grid(alpha=0.3)
        bx.legend(fontsize=7)
        bx.set_title("Shear angle")
        fig.tight_layout()
        fig.savefig(os.path.join(out, "rake_angle.png"))
        print("wrote rake_angle.png")
        for r in rows:
            table.append("| rake %.0f deg | Fc/w %.1f +- %.1f kN/m, Ft/w %.1f +- %.1f kN/m, r %.3f, phi %.1f deg, beta %.1f deg, Merchant %.1f deg, broken %.1f %% |" % (
                r["mesh.0.rake_angle"], r[FC] / 1e3, r[FCS] / 1e3, r[FT] / 1e3, r[FTS] / 1e3,
                num(r, "chip.compression_ratio"),
                num(r, "chip.shear_angle_deg"),
                r["chip.friction_angle_deg"], r["chip.merchant_shear_angle_deg"], 100 * r["results.broken_fraction"]))
    p = os.path.join(src, "refinement", "study.csv")
    if os.path.exists(p):
        rows = sorted(read(p), key=lambda r: -r["workpiece.radius"])
        R = col(rows, "workpiece.radius") * 1e3
        fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.5), dpi=120)
        forces(ax, R, rows, "particle radius R [mm]")
        ax.legend(fontsize=7)
        ax.set_title("Forces (h = 0.5 mm, rake 10 deg)")
        bx.plot(R, col(rows, "chip.shear_angle_deg"), "o-", label="shear angle from the chip [deg]")
        bx.plot(R, 100 * col(rows, "chip.compression_ratio"), "s-", label="compression ratio r x 100")
        bx.plot(R, 100 * col(rows, "results.broken_fraction"), "^-", label="broken rods [%]")
        bx.set_xlabel("particle radius R [mm]")
        bx.grid(alpha=0.3)
        bx.legend(fontsize=7)
        bx.set_title("Chip")
        for axis in (ax, bx):
            axis.invert_xaxis()
        fig.tight_layout()
        fig.savefig(os.path.join(out, "refinement.png"))
        print("wrote refinement.png")
        for r in rows:
            table.append("| R = %.3f mm | Fc/w %.1f +- %.1f kN/m, Ft/w %.1f +- %.1f kN/m, r %.3f, phi %.1f deg, broken %.1f %% |" % (
                r["workpiece.radius"] * 1e3, r[FC] / 1e3, r[FCS] / 1e3, r[FT] / 1e3, r[FTS] / 1e3,
                num(r, "chip.compression_ratio"),
                num(r, "chip.shear_angle_deg"),
                100 * r["results.broken_fraction"]))
    print("\n".join(table))


if __name__ == "__main__":
    main()
