#!/usr/bin/python3
"""Compare published orthogonal-cutting measurements with Oxley's model and a swarf study.

    /usr/bin/python3 validation/cutting/measured/compare_measured.py [--study DIR] [options]

Reads every *.csv in this directory (the measured data sets; their columns and sources are in
README.md here), and:
  - runs Oxley's model (`swarf oxley`, AISI 1045 with Jaspers' Johnson-Cook set) at each measured
    AISI 1045 / C45 / Ck45 point with a known rake angle, and on a stand-in grid of speeds and
    depths of cut (the force-speed curves of the C45 plot); never for Ti6Al4V, which that model's
    material is not;
  - with --study DIR, reads DIR/study.csv (swarf sweep) and matches its completed cases with the
    measured points of the same material by speed, uncut chip thickness and rake angle; for a C45
    study it also runs Oxley at each case;
  - summarises each measured set: means per (speed, h), repeatability, the speed trend of Fc per h
    and the Kienzle exponent 1 - mc at fixed speed (log-log least squares);
  - writes comparison.md (also on stdout) and the plots measured_vs_oxley_fc.png, _ft.png, _hc.png
    (measured against predicted, y = x and the +-15 % band) and measured_fc_vs_speed.png,
    measured_kienzle.png, next to this script (or in --out).

Units: speed m/min, h and h_c mm, forces per width N/mm (= kN/m), forces N, edge radius um.
Targets (the issue's): Fc within 15 %, Ft within 30 %, h_c within 15 % of the measurement.
"""
import argparse
import csv
import glob
import math
import os
import re
import subprocess
import sys
from collections import defaultdict

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
STEEL = {"aisi1045", "c45", "ck45", "c45e", "1045"}
TARGET = {"fc": 0.15, "ft": 0.30, "hc": 0.15}
STUDY_FC = "cutting.cutting_force_per_width_mean_N_per_m"
STUDY_FT = "cutting.thrust_force_per_width_mean_N_per_m"
STUDY_FC_CI = "cutting.cutting_force_per_width_ci95_N_per_m"
STUDY_FT_CI = "cutting.thrust_force_per_width_ci95_N_per_m"
STUDY_H = "chip.depth_of_cut_m"
STUDY_HC = "chip.thickness_m"
STUDY_HC_CI = "chip.thickness_ci95_m"
STUDY_RAKE = "chip.rake_angle_deg"


def is_steel(material):
    return re.sub(r"[^a-z0-9]", "", material.lower()) in STEEL


def fnum(s):
    """A float from a CSV cell; None when empty or not a number."""
    try:
        v = float(s)
    except (TypeError, ValueError):
        return None
    return v if math.isfinite(v) else None


# ---------------------------------------------------------------- measured data
def load_measured(directory, width_mm):
    """All rows of the measured CSVs, with numbers parsed and per-width forces derived."""
    rows = []
    for path in sorted(glob.glob(os.path.join(directory, "*.csv"))):
        with open(path, newline="") as f:
            for r in csv.DictReader(f):
                if r.get("status", "") == "error":
                    continue
                p = {k: r.get(k, "") for k in r}
                p["file"] = os.path.basename(path)
                for k in ("speed_m_per_min", "uncut_thickness_mm", "width_mm", "rake_deg", "edge_radius_um",
                          "fc_n_per_mm", "ft_n_per_mm", "chip_thickness_mm", "fc_n", "ft_n"):
                    p[k] = fnum(r.get(k))
                w = p["width_mm"]
                if w is None and p["fc_n"] is not None and width_mm:
                    w = width_mm  # the width assumed on the command line
                    p["note"] = (p["note"] + "; " if p["note"] else "") + f"width {width_mm} mm assumed"
                if p["fc_n_per_mm"] is None and p["fc_n"] is not None and w:
                    p["fc_n_per_mm"] = p["fc_n"] / w
                if p["ft_n_per_mm"] is None and p["ft_n"] is not None and w:
                    p["ft_n_per_mm"] = p["ft_n"] / w
                if p["speed_m_per_min"] is None or p["uncut_thickness_mm"] is None:
                    continue
                rows.append(p)
    return rows


