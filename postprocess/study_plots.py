#!/usr/bin/python3
"""Plots of a parameter study (PNG): each metric against each varied key, as computed by
'swarf sweep' into DIR/plots/plots.json (the script only draws); a steady mean with its 95 %
confidence interval (plots.json "y_err") gets error bars. Usage:
study_plots.py DIR/plots/plots.json. Prints 'wrote FILE' for every file written."""
import json
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main():
    path = sys.argv[1]
    spec = json.load(open(path))
    out_dir = os.path.dirname(os.path.abspath(path))
    for p in spec["plots"]:
        x, y = p["x"], p["y"]
        fig, ax = plt.subplots(figsize=(6, 4.2), dpi=110)
        err = p.get("y_err")  # 95 % half-widths of steady means (None: the case has none)
        if err and any(e is not None for e in err):
            # Cases without an interval are drawn without a bar (never a zero-length "exact" one).
            with_bar = [(xi, yi, e) for xi, yi, e in zip(x, y, err) if e is not None]
            ax.errorbar([v[0] for v in with_bar], [v[1] for v in with_bar], yerr=[v[2] for v in with_bar], fmt="o",
                        ms=5, capsize=3, color="C0", label="cases, bars: " + p.get("y_err_label", "95 % CI"))
            bare = [(xi, yi) for xi, yi, e in zip(x, y, err) if e is None]
            if bare:
                ax.plot([v[0] for v in bare], [v[1] for v in bare], "o", ms=5, mfc="none", color="C0",
                        label="cases without an interval (too few steady rows)")
        else:
            ax.plot(x, y, "o", ms=5, label="cases")
        # Several cases at one x (repetitions, other keys): a line through the means.
        means = {}
        for xi, yi in zip(x, y):
            means.setdefault(xi, []).append(yi)
        xs = sorted(means)
        if len(xs) > 1:
            ax.plot(xs, [sum(means[v]) / len(means[v]) for v in xs], "-", lw=1.2, color="C0", alpha=0.7,
                    label="mean at each value" if any(len(v) > 1 for v in means.values()) else None)
        ax.set_xlabel(p["x_label"])
        ax.set_ylabel(p["y_label"])
        ax.set_title(spec.get("title", ""), fontsize=9)
        ax.grid(True, alpha=0.3)
        if any(len(v) > 1 for v in means.values()) or err:
            ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(out_dir, p["file"]))
        plt.close(fig)
        print("wrote " + p["file"])


if __name__ == "__main__":
    main()
