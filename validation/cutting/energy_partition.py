#!/usr/bin/python3
"""Where the plastic work of a cut goes, layer by layer of the uncut material.

Reads a finished cutting run's results.h5 (the end state: positions, displacements and the
particles' accumulated plastic work, /particles/plastic_work, J/m^3, written since 2026-12-08; for
older runs the equivalent plastic strain peeq) and, for the material the tool has passed over in the steady part
of the cut (initial x between --from and the tool tip less --behind), sums the plastic work per
unit area of the cut (J/m^2 = N/m: a force per unit width) in layers of the initial depth below
the uncut surface. With --tracer work (the default where the run wrote it) the work of a particle
is what its rods dissipated, half of each rod's, including rods that broke or were exchanged since:
the whole ledger's plastic work, placed. With --tracer peeq the work of a particle is its volume a^3/4 times the Johnson-Cook work density
of C45 at its peeq, integral_0^peeq (A + B e^n) de (cold, at the reference rate: a measure of
where the work goes; with [heat] the sums are scaled so that the whole workpiece's estimate equals
the heat ledger's plastic work, heat_plastic_J over the Taylor-Quinney fraction).

  validation/cutting/energy_partition.py RUN_DIR [RUN_DIR ...] [--png FILE]

Prints, per run, the work per area in the removed layer (the chip), in a band of the chip's
side within 3 R of the separation line (the tool tip's height), in the same band below it, and in
the machined workpiece below; and writes the profile against depth over R as a PNG.
"""
import argparse
import json
import sys

import h5py
import numpy as np

A, B, N = 553.1e6, 600.8e6, 0.234  # C45, Jaspers (Pa, Pa, 1)


def work_density(peeq):
    e = np.maximum(peeq, 0.0)
    return A * e + B * e ** (N + 1) / (N + 1)  # J/m^3


