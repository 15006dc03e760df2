#!/usr/bin/env python3
"""The speed trend with and without the tool's friction table (validation/cutting/README.md,
"A friction that falls with the sliding speed").

    compare.py DATA [DEST]

DATA holds one summary.json per run, named <arm>_<v>.json or <arm>_<v>_s<seed>.json with arm
'table' (the stand-in mu(v_s) table of validation/studies/speed_friction.toml) or 'const'
(mu = 0.5), v the speed in m/min and the seed of the jitter (1 when not named). The trends and the
figure use the mean over the seeds at each speed.
Writes DEST/speed_friction.csv (units in its header) and DEST/speed_friction.png, and prints the
README's table. Oxley's figures are `swarf oxley` at h = 0.2 mm, rake 10 deg (Jaspers' AISI 1045,
temperature-dependent conductivity and heat capacity), the theory the table was taken from.
"""
import glob
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# `swarf oxley --speed V --uncut-thickness 0.2e-3 --rake-angle 10` (m/min: Fc/w kN/m, Ft/Fc, h/h_c),
# printed by swarf at 100, 200, 300, 400 and 600 m/min (2026-12-07).
OXLEY = {100: (381.9, 0.4394, 0.4527), 200: (337.5, 0.3282, 0.5295), 300: (316.3, 0.2683, 0.5738),
         400: (302.9, 0.2280, 0.6046), 600: (287.0, 0.1743, 0.6466)}


def load(data):
    rows = []
    for f in sorted(glob.glob(os.path.join(data, "*.json"))):
        parts = os.path.basename(f)[:-5].split("_")
        arm, v = parts[0], parts[1]
        seed = int(parts[2][1:]) if len(parts) > 2 else 1
        j = json.load(open(f))
        c, ch = j["cutting"], j["chip"]
        rows.append(dict(arm=arm, v=int(v), seed=seed,
                         fc=c["cutting_force_per_width_mean_N_per_m"] / 1e3,
                         fc_ci=c["cutting_force_per_width_ci95_N_per_m"] / 1e3,
                         ft=c["thrust_force_per_width_mean_N_per_m"] / 1e3,
                         ft_ci=c["thrust_force_per_width_ci95_N_per_m"] / 1e3,
                         hc=ch["thickness_m"] * 1e3 if ch.get("thickness_m") else float("nan"),
                         beta=ch["friction_angle_deg"], phi=ch["shear_angle_deg"],
                         lc=ch["contact_length_m"] * 1e3,
                         t_rake=ch["rake_face_temperature_K"], t_chip=ch["chip_temperature_K"]))
    return sorted(rows, key=lambda r: (r["arm"], r["v"], r["seed"]))


def means(rows, arm):
    """Per speed, the mean over the seeds of each figure (the intervals: the mean of the runs')."""
    out = {}
    for v in sorted({r["v"] for r in rows if r["arm"] == arm}):
        rs = [r for r in rows if r["arm"] == arm and r["v"] == v]
        out[v] = {k: sum(r[k] for r in rs) / len(rs) for k in ("fc", "fc_ci", "ft", "ft_ci", "hc")}
        out[v]["n"] = len(rs)
    return out


def main():
    data = sys.argv[1]
    dest = sys.argv[2] if len(sys.argv) > 2 else "."
    rows = load(data)
    with open(os.path.join(dest, "speed_friction.csv"), "w") as out:
        out.write("arm,v_m_per_min,seed,Fc_per_w_kN_per_m,Fc_ci95_kN_per_m,Ft_per_w_kN_per_m,Ft_ci95_kN_per_m,"
                  "h_c_mm,friction_angle_deg,shear_angle_deg,contact_length_mm,rake_face_T_K,chip_T_K\n")
        for r in rows:
            out.write("{arm},{v},{seed},{fc:.2f},{fc_ci:.2f},{ft:.2f},{ft_ci:.2f},{hc:.4f},{beta:.2f},{phi:.2f},"
                      "{lc:.4f},{t_rake:.1f},{t_chip:.1f}\n".format(**r))
    print("| mu of the tool | v (m/min) | seed | Fc/w (kN/m) | Ft/w (kN/m) | Ft/Fc | h_c (mm) | friction angle (deg) "
          "| contact length (mm) | rake face T (K) | Oxley: Fc/w, Ft/Fc, h_c |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        o = OXLEY.get(r["v"])
        ox = "{:.1f}, {:.3f}, {:.3f}".format(o[0], o[1], 0.2 / o[2]) if o else "-"
        print("| {} | {} | {} | {:.1f} +- {:.1f} | {:.1f} +- {:.1f} | {:.3f} | {:.3f} | {:.1f} | {:.3f} | {:.0f} | {} |".format(
            "table" if r["arm"] == "table" else "0.5", r["v"], r["seed"], r["fc"], r["fc_ci"], r["ft"], r["ft_ci"],
            r["ft"] / r["fc"], r["hc"], r["beta"], r["lc"], r["t_rake"], ox))
    print()
    for arm in ("table", "const"):
        a = means(rows, arm)
        if 600 in a:
            ratios = ", ".join("{}: {:.3f} (Oxley {:.3f})".format(v, a[v]["fc"] / a[600]["fc"], OXLEY[v][0] / OXLEY[600][0])
                               for v in sorted(a))
            print("{} (seed means): Fc/w(v) / Fc/w(600 m/min): {}".format(arm, ratios))
    fig, ax = plt.subplots(1, 3, figsize=(13, 4))
    vo = sorted(OXLEY)
    for arm, style, label in (("table", "o-", "swarf, tool mu(v_s) table"), ("const", "s--", "swarf, mu = 0.5")):
        m = means(rows, arm)
        v = sorted(m)
        ax[0].errorbar(v, [m[x]["fc"] for x in v], yerr=[m[x]["fc_ci"] for x in v], fmt=style, capsize=3, label=label)
        ax[1].errorbar(v, [m[x]["ft"] for x in v], yerr=[m[x]["ft_ci"] for x in v], fmt=style, capsize=3, label=label)
        ax[2].plot(v, [m[x]["hc"] for x in v], style, label=label)
        single = [r for r in rows if r["arm"] == arm]
        if any(m[x]["n"] > 1 for x in v):
            ax[0].plot([r["v"] for r in single], [r["fc"] for r in single], "k.", ms=3)
    ax[0].plot(vo, [OXLEY[v][0] for v in vo], "k:", label="Oxley (sharp tool)")
    ax[1].plot(vo, [OXLEY[v][0] * OXLEY[v][1] for v in vo], "k:", label="Oxley (sharp tool)")
    ax[2].plot(vo, [0.2 / OXLEY[v][2] for v in vo], "k:", label="Oxley (sharp tool)")
    for a_, name in zip(ax, ("cutting force Fc/w (kN/m)", "thrust force Ft/w (kN/m)", "chip thickness h_c (mm)")):
        a_.set_xlabel("cutting speed (m/min)")
        a_.set_ylabel(name)
        a_.grid(alpha=0.3)
    ax[0].legend(fontsize=8)
    fig.suptitle("Default C45 cut, h = 0.2 mm, rake 10 deg: the speed trend with the tool's friction "
                 "against the sliding speed (seed means, 95 % intervals of the runs; dots: single runs)", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(dest, "speed_friction.png"), dpi=110)


if __name__ == "__main__":
    main()
