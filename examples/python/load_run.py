#!/usr/bin/python3
"""Run a short cut, then read what it wrote with swarf.load: the forces over time and the chip
coloured by a per-particle field, as PNG pictures (matplotlib, no display needed).

    python3 examples/python/load_run.py --end-time 2e-5 --out load_run          # the default cut
    python3 examples/python/load_run.py my_case.toml --field von_mises_stress --out mine

Steps, as one would type them in a notebook:
  1. summary = swarf.run(case, out=DIR, set=[...])  runs the cut as `swarf run` does and returns
     summary.json as a dict;
  2. r = swarf.load(DIR)  reads the run: r.series (series.csv as a NumPy structured array, with
     r.units), r.times and r.frame(k) (the frames' per-particle fields from results.h5);
  3. OUT/forces.png: the tool's force over time; OUT/chip.png: the last frame's particles seen
     along the width (x, z), coloured by the field (default: peeq, the accumulated equivalent plastic strain), 1 mm around
     the field's peak.
"""
import argparse
import os

import numpy as np

import swarf


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("case", nargs="?", help="case file (default: the built-in default cut)")
    ap.add_argument("--end-time", type=float, default=2e-5, help="simulated time, s (default 2e-5)")
    ap.add_argument("--field", default="peeq",
                    help="the frames' field that colours the chip (default peeq, the accumulated equivalent plastic strain)")
    ap.add_argument("--threads", type=int, default=0, help="OpenMP threads (0: OpenMP's default)")
    ap.add_argument("--out", default="load_run", help="run directory and pictures")
    a = ap.parse_args()
    if not a.end_time > 0:
        ap.error(f"--end-time {a.end_time}: must be a positive time in s")

    # 1. The run: about ten frames over it, no plots of the program's own (this script draws).
    summary = swarf.run(a.case, out=a.out, threads=a.threads,
                        set=[f"integrator.end_time={a.end_time!r}", f"output.frame_interval={a.end_time / 10!r}",
                             "output.vtk=true", "output.plots=false"])
    print(f"run {summary['status']}: {summary['counts']['particles']} particles, "
          f"{summary['counts'].get('steps', '?')} steps")

    # 2. What it wrote.
    r = swarf.load(a.out)
    print(r)
    s = r.series
    t_us = s["time"] * 1e6

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    # 3a. Forces: per width for a [cut] case, else the tool's force components.
    fig, ax = plt.subplots(figsize=(6, 3.5))
    if "cutting_force_per_width" in s.dtype.names:
        for col, label in (("cutting_force_per_width", "cutting force Fc/w"),
                           ("thrust_force_per_width", "thrust force Ft/w")):
            ax.plot(t_us, s[col] / 1e3, label=label)
        ax.set_ylabel("force per width (kN/m)")
    else:
        for col in ("force_tool_x", "force_tool_z"):
            ax.plot(t_us, s[col], label=f"{col} ({r.units.get(col, 'N')})")
        ax.set_ylabel("force")
    ax.set_xlabel("time (us)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "forces.png"), dpi=120)
    plt.close(fig)

    # 3b. The chip: the last frame's particles, coloured by the field.
    f = r.frame(-1)
    if a.field not in f.fields:
        ap.error(f"--field {a.field}: the frames hold {sorted(f.fields)}")
    v = f.fields[a.field]
    if v.ndim > 1:  # (a vector or tensor: its magnitude)
        v = np.linalg.norm(v, axis=1)
    fig, ax = plt.subplots(figsize=(7, 3.5))
    sc = ax.scatter(f.position[:, 0] * 1e3, f.position[:, 2] * 1e3, c=v, s=4, cmap="viridis")
    fig.colorbar(sc, ax=ax, label=f"{a.field} ({f.units.get(a.field, '1')})")
    # Zoomed on where the field peaks (the tool's edge and the chip): 1 mm along x around it.
    peak = f.position[np.argmax(v), 0] * 1e3
    ax.set_xlim(max(f.position[:, 0].min() * 1e3, peak - 0.6), min(f.position[:, 0].max() * 1e3, peak + 0.4) + 0.05)
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("z (mm)")
    ax.set_title(f"t = {f.time * 1e6:.3g} us")
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "chip.png"), dpi=120, bbox_inches="tight")  # (equal axes leave margins)
    plt.close(fig)
    print(f"frames at {', '.join(f'{t * 1e6:.3g}' for t in r.times)} us; {a.field} up to {v.max():.4g}")
    print(f"wrote {a.out}/forces.png and {a.out}/chip.png")


if __name__ == "__main__":
    main()
