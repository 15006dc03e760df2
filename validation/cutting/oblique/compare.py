#!/usr/bin/python3
"""compare.py: the oblique-cut series (run.sh) against Stabler's flow rule.

Usage: compare.py OUT [DEST]. Reads OUT/l*/summary.json (swarf run of oblique_c45.toml at several
inclinations lambda), prints a table (lambda; the chip flow angle eta_c with its 95 % interval beside
Stabler's eta_c = lambda; the chip's width over the cut's; Fc/w, Ft/w, Fp/w in kN/m with their
intervals; h_c in mm) and writes DEST/oblique.csv (the same numbers, units in the header) and
DEST/oblique.png (eta_c against lambda with Stabler's line; the three forces against lambda).
DEST defaults to OUT. Exit 1 when no run is found or a run lacks the flow figures.
"""
import csv
import glob
import json
import os
import sys


def num(d, key):
    v = d.get(key)
    return float(v) if isinstance(v, (int, float)) else float("nan")


def finish_figure(fig, dest, stem, title):
    """Titles, lays out and writes DEST/STEM.png; names it beside DEST/STEM.csv."""
    fig.suptitle(title)
    fig.tight_layout()
    png = os.path.join(dest, stem + ".png")
    fig.savefig(png, dpi=110)
    print("wrote %s and %s" % (os.path.join(dest, stem + ".csv"), png))


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    out = sys.argv[1]
    dest = sys.argv[2] if len(sys.argv) > 2 else out
    rows = []
    for path in sorted(glob.glob(os.path.join(out, "l*", "summary.json"))):
        with open(path) as f:
            s = json.load(f)
        c, ch = s.get("cutting", {}), s.get("chip", {})
        if "flow_angle_deg" not in ch:
            print("compare.py: %s has no chip flow angle: %s" % (path, ch.get("flow_note", "not a cut with free "
                                                                                  "sides")), file=sys.stderr)
            return 1
        rows.append({
            "inclination_deg": num(ch, "inclination_deg"),
            "flow_angle_deg": num(ch, "flow_angle_deg"),
            "flow_angle_ci95_deg": num(ch, "flow_angle_ci95_deg"),
            "stabler_deg": num(ch, "flow_angle_stabler_deg"),
            "chip_width_to_cut_width": num(ch, "width_to_cut_width"),
            "Fc_per_width_kN_per_m": num(c, "cutting_force_per_width_mean_N_per_m") / 1e3,
            "Fc_ci95_kN_per_m": num(c, "cutting_force_per_width_ci95_N_per_m") / 1e3,
            "Ft_per_width_kN_per_m": num(c, "thrust_force_per_width_mean_N_per_m") / 1e3,
            "Ft_ci95_kN_per_m": num(c, "thrust_force_per_width_ci95_N_per_m") / 1e3,
            "Fp_per_width_kN_per_m": num(c, "passive_force_per_width_mean_N_per_m") / 1e3,
            "Fp_ci95_kN_per_m": num(c, "passive_force_per_width_ci95_N_per_m") / 1e3,
            "chip_thickness_mm": num(ch, "thickness_m") * 1e3,
            "width_mm": num(c, "width_m") * 1e3,
            "run": os.path.basename(os.path.dirname(path)),
        })
    if not rows:
        print("compare.py: no OUT/l*/summary.json in %s" % out, file=sys.stderr)
        return 1
    rows.sort(key=lambda r: r["inclination_deg"])
    print("| lambda (deg) | eta_c (deg) | Stabler (deg) | chip width / cut width | Fc/w (kN/m) | Ft/w (kN/m) | "
          "Fp/w (kN/m) | h_c (mm) |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        print("| %.0f | %.1f +- %.1f | %.0f | %.2f | %.0f +- %.0f | %.0f +- %.0f | %.1f +- %.1f | %.3f |" % (
            r["inclination_deg"], r["flow_angle_deg"], r["flow_angle_ci95_deg"], r["stabler_deg"],
            r["chip_width_to_cut_width"], r["Fc_per_width_kN_per_m"], r["Fc_ci95_kN_per_m"],
            r["Ft_per_width_kN_per_m"], r["Ft_ci95_kN_per_m"], r["Fp_per_width_kN_per_m"], r["Fp_ci95_kN_per_m"],
            r["chip_thickness_mm"]))
    os.makedirs(dest, exist_ok=True)
    with open(os.path.join(dest, "oblique.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    lam = [r["inclination_deg"] for r in rows]
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4))
    a1.errorbar(lam, [r["flow_angle_deg"] for r in rows], yerr=[r["flow_angle_ci95_deg"] for r in rows], fmt="o-",
                capsize=3, label="swarf (5 layers, b = %.2g mm)" % rows[0]["width_mm"])
    top = max(lam + [r["flow_angle_deg"] for r in rows]) * 1.1 + 1
    a1.plot([0, top], [0, top], "k--", label="Stabler: eta_c = lambda")
    a1.set_xlabel("inclination lambda (deg)")
    a1.set_ylabel("chip flow angle eta_c (deg)")
    a1.legend()
    a1.grid(alpha=0.3)
    for key, ci, label in (("Fc_per_width_kN_per_m", "Fc_ci95_kN_per_m", "Fc/w"),
                           ("Ft_per_width_kN_per_m", "Ft_ci95_kN_per_m", "Ft/w"),
                           ("Fp_per_width_kN_per_m", "Fp_ci95_kN_per_m", "Fp/w")):
        a2.errorbar(lam, [r[key] for r in rows], yerr=[r[ci] for r in rows], fmt="o-", capsize=3, label=label)
    a2.set_xlabel("inclination lambda (deg)")
    a2.set_ylabel("force per width (kN/m)")
    a2.legend()
    a2.grid(alpha=0.3)
    finish_figure(fig, dest, "oblique", "Oblique cut of C45, h = 0.2 mm, 600 m/min, normal rake 10 deg")
    return 0


if __name__ == "__main__":
    sys.exit(main())
