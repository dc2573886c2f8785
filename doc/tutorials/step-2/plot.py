#!/usr/bin/env python3
"""Figures of step 2, drawn from the CSV files the program wrote.

    plot.py OUTPUT_DIR

column.png: one column of the compliance A (the surface response to a unit
normal traction on one contact element) against the elastic half-plane,
both as differences to a reference element; compliance.png: the matrix |A|
and its eigenvalues; cost.png: the times of factorisation and condensation
against the number of contact unknowns.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def column(out):
    c = read(os.path.join(out, "column.csv"))
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    ax.plot(c["x"], 1e6 * c["exact_w_minus_ref"], "k-", lw=1, label="half-plane (Flamant), same differences")
    ax.plot(c["x"], 1e6 * c["w_minus_ref"], "o", ms=3, label=r"$A_{2i,2j}/|\Gamma_i| - $ reference (finite elements)")
    ax.set_xlabel("x (mm), centre of contact element i")
    ax.set_ylabel(r"mean normal displacement difference ($10^{-6}$ mm)")
    ax.set_title("A column of A: unit normal traction on one element")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "column.png"), dpi=110)


def compliance(out):
    A = np.loadtxt(os.path.join(out, "compliance.csv"), delimiter=",")
    lam = read(os.path.join(out, "eigenvalues.csv"))["eigenvalue"]
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(10, 4.2))
    im = ax.imshow(np.log10(np.maximum(np.abs(A), 1e-5 * np.abs(A).max())), cmap="viridis")
    fig.colorbar(im, ax=ax, label=r"$\log_{10}|A_{ij}|$")
    ax.set_title("the compliance A (unknowns N, T interleaved;\nentries below 1e-5 of the largest shown as 1e-5)", fontsize=9)
    ax.set_xlabel("column")
    ax.set_ylabel("row")
    bx.semilogy(np.arange(1, len(lam) + 1), np.sort(lam)[::-1], ".")
    bx.set_xlabel("index")
    bx.set_ylabel(r"eigenvalue (mm$^2$/MPa)")
    bx.set_title("its eigenvalues: all positive")
    bx.grid(True, which="both", lw=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "compliance.png"), dpi=110)


def cost(out):
    c = read(os.path.join(out, "cost.csv"))
    n = len(c["refinements"])
    # The first rows refine the mesh at fixed candidate width; the last
    # rows widen the candidate surface on the finest mesh.
    finest = c["refinements"].max()
    widths = np.arange(n) >= n - np.sum(c["refinements"] == finest) + 1
    mesh = ~widths
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    ax.loglog(c["unknowns"][mesh], c["seconds_factorization"][mesh], "s-", label="factorisation, mesh refined")
    ax.loglog(c["unknowns"][mesh], c["seconds_condensation"][mesh], "o-", label="condensation, mesh refined")
    ax.loglog(c["unknowns"][widths], c["seconds_factorization"][widths], "s--", label="factorisation, finest mesh, wider surface")
    ax.loglog(c["unknowns"][widths], c["seconds_condensation"][widths], "o--", label="condensation, finest mesh, wider surface")
    x = c["unknowns"][widths]
    y = c["seconds_condensation"][widths]
    ax.loglog(x, y[-1] * x / x[-1], "k:", lw=0.8, label="slope 1")
    for i in np.nonzero(mesh)[0]:
        ax.annotate("%d dofs" % c["dofs"][i], (c["unknowns"][i], c["seconds_factorization"][i]), fontsize=7,
                    textcoords="offset points", xytext=(4, -10))
    ax.set_xlabel("number of contact unknowns n")
    ax.set_ylabel("wall time (s)")
    ax.set_title("cost of the condensation")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "cost.png"), dpi=110)


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else "output"
    column(out)
    compliance(out)
    cost(out)