def analyse(run, x_from, behind, tracer):
    f = h5py.File(f"{run}/results.h5", "r")
    r = float(f["cutting/radius"][0])
    n = int(f["cutting/workpiece_particles"][0])
    tip = f["cutting/tool_tip"][:]
    top = float(f["cutting/uncut_surface_z"][0])
    width = float(f["cutting/width"][0])
    x = f["particles/position"][:n]
    x0 = x - f["particles/displacement"][:n]
    peeq = f["particles/peeq"][:n]
    a = 2.0 * np.sqrt(2.0) * r
    vol = a ** 3 / 4.0
    x_to = tip[0] - behind
    sel = (x0[:, 0] >= x_from) & (x0[:, 0] < x_to)
    area = (x_to - x_from) * width  # m^2 of cut surface
    if tracer == "temperature":
        # The heat each particle holds, m c (T - T0): with [heat] and a negligible conductivity
        # (heat.conductivity = 1e-3 W/(m K): a diffusion length of a fraction of a micrometre over the
        # run) it is where the plastic work (times Taylor-Quinney) and the friction were dissipated.
        summ = json.load(open(f"{run}/summary.json"))
        heat_case = summ["case_effective"]["heat"]
        rho = summ["case_effective"]["material"]["density"]
        t0 = heat_case.get("initial_temperature", 293.15)
        temp = f["particles/temperature"][:n]
        w = rho * vol * heat_case["heat_capacity"] * (temp - t0) / area  # J/m^2 per particle
    elif tracer == "work":
        w = vol * f["particles/plastic_work"][:n] / area  # J/m^2 per particle (the field is J/m^3 of vol)
    else:
        w = vol * work_density(peeq) / area  # J/m^2 per particle
    # Scaled to the run's own plastic work (the heat ledger's plastic heat over the Taylor-Quinney
    # fraction) where the run had heat: the shape of the estimate, the ledger's total.
    scale = 1.0
    try:
        if tracer in ("temperature", "work"):
            raise ValueError("the temperature is its own scale, the work is the ledger's")
        with open(f"{run}/summary.json") as fh:
            summ = json.load(fh)
        heat = summ.get("heat", {})
        tq = summ.get("case_effective", {}).get("heat", {}).get("taylor_quinney", 0.9)
        if "heat_plastic_J" in heat:
            scale = heat["heat_plastic_J"] / tq / (vol * work_density(peeq)).sum()
    except (OSError, ValueError):
        pass
    w *= scale
    depth = top - x0[:, 2]  # m below the uncut surface (top centres at 0)
    h = top - tip[2]  # the depth of cut, m (the tip's height below the top centres)
    s = depth - h  # m below the separation line (negative: removed material)
    out = {
        "R_um": r * 1e6,
        "h_mm": h * 1e3,
        "chip": w[sel & (s < -3 * r)].sum(),
        "band_above": w[sel & (s >= -3 * r) & (s < 0)].sum(),
        "band_below": w[sel & (s >= 0) & (s < 3 * r)].sum(),
        "below": w[sel & (s >= 3 * r)].sum(),
    }
    # The separation band's excess: its work beyond what the bulk chip's work density (the mean
    # over initial depths 100-180 um above the line, where the profile is flat at every R) would
    # give the same removed layers, plus all the work below the line (the workpiece has no bulk).
    thick = a / 2.0
    bulk = sel & (s < -100e-6) & (s >= -180e-6)
    w_bulk = w[bulk].sum() / ((bulk.sum() * vol) / area)  # J/m^3 of initial volume
    band_up = sel & (s >= -4 * r) & (s < 0)
    out["bulk_MJ_per_m3"] = w_bulk / 1e6
    out["band_excess"] = (w[band_up].sum() - w_bulk * band_up.sum() * vol / area) + w[sel & (s >= 0)].sum()
    # The same over a fixed physical depth, 100 um above the line (the shoulder of the profile
    # next to the band: the chip's underside, which slides on the rake face, is included).
    near = sel & (s >= -100e-6) & (s < 0)
    out["near_excess"] = (w[near].sum() - w_bulk * near.sum() * vol / area) + w[sel & (s >= 0)].sum()
    out["scale"] = scale
    out["total"] = out["chip"] + out["band_above"] + out["band_below"] + out["below"]
    # The profile: work per area per layer of initial depth (layers a/2 apart), against s/R.
    layer = np.round(s / (a / 2.0)).astype(int)
    prof = {}
    for k in np.unique(layer[sel]):
        prof[k] = w[sel & (layer == k)].sum()
    out["profile"] = prof
    out["counts"] = {k: int((sel & (layer == k)).sum()) for k in prof}
    # By the initial height against the tip's: the layers above it, the layer at its height (within a/8: the
    # lattice's layers are a/2 apart and the default's tip lies on one), and the layers below.
    out["above_tip"] = sum(v for k, v in prof.items() if k * a / 2.0 < -a / 8.0)
    out["tip_layer"] = sum(v for k, v in prof.items() if abs(k * a / 2.0) <= a / 8.0)
    out["below_tip"] = sum(v for k, v in prof.items() if k * a / 2.0 > a / 8.0)
    out["a"] = a
    out["r"] = r
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("runs", nargs="+")
    p.add_argument("--from", dest="x_from", type=float, default=1.0e-3, help="m: initial x where the sum starts")
    p.add_argument("--behind", type=float, default=0.3e-3, help="m: the sum ends this far behind the tip")
    p.add_argument("--png", default="")
    p.add_argument("--csv", default="", help="the profiles: one row per run and layer, SI units")
    p.add_argument("--tracer", choices=["auto", "work", "peeq", "temperature"], default="auto",
                   help="the work the particles' rods dissipated (plastic_work), the work from the plastic strain "
                        "(Johnson-Cook density) or from the heat each particle holds; auto: work where the run wrote it")
    args = p.parse_args()

    def tracer_of(run):
        if args.tracer != "auto":
            return args.tracer
        with h5py.File(f"{run}/results.h5", "r") as f:
            return "work" if "particles/plastic_work" in f else "peeq"

    rows = [analyse(r, args.x_from, args.behind, tracer_of(r)) for r in args.runs]
    print("| run | R (um) | chip, removed beyond 3R (kJ/m^2) | band 3R above the line | band 3R below | "
          "workpiece below | total (kJ/m^2 = kN/m) | bulk chip (MJ/m^3) | separation band's excess (kJ/m^2) | "
          "excess within 100 um of the line (kJ/m^2) | scale to the ledger |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for run, o in zip(args.runs, rows):
        print(f"| {run} | {o['R_um']:.2f} | {o['chip']/1e3:.1f} | {o['band_above']/1e3:.1f} | "
              f"{o['band_below']/1e3:.1f} | {o['below']/1e3:.1f} | {o['total']/1e3:.1f} | {o['bulk_MJ_per_m3']:.0f} | {o['band_excess']/1e3:.1f} | {o['near_excess']/1e3:.1f} | {o['scale']:.3f} |")
    print()
    print("| run | R (um) | above the tip's height (kJ/m^2) | the layer at the tip's height | below it | total |")
    print("|---|---|---|---|---|---|")
    for run, o in zip(args.runs, rows):
        print(f"| {run} | {o['R_um']:.2f} | {o['above_tip']/1e3:.1f} | {o['tip_layer']/1e3:.1f} | "
              f"{o['below_tip']/1e3:.1f} | {o['total']/1e3:.1f} |")
    if args.csv:
        with open(args.csv, "w") as fh:
            fh.write("run,R_m,depth_below_separation_m,work_per_area_J_per_m2,work_density_J_per_m3,particles\n")
            for run, o in zip(args.runs, rows):
                for k in sorted(o["profile"]):
                    v = o["profile"][k]
                    fh.write(f"{run},{o['r']:.6g},{k * o['a'] / 2.0:.6g},{v:.6g},{v / (o['a'] / 2.0):.6g},"
                             f"{o['counts'][k]}\n")
        print(f"wrote {args.csv}")
    if args.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(1, 3, figsize=(16, 4.5))
        for run, o in zip(args.runs, rows):
            k = np.array(sorted(o["profile"]))
            v = np.array([o["profile"][i] for i in k])
            s_um = k * o["a"] / 2.0 * 1e6
            # per unit of depth: J/m^2 per m of layer = J/m^3, shown in MJ/m^3 (the mean work density)
            ax[0].plot(s_um, v / (o["a"] / 2.0) / 1e6, ".-", label=f"R = {o['R_um']:.1f} um")
            ax[1].plot(s_um / o["R_um"], v / 1e3, ".-", label=f"R = {o['R_um']:.1f} um")
            # The work summed from the uncut surface down to each layer: where two resolutions' totals part.
            ax[2].plot(s_um, np.cumsum(v) / 1e3, ".-", label=f"R = {o['R_um']:.1f} um")
        ax[0].set_xlabel("initial depth below the separation line (um; < 0: removed material)")
        ax[0].set_ylabel("plastic work per volume of the layer (MJ/m^3)")
        ax[1].set_xlabel("initial depth below the separation line / R")
        ax[1].set_ylabel("plastic work per area of cut in the layer (kJ/m^2)")
        ax[2].set_xlabel("initial depth below the separation line (um)")
        ax[2].set_ylabel("per area of cut, summed from the top (kJ/m^2)")
        for a_ in ax:
            a_.axvline(0, color="k", lw=0.8)
            a_.legend()
            a_.grid(alpha=0.3)
        fig.suptitle("Where the plastic work of the cut goes (C45, h = 0.2 mm, steady part)")
        fig.tight_layout()
        fig.savefig(args.png, dpi=110)
        print(f"wrote {args.png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
