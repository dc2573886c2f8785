#!/usr/bin/env python3
"""Figures of tutorial step 3, from the CSV files its run writes.

    python3 plot.py OUTPUT_DIR

lcp_solvers.png: iterations and time of projected Gauss-Seidel and the
active set method on the normal LCP of the uniform receding block against
the number of contact elements; candidate_surface.png: the normal tractions
of the block under a line load for several candidate surfaces.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def plot_solvers(out):
    data = rows(os.path.join(out, "lcp_solvers.csv"))
    fig, (left, right) = plt.subplots(1, 2, figsize=(9, 3.6))
    for method, marker in (("pgs", "o"), ("active set", "s")):
        sel = [r for r in data if r["method"] == method]
        n = [int(r["n"]) for r in sel]
        left.loglog(n, [int(r["iterations"]) for r in sel], marker=marker,
                    label=method)
        right.loglog(n, [1e3 * float(r["seconds"]) for r in sel],
                     marker=marker, label=method)
    left.set_xlabel("contact elements n")
    left.set_ylabel("sweeps (PGS) / active-set steps")
    right.set_xlabel("contact elements n")
    right.set_ylabel("time (ms)")
    for ax in (left, right):
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.suptitle("Normal LCP of the uniform receding block (mu = 0)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "lcp_solvers.png"), dpi=120)


def plot_candidates(out):
    data = rows(os.path.join(out, "candidates.csv"))
    widths = []
    for r in data:
        if r["half_width"] not in widths:
            widths.append(r["half_width"])
    fig, ax = plt.subplots(figsize=(7, 3.8))
    for k, w in enumerate(widths):
        sel = [r for r in data if r["half_width"] == w]
        s = [float(r["s"]) for r in sel]
        N = [float(r["N"]) for r in sel]
        small = float(w) < 15
        ax.plot(s, N, linestyle="--" if small else "-",
                marker="x" if small else "o", markersize=7 - k,
                label="half width %g mm" % float(w))
    ax.set_xlabel("s (mm)")
    ax.set_ylabel("N (MPa)")
    ax.set_title("Line load on the layer 40 x 20 mm: candidate surfaces")
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "candidate_surface.png"), dpi=120)


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else "output"
    plot_solvers(out)
    plot_candidates(out)
