#!/usr/bin/python3
"""The cutting speed x uncut chip thickness study of the default cut with heat, beside Oxley.

  validation/cutting/plot_speed_feed.py STUDY_DIR [--out DIR]

STUDY_DIR: the study directory of validation/studies/speed_feed.toml (swarf sweep ... --out DIR).
Reads its study.csv (the steady means, the oxley.* columns every cutting run writes) and
  - prints a Markdown table per point (h, v): the mean over the seeds with a 95 % interval,
    Oxley's figure at the same conditions and their ratio, for Fc/w, Ft/w, h_c, the rake-face
    and chip temperatures; the speed trend Fc(v) / Fc(fastest) per depth beside Oxley's; and
    Kienzle's fit Fc/w = kc1.1 b h^(1 - mc) per speed (least squares in log-log on the means);
  - draws speed_feed.png (Fc/w against h per speed, Fc/w, Ft/w, h_c and the rake-face
    temperature against v per depth, Oxley dashed in the same colour).

The interval of a point's mean: the seeds' scatter pooled over the points as a relative
variance (the scatter is assumed proportional to the mean, the same at every point; each
point has only two seeds, whose own t interval, t(1) = 12.7, would say little), times
t(pooled degrees of freedom) / sqrt(seeds). The pooled relative standard deviation is printed.
"""
import argparse
import csv
import math
import os
from collections import defaultdict

import numpy as np

METRICS = [  # column, Oxley's column, label, scale, unit
    ("cutting.cutting_force_per_width_mean_N_per_m", "oxley.cutting_force_per_width_N_per_m", "Fc/w", 1e-3, "kN/m"),
    ("cutting.thrust_force_per_width_mean_N_per_m", "oxley.thrust_force_per_width_N_per_m", "Ft/w", 1e-3, "kN/m"),
    ("chip.thickness_m", "oxley.chip_thickness_m", "h_c", 1e3, "mm"),
    ("chip.rake_face_temperature_K", "oxley.rake_face_temperature_K", "T rake face", 1.0, "K"),
    ("chip.chip_temperature_K", None, "T chip", 1.0, "K"),
]
T975 = {1: 12.706, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571, 6: 2.447, 7: 2.365, 8: 2.306, 9: 2.262, 10: 2.228,
        12: 2.179, 15: 2.131, 18: 2.101, 20: 2.086, 30: 2.042}


def t975(df):
    """Student's t, 97.5 % quantile (two-sided 95 %), for df degrees of freedom (the next lower tabulated)."""
    keys = [k for k in sorted(T975) if k <= df]
    return T975[keys[-1]] if keys else float("nan")


def number(r, name):
    v = r.get(name)
    try:
        return float(v)
    except (TypeError, ValueError):
        return float("nan")


def load(directory):
    with open(os.path.join(directory, "study.csv"), newline="") as f:
        table = [r for r in csv.DictReader(f) if r.get("status") == "completed"]
    points = defaultdict(list)  # (origin text, speed m/s) -> rows
    for r in table:
        v = float(r["mesh.0.velocity"].strip("[]").split(",")[0])
        points[(r["mesh.0.origin"], v)].append(r)
    return points


def summarise(points):
    """Per point: mean depth h (m), speed v (m/s), and per metric the seeds' mean, relative variance, Oxley's mean."""
    out = []
    for (origin, v), rows in points.items():
        p = {"h": np.mean([number(r, "chip.depth_of_cut_m") for r in rows]), "v": v, "n": len(rows)}
        for col, ox, *_ in METRICS:
            y = np.array([number(r, col) for r in rows])
            y = y[np.isfinite(y)]
            p[col] = (y.mean() if len(y) else np.nan, y.var(ddof=1) / y.mean() ** 2 if len(y) > 1 else np.nan, len(y))
            p[col + ":ox"] = np.nanmean([number(r, ox) for r in rows]) if ox else np.nan
        out.append(p)
    out.sort(key=lambda p: (p["v"], p["h"]))
    return out


