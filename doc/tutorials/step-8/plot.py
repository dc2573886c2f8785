#!/usr/bin/env python3
"""Figure of tutorial step 8 from the CSV data its run wrote.

    plot.py OUTPUT_DIR

residuals.png: the natural-map residual of the contact solver after every
outer iteration, for the held block and for the hard cases.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main(out):
    history = {}
    with open(os.path.join(out, "residuals.csv"), newline="") as f:
        for row in csv.DictReader(f):
            history.setdefault(row["case"], []).append(
                (int(row["iteration"]), float(row["residual"])))
    fig, ax = plt.subplots(figsize=(6.5, 4))
    styles = ["o-", "s--", "^-.", "v:", "D-"]
    for k, (name, points) in enumerate(history.items()):
        ax.semilogy([p[0] for p in points], [max(p[1], 1e-17) for p in points],
                    styles[k % len(styles)], mfc="none", ms=5,
                    label=name.replace("_splitting_active_set", "")
                    .replace("_", " "))
    ax.axhline(1e-10, color="k", ls=":", lw=1, label="tolerance 1e-10")
    ax.set_xlabel("outer iteration")
    ax.set_ylabel("natural-map residual")
    ax.set_title("Floating block on a rigid plane: the solver's residual")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "residuals.png"), dpi=110)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "output")
