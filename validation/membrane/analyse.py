#!/usr/bin/python3
"""Measures the wave speeds of the membrane runs (membrane_waves.cpp) and draws the plots.

For each probe at distance r from the source, the time of the pulse's peak (the largest
displacement, refined by a parabola through the three samples around it). The speed is
1 / slope of a straight line t_peak = t0 + r / c fitted over r in [2, 5] wave lengths; a second
fit t0 + r / c + b / r shows how much the cylindrical wave's near field (its shape still
changing, O(wave length / r)) moves the result. Writes results.md and waves.png, peaks.png
into the directory given as the first argument (default: this script's directory).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

WAVE = 10e-3  # m, the pulse's wave length c tau (membrane_waves.cpp)
FIT = (2.0 * WAVE, 5.0 * WAVE)


def load(path):
    with open(path) as f:
        header = f.readline().strip().split(",")
    r = np.array([float(h[2:]) for h in header[1:]])
    data = np.loadtxt(path, delimiter=",", skiprows=1)
    return data[:, 0], r, data[:, 1:]


def peak_times(t, u):
    out = []
    for j in range(u.shape[1]):
        k = int(np.argmax(u[:, j]))
        k = min(max(k, 1), len(t) - 2)
        y0, y1, y2 = u[k - 1, j], u[k, j], u[k + 1, j]
        den = y0 - 2 * y1 + y2
        s = 0.5 * (y0 - y2) / den if den != 0 else 0.0
        out.append(t[k] + s * (t[k + 1] - t[k]))
    return np.array(out)


def main():
    here = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, "cases.csv")) as f:
        cases = list(csv.DictReader(f))
    results = {}
    for c in cases:
        t, r, u = load(os.path.join(here, f"waves_{c['run']}.csv"))
        tp = peak_times(t, u)
        sel = (r >= FIT[0] - 1e-12) & (r <= FIT[1] + 1e-12)
        slope, t0 = np.polyfit(r[sel], tp[sel], 1)
        a = np.vstack([np.ones(sel.sum()), r[sel], 1.0 / r[sel]]).T
        coef, *_ = np.linalg.lstsq(a, tp[sel], rcond=None)
        closed = float(c["closed_form_speed_m_per_s"])
        results[c["run"]] = dict(case=c, t=t, r=r, u=u, tp=tp, sel=sel, c=1.0 / slope, t0=t0, c3=1.0 / coef[1],
                                 closed=closed, resid=np.max(np.abs(tp[sel] - (t0 + slope * r[sel]))))

    lines = ["# Membrane wave speeds (written by analyse.py)", "",
             "| run | particles | spacing d (mm) | wave length / d | closed form c (m/s) | measured (m/s) | "
             "error | with b/r term (m/s) | error | largest fit residual (us) |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for name, v in results.items():
        d = float(v["case"]["spacing_m"])
        e1 = 100 * (v["c"] / v["closed"] - 1)
        e3 = 100 * (v["c3"] / v["closed"] - 1)
        lines.append(f"| {name} | {v['case']['particles']} | {d * 1e3:.3g} | {WAVE / d:.0f} | {v['closed']:.5g} | "
                     f"{v['c']:.5g} | {e1:+.2f} % | {v['c3']:.5g} | {e3:+.2f} % | {v['resid'] * 1e6:.3g} |")
    lines += ["", f"Fit range: r = {FIT[0] * 1e3:.0f} to {FIT[1] * 1e3:.0f} mm from the source.", ""]
    with open(os.path.join(here, "results.md"), "w") as f:
        f.write("\n".join(lines))
    print("\n".join(lines))

    fig, grid = plt.subplots(2, 2, figsize=(12, 8), sharex="col")
    for ax, low, kind in zip(grid[0], grid[1], ["transverse", "longitudinal"]):
        for res, style in [("coarse", "o"), ("fine", ".")]:
            v = results.get(f"{kind}_{res}")
            if v is None:
                continue
            d = float(v["case"]["spacing_m"])
            ax.plot(v["r"] * 1e3, v["tp"] * 1e3, style, ms=3, label=f"{res} (d = {d * 1e3:.3g} mm): "
                    f"c = {v['c']:.4g} m/s ({100 * (v['c'] / v['closed'] - 1):+.2f} %)")
            ax.plot(v["r"] * 1e3, (v["t0"] + v["r"] / v["closed"]) * 1e3, "-", lw=0.8,
                    label=f"slope of the closed form c = {v['closed']:.4g} m/s" if res == "coarse" else None)
            # Below: the peak times less the closed form's line through their mean in the fit range.
            dev = v["tp"] - v["r"] / v["closed"]
            dev -= np.mean(dev[v["sel"]])
            low.plot(v["r"] * 1e3, dev * 1e6, style, ms=3, label=f"{res}")
        low.axvspan(FIT[0] * 1e3, FIT[1] * 1e3, color="0.92", zorder=0)
        low.axhline(0, color="k", lw=0.6)
        for frac in (0.02, -0.02):
            rr = np.linspace(FIT[0], FIT[1], 2)
            c = results[f"{kind}_coarse"]["closed"] if f"{kind}_coarse" in results else 1.0
            mid = 0.5 * (FIT[0] + FIT[1])
            low.plot(rr * 1e3, (rr - mid) * (1 / (c * (1 + frac)) - 1 / c) * 1e6, "r:", lw=0.8,
                     label="slope of c +- 2 %" if frac > 0 else None)
        low.set_xlabel("distance from the source r (mm)")
        low.set_ylabel("peak time - r / c_closed form (us)")
        low.legend(fontsize=8)
        low.grid(alpha=0.3)
        ax.axvspan(FIT[0] * 1e3, FIT[1] * 1e3, color="0.92", zorder=0, label="fit range")
        ax.set_ylabel("time of the peak (ms)")
        ax.set_title(f"{kind} wave: " + ("c_T = sqrt(T / rho_A)" if kind == "transverse" else
                                         "c_L, lattice closed form"))
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(here, "peaks.png"), dpi=120)

    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
    for ax, kind in zip(axes, ["transverse", "longitudinal"]):
        v = results.get(f"{kind}_fine") or results.get(f"{kind}_coarse")
        if v is None:
            continue
        amp = np.max(np.abs(v["u"]))
        for j in range(0, len(v["r"]), max(1, len(v["r"]) // 12)):
            ax.plot(v["t"] * 1e3, v["r"][j] * 1e3 + 4.0 * v["u"][:, j] / amp * np.sqrt(v["r"][j] / WAVE), lw=0.8,
                    color="C0")
        ax.plot(v["tp"] * 1e3, v["r"] * 1e3, "k.", ms=1.5, label="peak of each probe")
        tt = np.linspace(0, v["t"][-1], 50)
        ax.plot(tt * 1e3, (tt - v["t0"]) * v["closed"] * 1e3, "r--", lw=1, label="r = c (t - t0), closed-form c")
        ax.set_ylim(0, v["r"][-1] * 1e3 + 5)
        ax.set_xlabel("time (ms)")
        ax.set_ylabel("r (mm); trace: displacement x sqrt(r), scaled")
        ax.set_title(f"{kind} wave along +x, {v['case']['run'].split('_')[1]} sheet")
        ax.legend(fontsize=8, loc="lower right")
    fig.tight_layout()
    fig.savefig(os.path.join(here, "waves.png"), dpi=120)


if __name__ == "__main__":
    main()
