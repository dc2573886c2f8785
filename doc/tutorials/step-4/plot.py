#!/usr/bin/env python3
"""Figures of tutorial step 4, from the CSV files its run writes.

    python3 plot.py OUTPUT_DIR

tractions.png: N, T and the friction bound -mu N along the base of the
receding block, the stick, slip and separated zones shaded;
history.png: the shared residual of every outer iteration of the four
solvers.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MU = 1.0
COLOURS = {"stick": "tab:green", "slip": "tab:orange", "separated": "0.8"}


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def plot_tractions(out):
    data = rows(os.path.join(out, "tractions.csv"))
    s = [float(r["s"]) for r in data]
    N = [float(r["N"]) for r in data]
    T = [float(r["T"]) for r in data]
    h = s[1] - s[0] if len(s) > 1 else 1.0
    fig, ax = plt.subplots(figsize=(7.5, 4.6))
    shown = set()
    for si, r in zip(s, data):
        status = r["status"]
        ax.axvspan(si - h / 2, si + h / 2, color=COLOURS[status], alpha=0.25,
                   lw=0, label=None if status in shown else status)
        shown.add(status)
    ax.step(s, N, where="mid", color="tab:blue", label="N")
    ax.step(s, T, where="mid", color="tab:red", label="T")
    ax.step(s, [-MU * n for n in N], where="mid", color="tab:red", ls=":",
            label="-mu N (friction bound)")
    ax.axhline(-50, color="k", lw=0.8, ls="--", label="N without friction")
    ax.set_xlabel("s (mm), from the plane of symmetry")
    ax.set_ylabel("traction (MPa)")
    ax.set_title("Receding block, mu = 1: tractions and zones")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, ncol=4, loc="upper center",
              bbox_to_anchor=(0.5, -0.15))
    fig.tight_layout()
    fig.savefig(os.path.join(out, "tractions.png"), dpi=120)


def plot_history(out):
    data = rows(os.path.join(out, "history.csv"))
    solvers = []
    for r in data:
        if r["solver"] not in solvers:
            solvers.append(r["solver"])
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    for name in solvers:
        sel = [r for r in data if r["solver"] == name]
        k = [int(r["iteration"]) for r in sel]
        res = [max(float(r["residual"]), 1e-17) for r in sel]
        right.loglog(k, res, marker=".", label=name)
        if name.startswith("splitting"):
            left.semilogy(k, res, marker="o", label=name)
    left.set_title("D-PANA splitting: the fixed-point history")
    right.set_title("the four solvers")
    for ax in (left, right):
        ax.axhline(1e-10, color="k", lw=0.8, ls="--", label="tolerance")
        ax.set_xlabel("outer iteration")
        ax.set_ylabel("shared residual (natural map)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "history.png"), dpi=120)


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else "output"
    plot_tractions(out)
    plot_history(out)
