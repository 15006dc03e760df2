#!/usr/bin/python3
"""Both integrators side by side: the hysteresis loop (validation/hysteresis/bar.toml) and a
bar pulled to fracture (fracture.toml), each with velocity Verlet and the implicit Newmark
step. Writes results.md, loops.png and fracture.png here.

Usage: validation/integrators/compare.py [--swarf build/bin/swarf] [--out DIR]
Wall time on the 2-core machine: about 5 minutes."""
import argparse, csv, json, os, subprocess, sys, time

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(os.path.dirname(here))


def run(swarf, case, out, extra):
    cmd = [swarf, "run", case, "--out", out, "--set", "output.progress=false", "--set", "output.vtk=false"] + extra
    t0 = time.time()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    wall = time.time() - t0
    s = json.load(open(os.path.join(out, "summary.json")))
    with open(os.path.join(out, "series.csv")) as f:
        rows = list(csv.DictReader(f))
    series = {k: [float(r[k]) for r in rows] for k in rows[0]}
    return s, series, wall


def interp(x, xs, ys):
    # linear interpolation on an ascending xs
    import bisect
    k = bisect.bisect_left(xs, x)
    if k <= 0:
        return ys[0]
    if k >= len(xs):
        return ys[-1]
    t = (x - xs[k - 1]) / (xs[k] - xs[k - 1])
    return ys[k - 1] + t * (ys[k] - ys[k - 1])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--swarf", default=os.path.join(root, "build", "bin", "swarf"))
    ap.add_argument("--out", default=os.path.join(root, "results", "integrators"))
    a = ap.parse_args()
    runs = {}
    for kind, case in (("loop", os.path.join(root, "validation", "hysteresis", "bar.toml")),
                       ("fracture", os.path.join(here, "fracture.toml"))):
        for scheme in ("verlet", "newmark"):
            out = os.path.join(a.out, "%s_%s" % (kind, scheme))
            runs[(kind, scheme)] = run(a.swarf, case, out, ["--set", "integrator.scheme=" + scheme])
            print("%s %s: %.0f s" % (kind, scheme, runs[(kind, scheme)][2]), file=sys.stderr)

    # Loop agreement: stress of both schemes at the same times, relative to the yield stress.
    sv, sn = runs[("loop", "verlet")][1], runs[("loop", "newmark")][1]
    ys = runs[("loop", "verlet")][0]["derived"]["bar_yield_stress_Pa"]
    diff = max(abs(interp(t, sn["time"], sn["stress"]) - s) for t, s in zip(sv["time"], sv["stress"]))
    lines = ["| case | scheme | steps | rejected | sweeps/step mean (max) | force evaluations per us | "
             "wall s | ns per particle-step | broken fraction at end | energy error / external work |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for (kind, scheme), (s, series, wall) in runs.items():
        r = s["run"]
        res = s["results"]
        lines.append("| %s | %s | %d | %d | %.2f (%d) | %.2f | %.1f | %.0f | %.4f | %.1e |" % (
            kind, scheme, r["steps"], r["steps_rejected"], r["iterations_per_step_mean"], r["iterations_per_step_max"],
            r["force_evaluations_per_us"], wall, r["ns_per_particle_step"], res["broken_fraction"],
            res["energy_error_J"] / max(abs(res["external_work_J"]), 1e-300)))
    frac_v, frac_n = runs[("fracture", "verlet")][1], runs[("fracture", "newmark")][1]

    def first_break(series):
        for t, b in zip(series["time"], series["broken_fraction"]):
            if b > 0:
                return t
        return float("nan")

    def failure_strain(series):
        k = max(range(len(series["stress"])), key=lambda i: series["stress"][i])
        return series["strain"][k], series["stress"][k]

    ev, sv_peak = failure_strain(frac_v)
    en, sn_peak = failure_strain(frac_n)
    text = ["<!-- written by compare.py; do not edit -->", "\n".join(lines), "",
            "Loop: largest stress difference between the schemes at equal times: %.3g MPa = %.3f %% of the "
            "predicted bar yield stress (%.4g MPa)." % (diff / 1e6, 100 * diff / ys, ys / 1e6),
            "",
            "Fracture: first broken rod at t = %.4g us (verlet) and %.4g us (newmark); peak stress %.4g MPa at "
            "strain %.5f (verlet) and %.4g MPa at strain %.5f (newmark)." % (
                first_break(frac_v) * 1e6, first_break(frac_n) * 1e6, sv_peak / 1e6, ev, sn_peak / 1e6, en)]
    open(os.path.join(here, "results.md"), "w").write("\n".join(text) + "\n")
    print("\n".join(text))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 5), dpi=120)
    ax.plot(sv["strain"], [v / 1e6 for v in sv["stress"]], "-", lw=2.2, label="velocity Verlet")
    ax.plot(sn["strain"], [v / 1e6 for v in sn["stress"]], "--", lw=1.2, label="Newmark (fixed point, step control)")
    ax.plot(sv["strain"], [v / 1e6 for v in sv["stress_predicted"]], ":", color="k", lw=1, label="rod-law prediction")
    ax.set_xlabel("nominal strain [1]")
    ax.set_ylabel("nominal stress [MPa]")
    ax.set_title("Hysteresis bar (6 x 6 cells): both schemes")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(here, "loops.png"))

    fig, axs = plt.subplots(1, 3, figsize=(14, 4.2), dpi=110)
    for scheme, series in (("velocity Verlet", frac_v), ("Newmark", frac_n)):
        t = [v * 1e6 for v in series["time"]]
        axs[0].plot(t, series["broken_fraction"], label=scheme)
        axs[1].plot(series["strain"], [v / 1e6 for v in series["stress"]], label=scheme)
        axs[2].plot(t, [v * 1e9 for v in series["dt"]], label=scheme)
    axs[0].set_xlabel("time [us]"); axs[0].set_ylabel("broken-rod fraction [1]"); axs[0].set_title("broken rods")
    axs[1].set_xlabel("nominal strain [1]"); axs[1].set_ylabel("nominal stress [MPa]"); axs[1].set_title("pull to fracture")
    axs[2].set_xlabel("time [us]"); axs[2].set_ylabel("step size [ns]"); axs[2].set_title("step size")
    for x in axs:
        x.grid(alpha=0.3)
        x.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(here, "fracture.png"))


if __name__ == "__main__":
    main()
