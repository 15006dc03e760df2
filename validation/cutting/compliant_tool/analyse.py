#!/usr/bin/python3
"""The compliant tool's ensemble (validation/cutting/compliant_tool/README.md): per run the steady
forces, the tool's deflection against the static F/k; over the ensemble the mean amplitude
spectrum of the deflection and the tool's frequency response estimated from the cut itself,
H1 = <conj(F) D> / <|F|^2> (Welch: Hann-windowed half-overlapping segments of every run's
engaged rows, averaged over segments and runs), against the mount's closed form
1 / (k - m w^2 + i c w). Writes compliant_tool.png.

Usage: /usr/bin/python3 analyse.py RIGID_RUN COMPLIANT_RUN [COMPLIANT_RUN ...]
"""
import csv
import json
import math
import os
import sys

import numpy as np

T95 = {1: 12.71, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571}


def series(run):
    rows = list(csv.DictReader(open(os.path.join(run, "series.csv"))))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def ensemble(values):
    v = np.array(values)
    if len(v) < 2:
        return v.mean(), float("nan")
    return v.mean(), T95[len(v) - 1] * v.std(ddof=1) / math.sqrt(len(v))


rigid, runs = sys.argv[1], sys.argv[2:]
summ = {r: json.load(open(os.path.join(r, "summary.json"))) for r in [rigid] + runs}
print("| run | Fc/w kN/m | Ft/w kN/m | h_c mm | deflection x um | -Fc/k um | deflection z um | Ft/k um |")
print("|---|---|---|---|---|---|---|---|")
for r in [rigid] + runs:
    c, ch, t = summ[r]["cutting"], summ[r]["chip"], summ[r].get("tool")
    row = [os.path.basename(os.path.normpath(r)),
           "%.1f +- %.1f" % (c["cutting_force_per_width_mean_N_per_m"] / 1e3, c["cutting_force_per_width_ci95_N_per_m"] / 1e3),
           "%.1f +- %.1f" % (c["thrust_force_per_width_mean_N_per_m"] / 1e3, c["thrust_force_per_width_ci95_N_per_m"] / 1e3),
           "%.3f" % (ch["thickness_m"] * 1e3)]
    if t:
        row += ["%.2f +- %.2f" % (1e6 * t["deflection_x_mean_m"], 1e6 * t["deflection_x_ci95_m"]),
                "%.2f +- %.2f" % (1e6 * t["static_deflection_x_m"], 1e6 * t["static_deflection_x_ci95_m"]),
                "%.2f +- %.2f" % (1e6 * t["deflection_z_mean_m"], 1e6 * t["deflection_z_ci95_m"]),
                "%.2f +- %.2f" % (1e6 * t["static_deflection_z_m"], 1e6 * t["static_deflection_z_ci95_m"])]
    else:
        row += ["(rigid)"] * 4
    print("| " + " | ".join(row) + " |")
fc, ft = ensemble([summ[r]["cutting"]["cutting_force_per_width_mean_N_per_m"] for r in runs]), \
    ensemble([summ[r]["cutting"]["thrust_force_per_width_mean_N_per_m"] for r in runs])
hc = ensemble([summ[r]["chip"]["thickness_m"] for r in runs])
print("ensemble of %d compliant runs (95 %%, Student t): Fc/w %.1f +- %.1f kN/m, Ft/w %.1f +- %.1f kN/m, h_c %.3f +- %.3f mm"
      % (len(runs), fc[0] / 1e3, fc[1] / 1e3, ft[0] / 1e3, ft[1] / 1e3, hc[0] * 1e3, hc[1] * 1e3))

tool = summ[runs[0]]["tool"]
k, m = tool["stiffness_x_N_per_m_per_m"], tool["mass_kg_per_m"]
zeta = tool["damping_ratio_x"]
c = 2 * zeta * math.sqrt(k * m)
fn = tool["natural_frequency_x_Hz"]

