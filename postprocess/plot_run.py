#!/usr/bin/python3
"""Plots of one swarf run (PNG): the stress-strain loop with the rod-law prediction for a
uniaxial case, and the energy balance. Usage: plot_run.py RUN_DIR [SUMMARY_JSON].
Prints 'wrote FILE' for every file written. Draws only columns swarf computed."""
import csv, json, os, sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read_series(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    head = rows[0]
    cols = {h: [] for h in head}
    for r in rows[1:]:
        for h, v in zip(head, r):
            cols[h].append(float(v))
    return cols


def plot_cut(run, summary, s):
    """Cutting and thrust force per width (and the passive force of a cut with free sides), the
    broken-rod fraction and the chip thickness against tool travel."""
    travel = [v * 1e3 for v in s["tool_travel"]]
    cut = summary.get("cutting", {})
    fig, (ax, bx) = plt.subplots(2, 1, figsize=(8, 6.5), dpi=120, sharex=True,
                                 gridspec_kw={"height_ratios": [2, 1]})
    ax.plot(travel, [v / 1e3 for v in s["cutting_force_per_width"]], lw=0.8, color="C0",
            label="cutting force Fc/w (against the cutting direction)")
    ax.plot(travel, [v / 1e3 for v in s["thrust_force_per_width"]], lw=0.8, color="C3",
            label="thrust force Ft/w (away from the workpiece)")
    means = [("cutting_force_per_width_mean_N_per_m", "C0"), ("thrust_force_per_width_mean_N_per_m", "C3")]
    if "passive_force_per_width" in s:  # a cut with free sides (an oblique cut)
        ax.plot(travel, [v / 1e3 for v in s["passive_force_per_width"]], lw=0.8, color="C2",
                label="passive force Fp/w (on the tool along +y)")
        means.append(("passive_force_per_width_mean_N_per_m", "C2"))
    steady = cut.get("steady_from_s")
    x0 = None
    if steady is not None:
        # travel at the start of the steady window (first row at or after steady_from)
        x0 = next((x for x, t in zip(travel, s["time"]) if t >= steady), None)
        if x0 is not None:
            ax.axvspan(x0, travel[-1], color="0.9", zorder=0, label="steady part (statistics)")
            for key, c in means:
                if cut.get(key) is not None:  # (null: no steady rows)
                    ax.hlines(cut[key] / 1e3, x0, travel[-1], colors=c, linestyles="--", lw=1.5)
                    # the mean's 95 % confidence interval (batch means; null when the part is too short)
                    ci = cut.get(key.replace("_mean_", "_ci95_"))
                    if ci is not None:
                        ax.fill_between([x0, travel[-1]], (cut[key] - ci) / 1e3, (cut[key] + ci) / 1e3, color=c,
                                        alpha=0.25, lw=0, label="steady mean (dashed), its 95 % CI" if c == "C0" else None)
    ax.set_ylabel("force per width [kN/m]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    ax.set_title("Cutting forces on the tool (%s)" % os.path.basename(os.path.normpath(run)))
    bx.plot(travel, [100 * v for v in s["broken_fraction"]], color="k", lw=1.2,
            label="broken rods (of the lattice's own, left axis)")
    bx.set_ylabel("broken rods [%]")
    # One legend for both axes of the lower panel (a legend per axis would put one over the
    # other), with the chip thickness only when it was measured: no empty box.
    handles = list(bx.get_legend_handles_labels()[0])
    pts = [(x, v * 1e3) for x, v in zip(travel, s.get("chip_thickness", [])) if v > 0]  # per row, 0 = not measured
    chip = summary.get("chip", {})
    cx = bx.twinx() if pts else None
    if pts:
        cx.plot([p[0] for p in pts], [p[1] for p in pts], color="C2", lw=0.8, label="chip thickness h_c (right axis)")
        if "thickness_m" in chip and steady is not None and x0 is not None:
            first = max(x0, pts[0][0])  # (over the rows that measured it: the chip's head passes late)
            cx.hlines(chip["thickness_m"] * 1e3, first, travel[-1], colors="C2", linestyles="--", lw=1.5,
                      label="h_c, median of the steady part")
        cx.set_ylabel("chip thickness [mm]", color="C2")
        # From zero: a settled chip's 1 % wander, scaled to the axis, read as a chip still thickening.
        cx.set_ylim(0.0, 1.15 * max(p[1] for p in pts))
        handles += cx.get_legend_handles_labels()[0]
    elif "chip_thickness" in s:
        bx.text(0.99, 0.05, "chip thickness not measured", transform=bx.transAxes, ha="right", va="bottom",
                fontsize=8, color="C2")
    (cx if pts else bx).legend(handles=handles, fontsize=8, loc="upper left")  # (on the twin: drawn over its lines)
    bx.set_xlabel("tool travel [mm]")
    bx.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(run, "forces.png"))
    print("wrote forces.png")


def plot_tool(run, summary, s):
    """A compliant tool: its deflection from the holder against time with the static F/k, and
    the amplitude spectra of the deflection and the forces (tool_spectrum.csv) with the mount's
    natural frequency."""
    tool = summary.get("tool", {})
    t = [v * 1e6 for v in s["time"]]
    fig, (ax, bx) = plt.subplots(2, 1, figsize=(8, 7), dpi=120)
    for c, col in (("x", "C0"), ("z", "C3")):
        ax.plot(t, [v * 1e6 for v in s["tool_deflection_" + c]], lw=0.8, color=col,
                label="deflection %s (tool minus holder)" % c)
        st = tool.get("static_deflection_%s_m" % c)
        t0 = next((v * 1e6 for v in s["time"] if v >= summary.get("cutting", {}).get("steady_from_s", 0)), None)
        if st is not None and t0 is not None:
            ax.hlines(st * 1e6, t0, t[-1], colors=col, linestyles="--", lw=1.5,
                      label="static %s = steady force / stiffness" % ("-Fc/k" if c == "x" else "Ft/k"))
    ax.set_xlabel("time [us]")
    ax.set_ylabel("deflection [um]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title("Compliant tool (%s): f_n = %.4g kHz, zeta = %.3g" % (
        os.path.basename(os.path.normpath(run)), tool.get("natural_frequency_x_Hz", float("nan")) / 1e3,
        tool.get("damping_ratio_x") or float("nan")))
    path = os.path.join(run, "tool_spectrum.csv")
    if os.path.exists(path):
        sp = read_series(path)
        f = [v / 1e3 for v in sp["frequency_Hz"]]
        bx.semilogy(f, [max(v * 1e6, 1e-12) for v in sp["deflection_x_m"]], lw=1.0, color="C0", label="deflection x")
        bx.semilogy(f, [max(v * 1e6, 1e-12) for v in sp["deflection_z_m"]], lw=1.0, color="C3", label="deflection z")
        fn = tool.get("natural_frequency_x_Hz")
        if fn:
            bx.axvline(fn / 1e3, color="k", ls="--", lw=1.0, label="f_n = sqrt(k/m) / 2 pi")
        bx.set_xlim(0, min(f[-1], 5 * fn / 1e3) if fn else f[-1])
        bx.set_xlabel("frequency [kHz]")
        bx.set_ylabel("amplitude [um]")
        bx.grid(alpha=0.3, which="both")
        bx.legend(fontsize=8)
        bx.set_title("Amplitude spectra from the first contact (Hann window), resolution %.3g kHz" %
                     (tool.get("spectrum_resolution_Hz", float("nan")) / 1e3), fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(run, "tool_vibration.png"))
    print("wrote tool_vibration.png")