# ---------------------------------------------------------------- Oxley
class Oxley:
    """`swarf oxley` runs, cached by (speed, h, rake)."""

    NAMES = {"Fc per width": "fc_per_w_N_per_m", "thrust force Ft": "ft_N", "cutting force Fc": "fc_N",
             "chip thickness h_c": "hc_m", "shear angle": "phi_deg"}

    def __init__(self, binary):
        self.binary = binary
        self.cache = {}
        self.calls = 0

    def __call__(self, v_m_per_min, h_mm, rake_deg):
        key = (round(v_m_per_min, 6), round(h_mm, 9), round(rake_deg, 6))
        if key in self.cache:
            return self.cache[key]
        width = 1e-3  # m; the per-width results do not depend on it
        cmd = [self.binary, "oxley", "--speed", repr(v_m_per_min / 60.0), "--uncut-thickness", repr(h_mm * 1e-3),
               "--rake-angle", repr(rake_deg), "--width", repr(width)]
        self.calls += 1
        p = subprocess.run(cmd, capture_output=True, text=True)
        res = {"ok": p.returncode == 0, "reason": p.stderr.strip().splitlines()[-1] if p.stderr.strip() else ""}
        if p.returncode == 0:
            for line in p.stdout.splitlines():
                cells = [c.strip() for c in line.strip().strip("|").split("|")]
                if len(cells) == 3 and cells[0] in self.NAMES:
                    res[self.NAMES[cells[0]]] = float(cells[1])
            res["fc"] = res["fc_per_w_N_per_m"] / 1000.0  # N/mm
            res["ft"] = res["ft_N"] / width / 1000.0  # N/mm
            res["hc"] = res["hc_m"] * 1000.0  # mm
        self.cache[key] = res
        return res


