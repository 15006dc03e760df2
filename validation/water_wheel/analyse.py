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

# Mass flow and speed of the stream: the inflow's measured rate (created per second over the
# steady window) times a particle's mass; its speed where it meets the paddles' tips at x = X
# (z = sqrt(R_out^2 - X^2)), after falling from the inflow box's middle.
mp = 2500.0 * 4.0 / 3.0 * math.pi * mc.RP ** 3
created = col("inflow_created")
g = 9.81
z_in, z_hit = mc.Z0 + 1e-3, math.sqrt(mc.PADDLE_OUT ** 2 - mc.X ** 2)
U_hit = math.sqrt(mc.U ** 2 + 2 * g * (z_in - z_hit))
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

# Steady window: the second half of the run (the wheel spins up in a few I / c = 10 ms and the
# first particles reach the outflow after about 15 ms).
win = t >= 0.5 * t[-1]
mdot = mp * (created[win][-1] - created[win][0]) / (t[win][-1] - t[win][0])


def batch_ci95(x, batches=10):
    """Half-width of the 95 % interval of the mean of correlated rows by 10 batch means."""
    m = len(x) // batches
    b = np.array([x[len(x) - (batches - k) * m:len(x) - (batches - k - 1) * m].mean() for k in range(batches)])
    return 2.262 * b.std(ddof=1) / math.sqrt(batches)


w_mean, w_std = w[win].mean(), w[win].std()
tq_mean, tq_std = tq[win].mean(), tq[win].std()
damp = c * w_mean
# Angular momentum over the window: mean particle torque = c <omega> + I (w_end - w_start) / T.
spin_up = I_axis * (w[win][-1] - w[win][0]) / (t[win][-1] - t[win][0])
# Power: the damper takes c w^2; the stream brings 1/2 mdot U^2.
p_damp = c * (w[win] ** 2).mean()
p_in = 0.5 * mdot * U_hit ** 2
# Momentum balance at the impact radius Rm (the stream's centre): a particle that leaves with
# the paddle's speed (no rebound, k = 1) hands over mdot (U - w Rm); with a full rebound (k = 2)
# twice that. Torque k mdot Rm (U - w Rm) = c w gives w = k mdot Rm U / (c + k mdot Rm^2).
Rm = mc.X
est = {k: k * mdot * Rm * U_hit / (c + k * mdot * Rm ** 2) for k in (1.0, 1.5, 2.0)}
summary = json.load(open(os.path.join(run, "summary.json")))
res = summary.get("results", {})

print(f"stream: inflow rate {mdot / mp:.5g} /s (set {mc.RATE:g} /s), mass flow {mdot:.4g} kg/s, speed {mc.U} m/s "
      f"at the inflow, {U_hit:.4g} m/s at the paddles' tips; damping c = {c:g} N m s")
print(f"particles: created {created[-1]:.0f}, missed {col('inflow_missed')[-1]:.0f}, removed "
      f"{col('outflow_removed')[-1]:.0f}, in the run at the end {col('particles')[-1]:.0f}")
print(f"steady window {t[win][0] * 1e3:.1f}-{t[win][-1] * 1e3:.1f} ms ({win.sum()} rows)")
w_ci = batch_ci95(w[win])
print(f"omega: mean {w_mean:.4g} +- {w_ci:.2g} rad/s (95 %, batch means), row std {w_std:.3g} rad/s "
      f"({100 * w_std / w_mean:.1f} %)")
print(f"wheel: I about the axis {I_axis:.4g} kg m^2, spin-up time I / c = {1e3 * I_axis / c:.1f} ms")
tq_ci = batch_ci95(tq[win])
print(f"particles' torque on the wheel: mean {tq_mean:.4g} +- {tq_ci:.2g} N m (95 %, batch means; row std "
      f"{tq_std:.3g}); damping torque c <omega> = {damp:.4g} +- {c * w_ci:.2g} N m, plus I d(omega)/dt over the "
      f"window {spin_up:.3g} N m: {damp + spin_up:.4g} N m; difference {tq_mean - damp - spin_up:.3g} N m "
      f"({100 * (tq_mean - damp - spin_up) / (damp + spin_up):.2f} %)")
print(f"power: the stream brings 1/2 mdot U^2 = {p_in:.4g} W at the paddles; the damper takes c <omega^2> = "
      f"{p_damp:.4g} W ({100 * p_damp / p_in:.1f} %)")
print("momentum-balance estimate: " + ", ".join(f"k = {k:g}: {v:.4g} rad/s" for k, v in est.items()))
print(f"energy books of the whole run (summary.json): external work (the damper's) "
      f"{res.get('external_work_J', float('nan')):.4g} J, contact work {res.get('contact_work_J', float('nan')):.4g} J, "
      f"carried by the flows (out - in) {summary.get('flows', {}).get('flow_energy_J', float('nan')):.4g} J, "
      f"kinetic {res.get('kinetic_energy_J', float('nan')):.4g} J, potential {res.get('potential_energy_J', float('nan')):.4g} J; "
      f"balance error {res.get('energy_error_J', float('nan')):.3g} J")

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