def main():
    run = sys.argv[1]
    summary = json.load(open(sys.argv[2] if len(sys.argv) > 2 else os.path.join(run, "summary.json")))
    s = read_series(os.path.join(run, "series.csv"))
    if "strain" in s:
        fig, ax = plt.subplots(figsize=(7, 5), dpi=120)
        ax.plot(s["strain"], [v / 1e6 for v in s["stress"]], "-", lw=1.6, label="swarf bar (grip force / cross-section)")
        ax.plot(s["strain"], [v / 1e6 for v in s["stress_predicted"]], "--", lw=1.2, color="k",
                label="rod law via FCC relations: 3 (E100/E) sigma_rod(eps/3)")
        u = summary.get("uniaxial", {})
        dev = u.get("deviation_percent", {})
        if dev:
            txt = "\n".join("%s: %+.2f %%" % (k.replace("_", " "), v) for k, v in dev.items())
            ax.text(0.02, 0.98, "deviation from prediction\n" + txt, transform=ax.transAxes, va="top", fontsize=8,
                    bbox=dict(boxstyle="round", fc="w", alpha=0.8))
        ax.set_xlabel("nominal strain (grip separation change / gauge length) [1]")
        ax.set_ylabel("nominal stress (grip force / initial cross-section) [MPa]")
        ax.set_title("Uniaxial cyclic test along [100]: %s" % os.path.basename(summary.get("case_file", "")))
        ax.grid(alpha=0.3)
        ax.legend(loc="lower right", fontsize=8)
        fig.tight_layout()
        out = os.path.join(run, "stress_strain.png")
        fig.savefig(out)
        print("wrote stress_strain.png")
    if "cutting_force_per_width" in s:
        plot_cut(run, summary, s)
    if "tool_deflection_x" in s:
        plot_tool(run, summary, s)
    fig, ax = plt.subplots(figsize=(7, 4.5), dpi=120)
    t = [v * 1e6 for v in s["time"]]
    for key, label in (("external_work", "external work"), ("kinetic_energy", "kinetic"),
                       ("rotational_energy", "rotational (part of kinetic)"), ("potential_energy", "potential (gravity)"),
                       ("elastic_energy", "elastic (rods)"), ("contact_work", "taken up by contacts"), ("plastic_work", "plastic work"),
                       ("viscous_work", "viscous"), ("fracture_energy", "fracture"), ("energy_error", "balance error")):
        if key in s:
            ax.plot(t, s[key], label=label, lw=1.2)
    ax.set_xlabel("time [us]")
    ax.set_ylabel("energy [J]")
    ax.set_title("Energy balance")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(run, "energy.png"))
    print("wrote energy.png")


if __name__ == "__main__":
    main()