def pooled(points, col):
    """Pooled relative standard deviation of one seed's result and its degrees of freedom."""
    num = sum((p[col][2] - 1) * p[col][1] for p in points if p[col][2] > 1 and np.isfinite(p[col][1]))
    df = sum(p[col][2] - 1 for p in points if p[col][2] > 1 and np.isfinite(p[col][1]))
    return (math.sqrt(num / df) if df else float("nan")), df


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("study")
    ap.add_argument("--out", default=os.path.dirname(os.path.abspath(__file__)))
    a = ap.parse_args()
    pts = summarise(load(a.study))
    half = {}
    print("Pooled seed-to-seed scatter (relative standard deviation of one run, degrees of freedom):")
    for col, ox, label, scale, unit in METRICS:
        s, df = pooled(pts, col)
        half[col] = (s, df)
        print(f"- {label}: {100 * s:.2f} % ({df} df)")
    print()
    print("| h (mm) | v (m/min) | seeds | " + " | ".join(f"{m[2]} swarf / Oxley [{m[4]}]" for m in METRICS) + " |")
    print("|---" * (3 + len(METRICS)) + "|")
    for p in pts:
        cells = []
        for col, ox, label, scale, unit in METRICS:
            mean, _, n = p[col]
            s, df = half[col]
            ci = t975(df) * s * abs(mean) / math.sqrt(n) if n else float("nan")
            o = p[col + ":ox"]
            cell = f"{scale * mean:.4g} +- {scale * ci:.2g}"
            if ox and np.isfinite(o):
                cell += f" / {scale * o:.4g} = {mean / o:.2f}"
            cells.append(cell)
        print(f"| {1e3 * p['h']:.3f} | {60 * p['v']:.0f} | {p['n']} | " + " | ".join(cells) + " |")
    print()
    speeds = sorted({p["v"] for p in pts})
    fastest = speeds[-1]
    fc, fc_ox = METRICS[0][0], METRICS[0][0] + ":ox"
    print(f"Speed trend: Fc/w(v) / Fc/w({60 * fastest:.0f} m/min), swarf (Oxley):")
    print()
    print("| h (mm) | " + " | ".join(f"{60 * v:.0f} m/min" for v in speeds) + " |")
    print("|---" * (1 + len(speeds)) + "|")
    depths = sorted({round(p["h"], 6) for p in pts})
    for h in depths:
        row = {p["v"]: p for p in pts if round(p["h"], 6) == h}
        if fastest not in row:
            continue
        ref, ref_ox = row[fastest][fc][0], row[fastest][fc_ox]
        cells = [f"{row[v][fc][0] / ref:.3f} ({row[v][fc_ox] / ref_ox:.3f})" if v in row else "-" for v in speeds]
        print(f"| {1e3 * h:.2f} | " + " | ".join(cells) + " |")
    print()
    print("Kienzle's fit per speed on the means (Fc/w = kc1.1 * 1 mm * h^(1 - mc), h in mm), swarf (Oxley):")
    print()
    print("| v (m/min) | kc1.1 (N/mm^2) | 1 - mc | Oxley kc1.1 | Oxley 1 - mc |")
    print("|---|---|---|---|---|")
    for v in speeds:
        row = [p for p in pts if p["v"] == v]
        if len(row) < 2:
            continue
        h = np.log([1e3 * p["h"] for p in row])
        fits = []
        for y in ([p[fc][0] for p in row], [p[fc_ox] for p in row]):
            slope, icpt = np.polyfit(h, np.log(np.array(y) * 1e-3), 1)  # N/mm against mm
            fits.append((math.exp(icpt), slope))
        print(f"| {60 * v:.0f} | {fits[0][0]:.0f} | {fits[0][1]:.3f} | {fits[1][0]:.0f} | {fits[1][1]:.3f} |")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, 3, figsize=(14, 8.2))
    panels = [(axes[0, 0], "h", 0), (axes[0, 1], "v", 0), (axes[0, 2], "v", 1), (axes[1, 0], "v", 2),
              (axes[1, 1], "v", 3), (axes[1, 2], "v", 4)]
    for ax, against, k in panels:
        col, ox, label, scale, unit = METRICS[k]
        s, df = half[col]
        keys = speeds if against == "h" else depths
        for g, key in enumerate(keys):
            row = [p for p in pts if (p["v"] == key if against == "h" else round(p["h"], 6) == key)]
            row.sort(key=lambda p: p["h"] if against == "h" else p["v"])
            x = [1e3 * p["h"] if against == "h" else 60 * p["v"] for p in row]
            y = np.array([scale * p[col][0] for p in row])
            e = np.array([t975(df) * s * abs(yy) / math.sqrt(p[col][2]) for yy, p in zip(y, row)])
            name = f"{60 * key:.0f} m/min" if against == "h" else f"h = {1e3 * key:.1f} mm"
            ax.errorbar(x, y, yerr=e, fmt="o-", ms=5, capsize=3, color=f"C{g}", label=f"swarf, {name}")
            yo = [scale * p[col + ":ox"] for p in row]
            if ox and np.all(np.isfinite(yo)):
                ax.plot(x, yo, "x--", ms=7, color=f"C{g}", lw=1.3, label=f"Oxley, {name}")
        ax.set_xlabel("uncut chip thickness h [mm]" if against == "h" else "cutting speed v [m/min]")
        ax.set_ylabel(f"{label} [{unit}]")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
    axes[1, 1].set_title("swarf: the hottest particle of the rake-face layer; Oxley: mean interface T", fontsize=8)
    fig.suptitle("Default C45 cut with heat (rake 10 deg, R = 14.1 um, edge radius 20 um): h x v, "
                 "means over 2 seeds with pooled 95 % intervals; dashed: Oxley's theory (sharp tool)", fontsize=10)
    fig.tight_layout()
    path = os.path.join(a.out, "speed_feed.png")
    fig.savefig(path, dpi=100)
    print(f"\nwrote {path}")


if __name__ == "__main__":
    main()