# ---------------------------------------------------------------- swarf study
def toml_speed(text):
    """A speed from a TOML value text: a number, or the first component of an array (m/s)."""
    nums = re.findall(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?", text or "")
    return abs(float(nums[0])) if nums else None


def load_study(directory, speed_key, speed_m_per_s):
    path = os.path.join(directory, "study.csv")
    with open(path, newline="") as f:
        table = list(csv.DictReader(f))
    if not table:
        return [], "study.csv has no rows"
    cols = list(table[0].keys())
    note = f"speed {speed_m_per_s:g} m/s for every case (--speed-m-per-s)" if speed_m_per_s is not None else ""
    if speed_key is None and speed_m_per_s is None and "oxley.speed_m_per_s" in cols:
        # Runs from 2026-12-06 on record the tool's cutting speed with Oxley's reference.
        speed_key = "oxley.speed_m_per_s"
        note = "speed from each case's summary (oxley.speed_m_per_s, m/s)"
    elif speed_key is None and speed_m_per_s is None:
        guess = [c for c in cols if c.endswith("velocity") or c.endswith("speed")]
        speed_key = guess[0] if guess else None
        note = (f"speed from the varied key {speed_key} (m/s, first component)" if speed_key else
                "no speed in the study (give --speed-key or --speed-m-per-s): matched by h and rake only")
    rows = []
    for r in table:
        if r.get("status") != "completed":
            continue
        v = None
        if speed_m_per_s is not None:
            v = speed_m_per_s
        elif speed_key:
            v = toml_speed(r.get(speed_key))
        h = fnum(r.get(STUDY_H))
        if h is None:
            continue
        s = {"case": r.get("case", ""), "speed_m_per_min": v * 60.0 if v is not None else None,
             "uncut_thickness_mm": h * 1e3, "rake_deg": fnum(r.get(STUDY_RAKE))}
        for k, col, scale in (("fc", STUDY_FC, 1e-3), ("ft", STUDY_FT, 1e-3), ("hc", STUDY_HC, 1e3),
                              ("fc_ci", STUDY_FC_CI, 1e-3), ("ft_ci", STUDY_FT_CI, 1e-3), ("hc_ci", STUDY_HC_CI, 1e3)):
            x = fnum(r.get(col))
            s[k] = x * scale if x is not None else None
        rows.append(s)
    return rows, note


def matches(m, s, tol):
    """A study case s at the measured point m: h (and speed, rake where both have them) within tolerance."""
    if abs(s["uncut_thickness_mm"] - m["uncut_thickness_mm"]) > tol["h"] * m["uncut_thickness_mm"]:
        return False
    if m["speed_m_per_min"] is not None and s["speed_m_per_min"] is not None:
        if abs(s["speed_m_per_min"] - m["speed_m_per_min"]) > tol["v"] * m["speed_m_per_min"]:
            return False
    if m["rake_deg"] is not None and s["rake_deg"] is not None:
        if abs(s["rake_deg"] - m["rake_deg"]) > tol["rake"]:
            return False
    return True


# ---------------------------------------------------------------- statistics of the measured sets
def group_means(rows):
    """Means over the repeated tests at one (file, campaign, speed, h)."""
    g = defaultdict(list)
    for r in rows:
        g[(r["file"], campaign(r), r["speed_m_per_min"], r["uncut_thickness_mm"], r["rake_deg"])].append(r)
    out = []
    for (fname, camp, v, h, rake), rs in sorted(g.items(), key=lambda kv: (kv[0][0], kv[0][1], kv[0][3], kv[0][2])):
        def mean(k):
            x = [r[k] for r in rs if r[k] is not None]
            return (float(np.mean(x)), float(np.std(x, ddof=1)) if len(x) > 1 else None, len(x)) if x else (None, None, 0)
        out.append({"file": fname, "campaign": camp, "speed_m_per_min": v, "uncut_thickness_mm": h, "rake_deg": rake,
                    "n": len(rs), "fc_n": mean("fc_n"), "ft_n": mean("ft_n"), "fc": mean("fc_n_per_mm"),
                    "ft": mean("ft_n_per_mm"), "hc": mean("chip_thickness_mm"), "rn": mean("edge_radius_um"),
                    "material": rs[0]["material"]})
    return out


def campaign(r):
    """Klippel's table holds two test series (ids V00xx and V03xx-V05xx, other tools and edges)."""
    t = r.get("test_id", "")
    if r["file"].startswith("klippel2024") and t.startswith("V"):
        return "V00xx" if int(t[1:]) < 300 else "V03xx-V05xx"
    return ""


def slices(groups, fixed, along):
    """(series, value of `fixed`, the groups at it sorted by `along`) wherever there are 3 or more."""
    for camp in sorted({g["campaign"] for g in groups}):
        for x in sorted({g[fixed] for g in groups if g["campaign"] == camp}):
            sub = sorted((g for g in groups if g["campaign"] == camp and g[fixed] == x), key=lambda g: g[along])
            if len(sub) >= 3:
                yield camp, x, sub


def force_key(groups):
    """The force to fit: per width where known, else N (exponents and trends need no width)."""
    return "fc" if all(g["fc"][0] is not None for g in groups) else "fc_n"


def loglog_fit(h, f):
    a, b = np.polyfit(np.log(h), np.log(f), 1)
    return a, math.exp(b)


# ---------------------------------------------------------------- formatting
def fmt(x, d=1):
    return "-" if x is None else f"{x:.{d}f}"


def err(pred, meas):
    if pred is None or meas is None or meas == 0:
        return None
    return (pred - meas) / meas


def verdict(e, tol):
    if e is None:
        return "-"
    return f"{100 * e:+.0f} % {'ok' if abs(e) <= tol else 'no'}"


def md_table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return "\n".join(out)


# ---------------------------------------------------------------- plots
def scatter_plot(path, quantity, label, pairs, tol, empty_note):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 5.5))
    allv = [v for p in pairs for v in (p[1], p[2])]
    hi = 1.15 * max(allv) if allv else 1.0
    x = np.array([0, hi])
    ax.plot(x, x, "k-", lw=1, label="y = x")
    ax.fill_between(x, 0.85 * x, 1.15 * x, color="0.85", label="+-15 %")
    if quantity == "ft":
        ax.plot(x, 0.7 * x, "k:", lw=1, label="+-30 % (Ft target)")
        ax.plot(x, 1.3 * x, "k:", lw=1)
    styles = {"Oxley": ("o", "C0"), "swarf": ("s", "C3")}
    for name, (marker, color) in styles.items():
        pts = [(m, p) for who, m, p, _ in pairs if who == name]
        if pts:
            ax.plot([m for m, _ in pts], [p for _, p in pts], marker, color=color, ls="none", ms=7,
                    label=f"{name} ({len(pts)})")
            for who, m, p, tag in pairs:
                if who == name and tag:
                    ax.annotate(tag, (m, p), fontsize=7, xytext=(4, -8), textcoords="offset points")
    if not pairs:
        ax.text(0.5, 0.5, empty_note, ha="center", va="center", transform=ax.transAxes, fontsize=10, wrap=True,
                bbox=dict(fc="white", ec="0.5"))
    ax.set_xlim(0, hi)
    ax.set_ylim(0, hi)
    ax.set_xlabel(f"measured {label}")
    ax.set_ylabel(f"predicted {label}")
    ax.set_title(f"{label}: predicted against measured (target {int(100 * tol)} %)")
    ax.legend(loc="upper left", fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def speed_plot(path, groups, grid, measured_steel, study_pts, grid_rake):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(12, 5))
    ti = [g for g in groups if not is_steel(g["material"])]
    hs = sorted({g["uncut_thickness_mm"] for g in ti})
    cmap = plt.get_cmap("viridis")
    for i, h in enumerate(hs):
        col = cmap(i / max(1, len(hs) - 1))
        for camp, marker in (("V00xx", "s"), ("V03xx-V05xx", "o")):
            gs = sorted((g for g in ti if g["uncut_thickness_mm"] == h and g["campaign"] == camp),
                        key=lambda g: g["speed_m_per_min"])
            if gs:
                a1.plot([g["speed_m_per_min"] for g in gs], [g["fc_n"][0] for g in gs], marker + "-", color=col,
                        ms=4, lw=1, label=f"h = {h:g} mm" if camp == "V03xx-V05xx" or
                        not any(g["campaign"] == "V03xx-V05xx" and g["uncut_thickness_mm"] == h for g in ti) else None)
    a1.set_xscale("log")
    a1.set_xticks([10, 20, 50, 100, 200, 500])
    a1.set_xticklabels(["10", "20", "50", "100", "200", "500"])
    a1.set_xlabel("cutting speed (m/min)")
    a1.set_ylabel("Fc (N) on the tested width (width not in the table)")
    a1.set_title("Ti6Al4V, measured (Klippel et al. 2024)\ncircles: tests V03xx-V05xx, squares: V00xx")
    a1.legend(fontsize=7, ncol=2)
    a1.grid(alpha=0.3, which="both")
    ghs = sorted({h for (_, h) in grid})
    for i, h in enumerate(ghs):
        vs = sorted(v for (v, hh) in grid if hh == h and grid[(v, hh)]["ok"])
        a2.plot(vs, [grid[(v, h)]["fc"] for v in vs], "-", color=f"C{i}", label=f"Oxley, h = {h:g} mm")
    for r in measured_steel:
        if r["fc_n_per_mm"] is not None:
            a2.plot(r["speed_m_per_min"], r["fc_n_per_mm"], "k^", ms=7)
            a2.annotate(f"h {r['uncut_thickness_mm']:g}, rake {fmt(r['rake_deg'], 0)}",
                        (r["speed_m_per_min"], r["fc_n_per_mm"]), fontsize=7, xytext=(4, 3), textcoords="offset points")
    for s in study_pts:
        if s["speed_m_per_min"] is not None and s["fc"] is not None:
            a2.plot(s["speed_m_per_min"], s["fc"], "s", color="C3", ms=6)
            a2.annotate(f"h {s['uncut_thickness_mm']:.3g}, rake {fmt(s['rake_deg'], 0)}", (s["speed_m_per_min"], s["fc"]),
                        fontsize=7, color="C3", xytext=(4, -9), textcoords="offset points")
    n_steel = sum(r["fc_n_per_mm"] is not None for r in measured_steel)
    a2.plot([], [], "k^", label=f"measured AISI 1045 / C45 ({n_steel}; h mm, rake deg)")
    if study_pts:
        a2.plot([], [], "s", color="C3", label="swarf study")
    a2.set_xscale("log")
    ticks = sorted({v for (v, _) in grid} | {r["speed_m_per_min"] for r in measured_steel})
    if ticks:
        a2.set_xticks(ticks)
        a2.set_xticklabels([f"{t:g}" for t in ticks])
        a2.minorticks_off()
    a2.set_xlabel("cutting speed (m/min)")
    a2.set_ylabel("Fc / width (N/mm = kN/m)")
    a2.set_title(f"AISI 1045 / C45: Oxley stand-in (rake {grid_rake:g} deg, sharp tool)"
                 + ("" if measured_steel else "\nno measured point available"))
    a2.legend(fontsize=8)
    a2.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def kienzle_plot(path, fits):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.5, 5))
    for i, f in enumerate(fits):
        col = f"C{i % 10}"
        ax.plot(f["h_all"], f["f_all"], "o", color=col, ms=4)
        hh = np.array([min(f["h_fit"]), max(f["h_fit"])])
        ax.plot(hh, f["c"] * hh ** f["slope"], "-", color=col,
                label=f"{f['label']}: 1 - mc = {f['slope']:.2f}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("uncut chip thickness h (mm)")
    ax.set_ylabel("Fc (N, tested width) or Fc/b (N/mm)")
    ax.set_title("Kienzle fits at fixed speed (lines: fitted range)")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


# ---------------------------------------------------------------- main
def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--study", help="a swarf sweep output directory (its study.csv is read)")
    ap.add_argument("--study-material", default="C45", help="material of the study's cases (C45 or Ti6Al4V)")
    ap.add_argument("--speed-key", help="study.csv column holding the tool velocity (m/s, TOML number or array)")
    ap.add_argument("--speed-m-per-s", type=float, help="the study's cutting speed when it does not vary")
    ap.add_argument("--width-mm", type=float,
                    help="width of cut to assume for measured rows with forces in N and no width (Klippel's Ti6Al4V)")
    ap.add_argument("--swarf", default="/work/main/build/bin/swarf", help="the swarf binary (for swarf oxley)")
    ap.add_argument("--no-oxley", action="store_true", help="do not run Oxley's model")
    ap.add_argument("--grid-rake", type=float, default=10.0, help="rake angle of the Oxley stand-in grid, deg")
    ap.add_argument("--grid-speeds", default="50,100,200,300,400,600", help="stand-in grid speeds, m/min")
    ap.add_argument("--grid-h", default="0.1,0.2,0.3", help="stand-in grid uncut thicknesses, mm")
    ap.add_argument("--h-tol", type=float, default=0.10, help="relative h tolerance for matching (0.10)")
    ap.add_argument("--v-tol", type=float, default=0.10, help="relative speed tolerance for matching (0.10)")
    ap.add_argument("--rake-tol", type=float, default=1.0, help="rake tolerance for matching, deg (1)")
    ap.add_argument("--out", default=HERE, help="where comparison.md and the PNGs go (this directory)")
    a = ap.parse_args()
    tol = {"h": a.h_tol, "v": a.v_tol, "rake": a.rake_tol}

    rows = load_measured(HERE, a.width_mm)
    steel = [r for r in rows if is_steel(r["material"])]
    other = [r for r in rows if not is_steel(r["material"])]
    oxley = None if a.no_oxley else Oxley(a.swarf)
    md = ["# Measured orthogonal cutting against Oxley's model" + (" and swarf" if a.study else ""), "",
          "Written by compare_measured.py (see README.md for the sources and what each number is). "
          "Forces per width in N/mm (= kN/m), h and h_c in mm, speeds in m/min. Targets: Fc within 15 %, "
          "Ft within 30 %, h_c within 15 % of the measurement (relative error = (predicted - measured) / measured).",
          ""]
    if a.width_mm:
        md += [f"**Forces given in N without a width (Klippel's Ti6Al4V table) are divided by an assumed width of "
               f"{a.width_mm:g} mm (--width-mm): not a width read from the source.**", ""]
    pairs = {"fc": [], "ft": [], "hc": []}

    # ---- measured steel against Oxley
    md += ["## Measured AISI 1045 / C45 against Oxley", ""]
    if not steel:
        md += ["No measured AISI 1045 / C45 / Ck45 point is in this directory (README.md says which data sets "
               "could not be obtained and why), so there is nothing to compare Oxley's model with here. Oxley's "
               "model is AISI 1045 with Jaspers' Johnson-Cook set and is not run for Ti6Al4V.", ""]
    elif oxley is None:
        md += ["(--no-oxley: not run)", ""]
    else:
        table = []
        for r in steel:
            if r["rake_deg"] is None:
                table.append([r["file"], fmt(r["speed_m_per_min"], 0), fmt(r["uncut_thickness_mm"], 3), "?"] +
                             ["-"] * 9 + ["no rake angle: not run"])
                continue
            o = oxley(r["speed_m_per_min"], r["uncut_thickness_mm"], r["rake_deg"])
            if not o["ok"]:
                table.append([r["file"], fmt(r["speed_m_per_min"], 0), fmt(r["uncut_thickness_mm"], 3),
                              fmt(r["rake_deg"], 0)] + ["-"] * 9 + ["Oxley: no solution, " + o["reason"]])
                continue
            tag = r.get("note", "")[:18]
            cells = []
            for q, mk in (("fc", "fc_n_per_mm"), ("ft", "ft_n_per_mm"), ("hc", "chip_thickness_mm")):
                e = err(o[q], r[mk])
                cells += [fmt(r[mk], 3 if q == "hc" else 1), fmt(o[q], 3 if q == "hc" else 1), verdict(e, TARGET[q])]
                if r[mk] is not None:
                    pairs[q].append(("Oxley", r[mk], o[q], r.get("lab", "") or ""))
            table.append([r["file"], fmt(r["speed_m_per_min"], 0), fmt(r["uncut_thickness_mm"], 3),
                          fmt(r["rake_deg"], 0)] + cells + [tag])
        md += [md_table(["source", "V", "h", "rake", "Fc meas", "Fc Oxley", "Fc err", "Ft meas", "Ft Oxley",
                         "Ft err", "h_c meas", "h_c Oxley", "h_c err", "note"], table), ""]
        for q in ("fc", "ft", "hc"):
            es = [abs(err(p, m)) for who, m, p, _ in pairs[q] if who == "Oxley"]
            if es:
                md.append(f"- {q}: {len(es)} points, mean |error| {100 * np.mean(es):.0f} %, "
                          f"{sum(e <= TARGET[q] for e in es)} of {len(es)} within {int(100 * TARGET[q])} %")
        md.append("")

    # ---- the swarf study
    study = []
    if a.study:
        study, note = load_study(a.study, a.speed_key, a.speed_m_per_s)
        smat_steel = is_steel(a.study_material)
        md += [f"## swarf study {a.study} ({a.study_material}) against the measurements", "",
               f"{len(study)} completed cases. {note}", ""]
        table = []
        for r in (steel if smat_steel else [x for x in other if x["material"].lower() == a.study_material.lower()]):
            for s in study:
                if not matches(r, s, tol):
                    continue
                cells = []
                for q, mk in (("fc", "fc_n_per_mm"), ("ft", "ft_n_per_mm"), ("hc", "chip_thickness_mm")):
                    e = err(s[q], r[mk])
                    ci = s[q + "_ci"]
                    d = 3 if q == "hc" else 1
                    cells += [fmt(r[mk], d), fmt(s[q], d) + ("" if ci is None else f" +- {ci:.{d}f}"),
                              verdict(e, TARGET[q])]
                    if r[mk] is not None and s[q] is not None:
                        pairs[q].append(("swarf", r[mk], s[q], ""))
                table.append([r["file"] + " " + r.get("test_id", ""), fmt(r["speed_m_per_min"], 0),
                              fmt(r["uncut_thickness_mm"], 3), fmt(r["rake_deg"], 0), s["case"]] + cells)
        if table:
            md += [md_table(["measured", "V", "h", "rake", "swarf case", "Fc meas", "Fc swarf", "Fc err", "Ft meas",
                             "Ft swarf", "Ft err", "h_c meas", "h_c swarf", "h_c err"], table), ""]
        else:
            md += ["No study case matches a measured point of this material (h within "
                   f"{int(100 * tol['h'])} %, speed within {int(100 * tol['v'])} %, rake within {tol['rake']:g} deg "
                   "where both give them).", ""]
        if smat_steel and oxley is not None:
            table = []
            for s in study:
                if s["speed_m_per_min"] is None or s["rake_deg"] is None:
                    continue
                o = oxley(s["speed_m_per_min"], s["uncut_thickness_mm"], s["rake_deg"])
                if not o["ok"]:
                    continue
                cells = []
                for q in ("fc", "ft", "hc"):
                    d = 3 if q == "hc" else 1
                    cells += [fmt(s[q], d), fmt(o[q], d), verdict(err(s[q], o[q]), TARGET[q])]
                table.append([s["case"], fmt(s["speed_m_per_min"], 0), fmt(s["uncut_thickness_mm"], 3),
                              fmt(s["rake_deg"], 0)] + cells)
            if table:
                md += ["### The study's cases against Oxley (a model, not a measurement: swarf's deviation from it)",
                       "", md_table(["case", "V", "h", "rake", "Fc swarf", "Fc Oxley", "dev", "Ft swarf", "Ft Oxley",
                                     "dev", "h_c swarf", "h_c Oxley", "dev"], table), ""]

    # ---- Oxley stand-in grid for C45
    grid = {}
    if oxley is not None:
        speeds = [float(x) for x in a.grid_speeds.split(",")]
        hs = [float(x) for x in a.grid_h.split(",")]
        for h in hs:
            for v in speeds:
                grid[(v, h)] = oxley(v, h, a.grid_rake)
        md += [f"## Oxley stand-in for C45 (AISI 1045, Jaspers' set; rake {a.grid_rake:g} deg, sharp tool)", "",
               "What the physics cross-check predicts where measured C45 data are missing: not a measurement.", ""]
        table = []
        for h in hs:
            for v in speeds:
                o = grid[(v, h)]
                table.append([fmt(v, 0), fmt(h, 2)] + ([fmt(o["fc"]), fmt(o["ft"]), fmt(o["hc"], 3),
                                                        fmt(o["phi_deg"])] if o["ok"] else ["no solution"] * 4))
        md += [md_table(["V", "h", "Fc/b", "Ft/b", "h_c", "shear angle (deg)"], table), ""]
        for h in hs:
            ok = [v for v in speeds if grid[(v, h)]["ok"]]
            if len(ok) > 1:
                f0, f1 = grid[(ok[0], h)]["fc"], grid[(ok[-1], h)]["fc"]
                md.append(f"- h = {h:g} mm: Fc/b {f0:.1f} N/mm at {ok[0]:g} m/min to {f1:.1f} at {ok[-1]:g} m/min "
                          f"({100 * (f1 / f0 - 1):+.1f} %)")
        for v in speeds:
            ok = [h for h in hs if grid[(v, h)]["ok"]]
            if len(ok) > 1:
                slope, c = loglog_fit(np.array(ok), np.array([grid[(v, h)]["fc"] for h in ok]))
                md.append(f"- {v:g} m/min: Kienzle 1 - mc = {slope:.3f} (h {ok[0]:g} to {ok[-1]:g} mm), "
                          f"kc1.1 = {c:.0f} N/mm^2")
        md.append("")

    # ---- summaries of the measured sets
    groups = group_means(rows)
    fits = []
    for fname in sorted({r["file"] for r in rows}):
        gs = [g for g in groups if g["file"] == fname]
        fk = force_key(gs)
        tk = "ft" if fk == "fc" else "ft_n"
        unit = "N/mm" if fk == "fc" else "N (tested width; per width unknown)"
        md += [f"## {fname}: the measurements", "",
               f"{sum(g['n'] for g in gs)} tests (status error left out) at {len(gs)} conditions. "
               f"Means over repeated tests (sample standard deviation of the repeats in brackets). Fc, Ft in {unit}; "
               "Ft is the force normal to the cut surface (the feed force in orthogonal turning).", ""]
        table = []
        for g in gs:
            fc, ft, hc, rn = g[fk], g[tk], g["hc"], g["rn"]
            table.append([g["campaign"], fmt(g["speed_m_per_min"]), fmt(g["uncut_thickness_mm"], 3),
                          fmt(g["rake_deg"], 0), g["n"], fmt(fc[0]) + ("" if fc[1] is None else f" ({fc[1]:.1f})"),
                          fmt(ft[0]) + ("" if ft[1] is None else f" ({ft[1]:.1f})"),
                          fmt(hc[0], 3) + (f" (n={hc[2]})" if hc[2] else ""),
                          "-" if hc[0] is None else f"{g['uncut_thickness_mm'] / hc[0]:.2f}", fmt(rn[0])])
        md += [md_table(["series", "V", "h", "rake", "n", "Fc", "Ft", "h_c", "h/h_c", "r_n (um)"], table), ""]
        # repeatability
        cvs = [g[fk][1] / g[fk][0] for g in gs if g[fk][1] is not None and g[fk][0]]
        cvt = [g[tk][1] / g[tk][0] for g in gs if g[tk][1] is not None and g[tk][0]]
        if cvs:
            md.append(f"- Repeatability (standard deviation over mean of the repeated tests at one condition): Fc median "
                      f"{100 * np.median(cvs):.1f} % (max {100 * max(cvs):.1f} %), Ft median {100 * np.median(cvt):.1f} % "
                      f"(max {100 * max(cvt):.1f} %), over {len(cvs)} conditions.")
        # speed trend per (campaign, h)
        for camp, h, hs_ in slices(gs, "uncut_thickness_mm", "speed_m_per_min"):
            lo, hi_ = hs_[0], hs_[-1]
            md.append(f"- Speed trend{' ' + camp if camp else ''}, h = {h:g} mm: Fc {lo[fk][0]:.1f} at "
                      f"{lo['speed_m_per_min']:g} m/min to {hi_[fk][0]:.1f} at {hi_['speed_m_per_min']:g} m/min "
                      f"({100 * (hi_[fk][0] / lo[fk][0] - 1):+.1f} %, {len(hs_)} speeds)")
        # Kienzle at fixed speed
        for camp, v, at in slices(gs, "speed_m_per_min", "uncut_thickness_mm"):
            h_all = np.array([g["uncut_thickness_mm"] for g in at])
            f_all = np.array([g[fk][0] for g in at])
            previous = None
            for lo_h, label in ((0.0, "all h"), (0.04, "h >= 0.04 mm")):
                sel = h_all >= lo_h - 1e-12
                # at least 3 depths over a factor 3 in h, and not the same depths again
                if sel.sum() < 3 or h_all[sel].max() < 3 * h_all[sel].min() or sel.tolist() == previous:
                    continue
                previous = sel.tolist()
                slope, c = loglog_fit(h_all[sel], f_all[sel])
                fr = np.array([g[tk][0] for g in at])[sel]
                slope_t, _ = loglog_fit(h_all[sel], fr)
                md.append(f"- Kienzle{' ' + camp if camp else ''}, {v:g} m/min, {label} "
                          f"({h_all[sel].min():g} to {h_all[sel].max():g} mm, {int(sel.sum())} depths): "
                          f"1 - mc = {slope:.3f} for Fc, {slope_t:.3f} for Ft")
                if h_all[sel].min() >= 0.04 - 1e-12 and sel.sum() >= 5:
                    fits.append({"label": f"{v:g} m/min{' ' + camp if camp else ''}", "slope": slope, "c": c,
                                 "h_fit": h_all[sel], "h_all": h_all, "f_all": f_all})
        md.append("")

    # ---- plots
    out = a.out
    empty = "no measured AISI 1045 / C45 point\nand no swarf study matched:\nnothing to plot (see README.md)"
    scatter_plot(os.path.join(out, "measured_vs_oxley_fc.png"), "fc", "Fc/b (N/mm)", pairs["fc"], 0.15, empty)
    scatter_plot(os.path.join(out, "measured_vs_oxley_ft.png"), "ft", "Ft/b (N/mm)", pairs["ft"], 0.30, empty)
    scatter_plot(os.path.join(out, "measured_vs_oxley_hc.png"), "hc", "h_c (mm)", pairs["hc"], 0.15, empty)
    speed_plot(os.path.join(out, "measured_fc_vs_speed.png"), groups, grid, steel, study if a.study else [],
               a.grid_rake)
    if fits:
        kienzle_plot(os.path.join(out, "measured_kienzle.png"), fits)
    md += ["Plots: measured_vs_oxley_fc.png, measured_vs_oxley_ft.png, measured_vs_oxley_hc.png, "
           "measured_fc_vs_speed.png" + (", measured_kienzle.png" if fits else "") + "."]
    if oxley is not None:
        md.append(f"Oxley's model was run {oxley.calls} times ({a.swarf} oxley).")
    text = "\n".join(md) + "\n"
    with open(os.path.join(out, "comparison.md"), "w") as f:
        f.write(text)
    sys.stdout.write(text)


if __name__ == "__main__":
    main()
