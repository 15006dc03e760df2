#!/usr/bin/python3
"""A cut driven from Python: the built-in default cut (or a case file), the tool's forces recorded
by a step listener, the chip's particles found with NumPy, a CSV and a PNG plot of the forces.

    python3 examples/python/cut_forces.py --end-time 2e-5 --out cut_forces    # 0.2 mm of travel
    python3 examples/python/cut_forces.py my_case.toml --threads 2

Writes OUT/forces.csv (time s, cutting and thrust force per width, N/m) and OUT/forces.png:
Fc = -Fx and Ft = Fz of the force the particles exert on the tool (mesh 'tool') over the
workpiece's width, as `swarf run` writes them in series.csv (cutting_force_per_width,
thrust_force_per_width).
"""
import argparse
import csv
import os

import numpy as np

import swarf


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("case", nargs="?", help="case file (default: the built-in default cut)")
    ap.add_argument("--end-time", type=float, default=2e-5, help="simulated time, s (default 2e-5)")
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--out", default="cut_forces", help="output directory")
    a = ap.parse_args()
    if not a.end_time > 0:
        ap.error(f"--end-time {a.end_time}: must be a positive time in s")

    swarf.set_threads(a.threads)
    sim = swarf.Simulation(a.case, set=[f"integrator.end_time={a.end_time!r}"])
    if "tool" not in sim.mesh_names:
        ap.error(f"{a.case}: the case has no mesh named 'tool' (meshes: {sim.mesh_names})")
    x0 = np.array(sim.particles.position)
    # The workpiece's width as `swarf run` takes it: the lattice's extent along y plus half a
    # cell edge (a/2 = sqrt(2) R for touching spheres on the FCC lattice), m.
    work = x0[: sim.workpiece_particles]
    width = float(work[:, 1].max() - work[:, 1].min() + np.sqrt(2.0) * sim.particles.radius[0])

    rows = []  # (t s, Fc/w N/m, Ft/w N/m): Fc = -Fx and Ft = Fz of the particles' force on the tool
    sim.add_listener(after=lambda s: rows.append((s.time, -s.mesh_force("tool")[0] / width,
                                                  s.mesh_force("tool")[2] / width)))
    every = max(1, int(a.end_time / sim.dt) // 20)
    step = 0
    while sim.time < a.end_time * (1 - 1e-12):
        sim.step(a.end_time - sim.time)
        step += 1
        if step % every == 0:
            print(f"  t = {sim.time:.3e} s of {a.end_time:.3e} s, {sim.steps} steps", flush=True)

    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, "forces.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["time_s", "cutting_force_per_width_N_per_m", "thrust_force_per_width_N_per_m"])
        w.writerows(rows)
    # The particles that moved above the uncut surface: the chip so far.
    moved = sim.particles.position[:, 2] - x0[:, 2] > 0.5 * sim.particles.radius
    print(f"{sim.steps} steps to t = {sim.time:.4g} s; {int(moved.sum())} particles lifted by more than half "
          f"a radius; broken rods {sim.broken_rods}")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    t = np.array([r[0] for r in rows]) * 1e6
    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.plot(t, [r[1] / 1e3 for r in rows], label="cutting force Fc/w")
    ax.plot(t, [r[2] / 1e3 for r in rows], label="thrust force Ft/w")
    ax.set_xlabel("time (us)")
    ax.set_ylabel("force per width (kN/m)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "forces.png"), dpi=120)
    print(f"wrote {a.out}/forces.csv and {a.out}/forces.png")


if __name__ == "__main__":
    main()
