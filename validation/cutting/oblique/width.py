#!/usr/bin/python3
"""width.py: the force of a cut with free sides away from its sides, against the plane-strain cut.

Usage: width.py DIR [DEST]. Reads DIR/plane_strain/summary.json (swarf run of plane_strain_c45.toml)
and DIR/b*/summary.json (oblique_c45.toml at lambda = 0 with cut.width = b), prints a table (b and
b/h; Fc/w and Ft/w of the whole width and of its middle half, the series' *_middle columns, with
their 95 % intervals; each against the plane strain's) and writes DEST/width.csv (the same numbers,
units in the header) and DEST/width.png. DEST defaults to DIR. Exit 1 when a run is missing or a
free-sided run lacks the middle-half figures (runs before 2026-12-06).
"""
import csv
import glob
import json
import os
import sys

from compare import finish_figure, num  # (this folder's: a summary's number, NaN when absent; the figure's end)


def load(path):
    with open(path) as f:
        return json.load(f)


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    src = sys.argv[1]
    dest = sys.argv[2] if len(sys.argv) > 2 else src
    ps_path = os.path.join(src, "plane_strain", "summary.json")
    if not os.path.exists(ps_path):
        print("width.py: no %s" % ps_path, file=sys.stderr)
        return 1
    ps = load(ps_path)["cutting"]
    fc_ps, fc_ps_ci = num(ps, "cutting_force_per_width_mean_N_per_m") / 1e3, num(
        ps, "cutting_force_per_width_ci95_N_per_m") / 1e3
    ft_ps, ft_ps_ci = num(ps, "thrust_force_per_width_mean_N_per_m") / 1e3, num(
        ps, "thrust_force_per_width_ci95_N_per_m") / 1e3
    rows = []
    for path in sorted(glob.glob(os.path.join(src, "b*", "summary.json"))):
        s = load(path)
        c, cut = s["cutting"], s.get("cut", {})
        if "cutting_force_per_width_middle_mean_N_per_m" not in c:
            print("width.py: %s has no middle-half force (not a free-sided run, or one before 2026-12-06)" % path,
                  file=sys.stderr)
            return 1
        b = num(c, "width_m") if "width_m" in c else float("nan")
        h = num(s.get("chip", {}), "depth_of_cut_m")
        rows.append({
            "run": os.path.basename(os.path.dirname(path)),
            "width_mm": b * 1e3,
            "width_to_h": b / h,
            "Fc_whole_kN_per_m": num(c, "cutting_force_per_width_mean_N_per_m") / 1e3,
            "Fc_whole_ci95_kN_per_m": num(c, "cutting_force_per_width_ci95_N_per_m") / 1e3,
            "Fc_middle_kN_per_m": num(c, "cutting_force_per_width_middle_mean_N_per_m") / 1e3,
            "Fc_middle_ci95_kN_per_m": num(c, "cutting_force_per_width_middle_ci95_N_per_m") / 1e3,
            "Ft_whole_kN_per_m": num(c, "thrust_force_per_width_mean_N_per_m") / 1e3,
            "Ft_whole_ci95_kN_per_m": num(c, "thrust_force_per_width_ci95_N_per_m") / 1e3,
            "Ft_middle_kN_per_m": num(c, "thrust_force_per_width_middle_mean_N_per_m") / 1e3,
            "Ft_middle_ci95_kN_per_m": num(c, "thrust_force_per_width_middle_ci95_N_per_m") / 1e3,
            "Fc_plane_strain_kN_per_m": fc_ps,
            "Fc_plane_strain_ci95_kN_per_m": fc_ps_ci,
            "Ft_plane_strain_kN_per_m": ft_ps,
            "Ft_plane_strain_ci95_kN_per_m": ft_ps_ci,
        })
    if not rows:
        print("width.py: no DIR/b*/summary.json in %s" % src, file=sys.stderr)
        return 1
    rows.sort(key=lambda r: r["width_mm"])
    print("plane strain: Fc/w %.1f +- %.1f kN/m, Ft/w %.1f +- %.1f kN/m" % (fc_ps, fc_ps_ci, ft_ps, ft_ps_ci))
    print("| b (mm) | b/h | Fc/w whole (kN/m) | Fc/w middle half | middle / plane strain | Ft/w whole | "
          "Ft/w middle half | middle / plane strain |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        print("| %.2f | %.0f | %.1f +- %.1f | %.1f +- %.1f | %.3f | %.1f +- %.1f | %.1f +- %.1f | %.3f |" % (
            r["width_mm"], r["width_to_h"], r["Fc_whole_kN_per_m"], r["Fc_whole_ci95_kN_per_m"],
            r["Fc_middle_kN_per_m"], r["Fc_middle_ci95_kN_per_m"], r["Fc_middle_kN_per_m"] / fc_ps,
            r["Ft_whole_kN_per_m"], r["Ft_whole_ci95_kN_per_m"], r["Ft_middle_kN_per_m"],
            r["Ft_middle_ci95_kN_per_m"], r["Ft_middle_kN_per_m"] / ft_ps))
    os.makedirs(dest, exist_ok=True)
    with open(os.path.join(dest, "width.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    bh = [r["width_to_h"] for r in rows]
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, f, ref, ref_ci in ((axes[0], "Fc", fc_ps, fc_ps_ci), (axes[1], "Ft", ft_ps, ft_ps_ci)):
        ax.errorbar(bh, [r[f + "_whole_kN_per_m"] for r in rows], yerr=[r[f + "_whole_ci95_kN_per_m"] for r in rows],
                    fmt="o-", capsize=3, label="whole width")
        ax.errorbar(bh, [r[f + "_middle_kN_per_m"] for r in rows],
                    yerr=[r[f + "_middle_ci95_kN_per_m"] for r in rows], fmt="s-", capsize=3,
                    label="middle half of the width")
        lo, hi = min(bh) * 0.8, max(bh) * 1.2
        ax.axhspan(ref - ref_ci, ref + ref_ci, color="k", alpha=0.12)
        ax.plot([lo, hi], [ref, ref], "k--", label="plane strain (95 % CI shaded)")
        ax.set_xlim(lo, hi)
        ax.set_xlabel("width over uncut chip thickness b/h")
        ax.set_ylabel("%s/w (kN/m)" % f)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    finish_figure(fig, dest, "width", "C45, h = 0.2 mm, 600 m/min, rake 10 deg, 5 layers: free sides against plane strain")
    return 0


if __name__ == "__main__":
    sys.exit(main())
