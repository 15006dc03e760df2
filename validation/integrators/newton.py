#!/usr/bin/python3
"""The Newton solver of the Newmark step against the fixed-point sweeps and velocity Verlet on
the hysteresis bar (validation/hysteresis/bar.toml): steps, force evaluations, tangent
products, CG iterations, wall time, and the loop's stress against the small-step run
(fixed-point Newmark, at most 0.8 of the stable step), at equal times and at the peaks.

Usage: validation/integrators/newton.py [--swarf build/bin/swarf] [--out DIR] [--factors 2,5,10,20]
Prints a markdown table (README.md here). Wall time on the 2-core machine: about 4 minutes."""
import argparse, bisect, csv, json, os, subprocess, sys, time

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(os.path.dirname(here))
case = os.path.join(root, "validation", "hysteresis", "bar.toml")


def run(swarf, out, extra):
    cmd = [swarf, "run", case, "--out", out, "--set", "output.progress=false", "--set", "output.vtk=false",
           "--set", "output.plots=false"] + extra
    t0 = time.time()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    wall = time.time() - t0
    s = json.load(open(os.path.join(out, "summary.json")))
    with open(os.path.join(out, "series.csv")) as f:
        rows = list(csv.DictReader(f))
    return s, {k: [float(r[k]) for r in rows] for k in ("time", "stress")}, wall


def interp(x, xs, ys):
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
    ap.add_argument("--out", default=os.path.join(root, "results", "newton"))
    ap.add_argument("--factors", default="2,5,10,20")
    ap.add_argument("--krylov-tolerance", default="1e-2")
    a = ap.parse_args()
    runs = [("verlet", "0.5", ["--set", "integrator.scheme=verlet"]),
            ("fixed_point", "0.8", ["--set", "integrator.scheme=newmark"])]
    for f in a.factors.split(","):
        runs.append(("newton", f, ["--set", "integrator.scheme=newmark", "--set", "integrator.solver=newton",
                                   "--set", "integrator.krylov_tolerance=" + a.krylov_tolerance,
                                   "--set", "integrator.dt_max"]))  # (f x dt_stable, filled in below)
    results = []
    ref = None
    for solver, f, extra in runs:
        out = os.path.join(a.out, "%s_%s" % (solver, f))
        if solver == "newton":
            extra = extra[:-1] + ["integrator.dt_max=%.17g" % (float(f) * ds)]
        s, series, wall = run(a.swarf, out, extra)
        ds = s["derived"]["dt_stable_s"]  # (the first run, Verlet, sets it for the Newton runs' dt_max)
        if solver == "fixed_point":
            ref = series
        results.append((solver, f, s, series, wall))
        print("%s %s: %.0f s" % (solver, f, wall), file=sys.stderr)
    peak_ref = max(abs(x) for x in ref["stress"])
    print("| solver | dt_max / dt_stable | steps | rejected | force evaluations | tangent products | "
          "CG iterations | wall s | peak stress MPa | peak difference / peak | largest difference at equal "
          "times / peak |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for solver, f, s, series, wall in results:
        r = s["run"]
        peak = max(abs(x) for x in series["stress"])
        diff = max(abs(interp(t, series["time"], series["stress"]) - x) for t, x in zip(ref["time"], ref["stress"]))
        print("| %s | %s | %d | %d | %d | %s | %s | %.1f | %.1f | %.2e | %.2e |" % (
            solver, f if solver != "verlet" else "0.5 (fixed)", r["steps"], r["steps_rejected"],
            r["force_evaluations"], r.get("tangent_products", "-"), r.get("krylov_iterations", "-"), wall,
            peak / 1e6, abs(peak - peak_ref) / peak_ref, diff / peak_ref))


if __name__ == "__main__":
    main()
