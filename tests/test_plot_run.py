#!/usr/bin/env python3
"""test_plot_run.py: ctest 'plot_run_forces': the legends of forces.png (postprocess/plot_run.py).

Three synthetic cutting runs (series.csv and summary.json only, 40 rows): one whose chip
thickness was measured from the middle on, one where it never was (every row 0, no
thickness_m), and one that ended before its steady window (null steady means: drawn without
them). The script's figures are kept instead of written (Figure.savefig is replaced) and
checked: the broken-rod curve has a legend entry; every legend drawn has at least one entry (no
empty box when the chip thickness was not measured); the chip-thickness entries appear only
when it was measured. Usage: test_plot_run.py PATH/TO/plot_run.py. Exit 77 (skipped) without
matplotlib.
"""
import importlib.util
import json
import os
import sys
import tempfile

SKIP = 77


def write_run(path, measured, steady=True):
    os.makedirs(path)
    rows = 40
    with open(os.path.join(path, "series.csv"), "w") as f:
        f.write("time,tool_travel,cutting_force_per_width,thrust_force_per_width,broken_fraction,chip_thickness\n")
        for k in range(rows):
            t = 1e-7 * k
            h = 0.25e-3 if measured and k >= rows // 2 else 0.0
            f.write("%r,%r,%r,%r,%r,%r\n" % (t, 10 * t, 2e5 + 1e3 * (k % 3), 5e4, 1e-4 * k, h))
    cutting = {"steady_from_s": 2e-6, "cutting_force_per_width_mean_N_per_m": 2.01e5,
               "thrust_force_per_width_mean_N_per_m": 5e4, "cutting_force_per_width_ci95_N_per_m": 500.0,
               "thrust_force_per_width_ci95_N_per_m": None}
    if not steady:  # a run that ended before its steady window: no steady figures (null)
        cutting = {"steady_from_s": 1e-4, "cutting_force_per_width_mean_N_per_m": None,
                   "thrust_force_per_width_mean_N_per_m": None, "cutting_force_per_width_ci95_N_per_m": None,
                   "thrust_force_per_width_ci95_N_per_m": None, "steady_note": "the steady window starts ..."}
    chip = {"thickness_m": 0.25e-3} if measured else {"note": "chip thickness not measured"}
    with open(os.path.join(path, "summary.json"), "w") as f:
        json.dump({"cutting": cutting, "chip": chip}, f)


def legend_texts(fig):
    """[(axis label, [entries])] of every legend drawn in the figure."""
    out = []
    for ax in fig.axes:
        leg = ax.get_legend()
        if leg is not None:
            out.append((ax.get_ylabel(), [t.get_text() for t in leg.get_texts()]))
    return out


def main():
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.figure
    except ImportError as e:
        print("SKIP: no matplotlib for %s: %s" % (sys.executable, e))
        return SKIP
    spec = importlib.util.spec_from_file_location("plot_run", sys.argv[1])
    plot_run = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(plot_run)
    saved = {}
    matplotlib.figure.Figure.savefig = lambda fig, name, *a, **k: saved.__setitem__(os.path.basename(name), fig)
    failures = []
    with tempfile.TemporaryDirectory(prefix="swarf_test_plot_run_") as tmp:
        for measured, steady in ((True, True), (False, True), (False, False)):
            run = os.path.join(tmp, ("measured" if measured else "unmeasured") + ("" if steady else "_nosteady"))
            write_run(run, measured, steady)
            saved.clear()
            summary = json.load(open(os.path.join(run, "summary.json")))
            try:
                plot_run.plot_cut(run, summary, plot_run.read_series(os.path.join(run, "series.csv")))
            except Exception as e:  # (a null steady mean once raised a TypeError)
                failures.append("%s: plot_cut raised %r" % (run, e))
                continue
            fig = saved.get("forces.png")
            if fig is None:
                failures.append("%s: forces.png not drawn" % run)
                continue
            legends = legend_texts(fig)
            entries = [e for _, es in legends for e in es]
            print("%s: legends %s" % (os.path.basename(run), legends))
            if not any("broken" in e for e in entries):
                failures.append("%s: the broken-rod curve has no legend entry" % run)
            for label, es in legends:
                if not es:
                    failures.append("%s: an empty legend box (axis '%s')" % (run, label))
            thickness = [e for e in entries if "h_c" in e or "chip thickness" in e]
            if measured and len(thickness) != 2:
                failures.append("%s: expected the h_c curve and its median in the legend, got %s" % (run, thickness))
            if not measured and thickness:
                failures.append("%s: chip-thickness entries without a measurement: %s" % (run, thickness))
    for f in failures:
        print("FAIL: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
