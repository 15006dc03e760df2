#!/usr/bin/python3
"""Checks a water-wheel run (validation/water_wheel/README.md): steady angular velocity, the
torque balance (particles' torque on the wheel = damping torque c omega), the power balance,
and the momentum-balance estimate of the steady speed. Writes omega.png.

Usage: /usr/bin/python3 analyse.py RUN_DIR
"""
import csv
import json
import math
import os
import sys

import numpy as np

import make_case as mc  # the case's parameters

run = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(run, "series.csv"))))
col = lambda name: np.array([float(r[name]) for r in rows])
t, w, tq = col("time"), col("body_wheel_omega_y"), col("body_wheel_torque_y")

# Mass flow and speed of the stream.
mp = 2500.0 * 4.0 / 3.0 * math.pi * mc.RP ** 3
mdot = mc.COLS * mc.ROWS * mp * mc.U / mc.S
duration = mc.LENGTH / mc.U
c = mc.C

# The wheel's moment of inertia about y from wheel.obj (tetrahedra from the origin: the
# integral of x^2 over one is V/10 (sum of the squares + the pairwise products of its corners' x)).
def axis_inertia(path, density=1000.0):
    v, total = [], 0.0
    for line in open(path):
        f = line.split()
        if f and f[0] == "v":
            v.append([float(c) for c in f[1:4]])
        elif f and f[0] == "f":
            a, b, cc = (np.array(v[int(k.split("/")[0]) - 1]) for k in f[1:4])
            vol = np.dot(a, np.cross(b, cc)) / 6.0
            for i in (0, 2):
                total += vol / 10.0 * (a[i]**2 + b[i]**2 + cc[i]**2 + a[i]*b[i] + a[i]*cc[i] + b[i]*cc[i])
    return density * total


I_axis = axis_inertia(os.path.join(run, "..", "wheel.obj"))

# Steady window: from 40 % of the stream's duration to 90 % (the train's tail leaves after that).
win = (t > 0.4 * duration) & (t < 0.9 * duration)
w_mean, w_std = w[win].mean(), w[win].std()
tq_mean, tq_std = tq[win].mean(), tq[win].std()
damp = c * w_mean
# Angular momentum over the window: mean particle torque = c <omega> + I (w_end - w_start) / T.
spin_up = I_axis * (w[win][-1] - w[win][0]) / (t[win][-1] - t[win][0])
# Power: the damper takes c w^2; the stream brings 1/2 mdot U^2.
p_damp = c * (w[win] ** 2).mean()
p_in = 0.5 * mdot * mc.U ** 2
# Momentum balance at the impact radius Rm (the stream's centre): a particle that leaves with
# the paddle's speed (no rebound, k = 1) hands over mdot (U - w Rm); with a full rebound (k = 2)
# twice that. Torque k mdot Rm (U - w Rm) = c w gives w = k mdot Rm U / (c + k mdot Rm^2).
Rm = mc.X
est = {k: k * mdot * Rm * mc.U / (c + k * mdot * Rm ** 2) for k in (1.0, 1.5, 2.0)}
summary = json.load(open(os.path.join(run, "summary.json")))
res = summary.get("results", {})

print(f"stream: {mc.COLS * mc.ROWS * int(mc.LENGTH / mc.S)} particles, mass flow {mdot:.4g} kg/s, "
      f"speed {mc.U} m/s, {1e3 * duration:.0f} ms; damping c = {c:g} N m s")
print(f"steady window {t[win][0] * 1e3:.1f}-{t[win][-1] * 1e3:.1f} ms ({win.sum()} rows)")
print(f"omega: mean {w_mean:.4g} rad/s, std {w_std:.3g} rad/s ({100 * w_std / w_mean:.1f} %)")
sem = tq_std / math.sqrt(win.sum())
print(f"wheel: I about the axis {I_axis:.4g} kg m^2, spin-up time I / c = {1e3 * I_axis / c:.1f} ms")
print(f"particles' torque on the wheel: mean {tq_mean:.4g} N m (row std {tq_std:.3g}, standard error {sem:.2g}); "
      f"damping torque c <omega> = {damp:.4g} N m, plus I d(omega)/dt over the window {spin_up:.3g} N m: "
      f"{damp + spin_up:.4g} N m; difference {(tq_mean - damp - spin_up) / sem:.2f} standard errors")
print(f"power: stream brings 1/2 mdot U^2 = {p_in:.4g} W; damper takes c <omega^2> = {p_damp:.4g} W "
      f"({100 * p_damp / p_in:.1f} % efficiency)")
print("momentum-balance estimate: " + ", ".join(f"k = {k:g}: {v:.4g} rad/s" for k, v in est.items()))
ke = col("kinetic_energy")
print(f"energy: stream's kinetic energy at the start {ke[0]:.4g} J; at the end {ke[-1]:.4g} J (wheel and particles); "
      f"damper's work {res.get('external_work_J', float('nan')):.4g} J; taken up by the contacts "
      f"{res.get('contact_work_J', float('nan')):.4g} J")
print(f"summary: energy_error {res.get('energy_error_J', 'n/a')}, contact_work {res.get('contact_work_J', 'n/a')}, "
      f"external_work {res.get('external_work_J', 'n/a')}")

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.plot(1e3 * t, w, label="wheel")
    for k, v in est.items():
        ax.axhline(v, ls=":", lw=0.8, color="gray")
        ax.text(1e3 * t[-1], v, f" k={k:g}", va="center", fontsize=7)
    ax.axvspan(1e3 * t[win][0], 1e3 * t[win][-1], color="0.9")
    ax.set_xlabel("time (ms)")
    ax.set_ylabel("angular velocity (rad/s)")
    ax.legend(loc="lower right")
    fig.tight_layout()
    fig.savefig(os.path.join(run, "omega.png"), dpi=120)
    print("wrote", os.path.join(run, "omega.png"))
except ImportError:
    print("(no matplotlib: no plot)")
