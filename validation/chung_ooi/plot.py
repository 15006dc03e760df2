#!/usr/bin/python3
"""Plots test 4 of the Chung & Ooi suite (oblique.csv written by swarf_chung_ooi) as oblique.png."""
import csv, os
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = os.path.dirname(os.path.abspath(__file__))
rows = list(csv.DictReader(open(os.path.join(here, "oblique.csv"))))
a = [float(r["angle_deg"]) for r in rows]
fig, axs = plt.subplots(1, 2, figsize=(11, 4.2), dpi=110)
axs[0].plot(a, [float(r["vt_ratio"]) for r in rows], "o-", label="swarf")
axs[0].plot(a, [max(float(r["vt_ratio_sliding"]), -0.2) for r in rows], "k--", label="sliding theory: 1 - mu (1+e) vn/vt")
axs[0].axhline(5 / 7, color="grey", ls=":", label="rolling limit 5/7 (rigid)")
axs[0].set_ylim(-0.2, 1.05)
axs[0].set_xlabel("incidence angle from the normal [deg]"); axs[0].set_ylabel("tangential velocity ratio vt'/vt [1]")
axs[1].plot(a, [float(r["spin"]) for r in rows], "o-", label="swarf")
axs[1].plot(a, [float(r["spin_sliding"]) for r in rows], "k--", label="sliding theory: 5/2 mu (1+e)")
axs[1].set_xlabel("incidence angle from the normal [deg]"); axs[1].set_ylabel("rebound spin w' R / vn [1]")
for x in axs:
    x.grid(alpha=0.3); x.legend(fontsize=8)
fig.suptitle("Chung & Ooi test 4: aluminium oxide sphere on a plane, 3.9 m/s, mu = 0.092, e = 0.98")
fig.tight_layout()
fig.savefig(os.path.join(here, "oblique.png"))
