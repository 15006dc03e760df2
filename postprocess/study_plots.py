#!/usr/bin/python3
"""Plots of a parameter study (PNG): each metric against each varied key, as computed by
'swarf sweep' into DIR/plots/plots.json (the script only draws). One colour per group (the
cases that agree in the varied keys that do not go with x: one line per speed against the
depth of cut); a steady mean with its 95 % confidence interval (plots.json "y_err") gets
error bars; Oxley's figure at each case's conditions (plots.json "reference") is a dashed
line of the group's colour. Usage: study_plots.py DIR/plots/plots.json. Prints 'wrote FILE'
for every file written."""
import json
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def mean_line(xs, ys):
    """The mean of ys at each distinct x, sorted by x (None values left out)."""
    means = {}
    for xi, yi in zip(xs, ys):
        if yi is not None:
            means.setdefault(xi, []).append(yi)
    keys = sorted(means)
    return keys, [sum(means[k]) / len(means[k]) for k in keys], any(len(v) > 1 for v in means.values())


# Units shown scaled to what an engineer reads (mm, kN/m, MPa): (unit, threshold, factor, shown).
SCALES = [("m", 0.05, 1e3, "mm"), ("N/m", 1e4, 1e-3, "kN/m"), ("Pa", 1e5, 1e-6, "MPa"), ("N/m^2", 1e5, 1e-6, "MPa")]


def scaled(label, values):
    """(label, factor): a label 'name [unit]' with the unit scaled for values of this size."""
    if not label.endswith("]") or " [" not in label:
        return label, 1.0
    name, unit = label[:-1].rsplit(" [", 1)
    top = max((abs(v) for v in values if v is not None), default=0.0)
    for u, threshold, factor, shown in SCALES:
        if unit == u and ((factor > 1 and top < threshold) or (factor < 1 and top > threshold)):
            return "%s [%s]" % (name, shown), factor
    return label, 1.0


def scaled_group(name):
    """A group label 'key = value unit' with the value in the unit scaled as the axes are."""
    head, eq, rest = name.rpartition(" = ")
    if not eq or " " not in rest:
        return name
    value, unit = rest.split(" ", 1)
    try:
        v = float(value)
    except ValueError:
        return name
    label, factor = scaled("x [%s]" % unit, [v])
    return "%s = %.3g %s" % (head, v * factor, label[3:-1])


def main():
    path = sys.argv[1]
    spec = json.load(open(path))
    out_dir = os.path.dirname(os.path.abspath(path))
    for p in spec["plots"]:
        x_label, fx = scaled(p["x_label"], p["x"])
        y_label, fy = scaled(p["y_label"], p["y"])
        x = [v * fx for v in p["x"]]
        y = [v * fy for v in p["y"]]
        n = len(x)
        group = p.get("group") or [0] * n
        labels = [scaled_group(g) for g in p.get("group_labels") or [""]]
        err = [None if e is None else e * fy for e in p.get("y_err") or [None] * n]  # 95 % half-widths
        ref = [None if r is None else r * fy for r in p.get("reference") or [None] * n]  # Oxley
        fig, ax = plt.subplots(figsize=(6.4, 4.4), dpi=110)
        repeated = False
        for g, name in enumerate(labels):
            idx = [i for i in range(n) if group[i] == g]
            if not idx:
                continue
            colour = "C%d" % (g % 10)
            tag = (name + ": ") if name else ""
            with_bar = [i for i in idx if err[i] is not None]
            bare = [i for i in idx if err[i] is None]
            if with_bar:
                ax.errorbar([x[i] for i in with_bar], [y[i] for i in with_bar], yerr=[err[i] for i in with_bar],
                            fmt="o", ms=5, capsize=3, color=colour,
                            label=tag + "cases, bars: " + p.get("y_err_label", "95 % CI"))
            if bare:
                # Cases without an interval are drawn without a bar (never a zero-length "exact" one).
                ax.plot([x[i] for i in bare], [y[i] for i in bare], "o", ms=5, mfc="none", color=colour,
                        label=tag + ("cases without an interval (too few steady rows)" if p.get("y_err")
                                     else "cases"))
            xs, ms, rep = mean_line([x[i] for i in idx], [y[i] for i in idx])
            repeated = repeated or rep
            if len(xs) > 1:
                ax.plot(xs, ms, "-", lw=1.2, color=colour, alpha=0.7)
            rx, rm, _ = mean_line([x[i] for i in idx], [ref[i] for i in idx])
            if rx:
                ax.plot(rx, rm, "--" if len(rx) > 1 else "x", lw=1.4, ms=7, color=colour,
                        label=tag + "Oxley" if name else p.get("reference_label", "Oxley's theory"))
        ax.set_xlabel(x_label)
        ax.set_ylabel(y_label)
        title = spec.get("title", "")
        if repeated:
            title += "\nsolid lines: the mean over the seeds at each x"
        if any(r is not None for r in ref):
            title += "\ndashed: " + p.get("reference_label", "Oxley's theory")
        ax.set_title(title, fontsize=8)
        ax.grid(True, alpha=0.3)
        if len(labels) > 1 or p.get("y_err") or any(r is not None for r in ref):
            ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(out_dir, p["file"]))
        plt.close(fig)
        print("wrote " + p["file"])


if __name__ == "__main__":
    main()