# Welch over the engaged rows of every run: segments of L rows, half overlapping.
L = 160
f = None
Sfd = {"x": 0, "z": 0}
Sff = {"x": 0, "z": 0}
Sdd = {"x": 0, "z": 0}
segments = 0
for r in runs:
    s = series(r)
    t = s["time"]
    on = np.nonzero((s["cutting_force_per_width"] != 0) | (s["thrust_force_per_width"] != 0))[0][0]
    dt = np.diff(t[on:]).mean()
    w = np.hanning(L)
    f = np.fft.rfftfreq(L, dt)
    for a in range(on, len(t) - L + 1, L // 2):
        segments += 1
        for ax, d, F in (("x", s["tool_deflection_x"], -s["cutting_force_per_width"]),
                         ("z", s["tool_deflection_z"], s["thrust_force_per_width"])):
            D = np.fft.rfft(w * (d[a:a + L] - d[a:a + L].mean()))
            FF = np.fft.rfft(w * (F[a:a + L] - F[a:a + L].mean()))
            Sfd[ax] = Sfd[ax] + np.conj(FF) * D
            Sff[ax] = Sff[ax] + np.abs(FF) ** 2
            Sdd[ax] = Sdd[ax] + np.abs(D) ** 2
omega = 2 * math.pi * f
H0 = 1.0 / (k - m * omega ** 2 + 1j * c * omega)
print("Welch: %d segments of %d rows (%.0f us, resolution %.1f kHz) over %d runs" %
      (segments, L, L * dt * 1e6, 1e-3 / (L * dt), len(runs)))
band = (f > 0.5 * fn) & (f < 2 * fn)
for ax in ("x", "z"):
    H = Sfd[ax] / Sff[ax]
    coh = np.abs(Sfd[ax]) ** 2 / (Sff[ax] * Sdd[ax])
    i = np.argmax(np.where(band, np.abs(H), 0))
    j = np.argmax(np.where(band, Sdd[ax], 0))
    print("%s: |H1| peaks at %.1f kHz (|H1| k = %.2f; closed form %.2f at %.1f kHz); deflection spectrum peaks at %.1f kHz;"
          " |H1| / |H0| over 0.5-2 f_n: %.2f to %.2f; coherence there %.2f to %.2f"
          % (ax, f[i] / 1e3, abs(H[i]) * k, 1 / (2 * zeta), fn * math.sqrt(1 - 2 * zeta ** 2) / 1e3, f[j] / 1e3,
             (np.abs(H) / np.abs(H0))[band].min(), (np.abs(H) / np.abs(H0))[band].max(), coh[band].min(), coh[band].max()))

off = (f > 0) & (f <= 4 * fn) & ((f < 0.8 * fn) | (f > 1.25 * fn))
for ax in ("x", "z"):
    ratio = np.abs(Sfd[ax] / Sff[ax]) / np.abs(H0)
    coh = np.abs(Sfd[ax]) ** 2 / (Sff[ax] * Sdd[ax])
    print("%s, 0 to 4 f_n outside 0.8-1.25 f_n: |H1| / |H0| %.2f to %.2f, coherence %.2f to %.2f"
          % (ax, ratio[off].min(), ratio[off].max(), coh[off].min(), coh[off].max()))

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.2), dpi=120)
for ax, col in (("x", "C0"), ("z", "C3")):
    amp = np.sqrt(Sdd[ax] / segments) * 2 / w.sum()
    a1.semilogy(f / 1e3, amp * 1e6, color=col, label="deflection %s" % ax)
    a2.semilogy(f / 1e3, np.abs(Sfd[ax] / Sff[ax]) * k, color=col, label="H1 %s (from the cut)" % ax)
a2.semilogy(f / 1e3, np.abs(H0) * k, "k--", label="mount's closed form k |1/(k - m w^2 + i c w)|")
for a in (a1, a2):
    a.axvline(fn / 1e3, color="0.5", ls=":", lw=1)
    a.set_xlim(0, 400)
    a.set_xlabel("frequency [kHz]")
    a.grid(alpha=0.3, which="both")
    a.legend(fontsize=8)
a1.set_ylabel("amplitude, rms over segments [um]")
a1.set_title("Tool deflection spectrum (%d runs, Welch)" % len(runs), fontsize=10)
a2.set_ylabel("k |H| [1]")
a2.set_title("Frequency response of the tool measured in the cut", fontsize=10)
fig.tight_layout()
out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "compliant_tool.png")
fig.savefig(out)
print("wrote", out)
