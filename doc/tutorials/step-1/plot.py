#!/usr/bin/env python3
"""Figures of step 1, drawn from the CSV files the program wrote.

    plot.py OUTPUT_DIR

convergence.png: the four relative errors against the mesh size h, with
slopes 1 and 2 for reference; stresses.png: sigma_rr and sigma_tt at the
cell centroids of the finest mesh against r, with Lame's exact curves.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def convergence(out):
    e = read(os.path.join(out, "errors.csv"))
    h = e["h"]
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for key, label, marker in [
        ("e_u", r"$\|u_h-u\|_{L^2}/\|u\|_{L^2}$", "o"),
        ("e_u_max", r"$\max_{\rm vertices}|u_h-u|/u_r(a)$", "s"),
        ("e_sigma", r"$\|\sigma_h-\sigma\|_{L^2}/(p\,|\Omega|^{1/2})$", "^"),
        ("e_sigma_max", r"$\max_{\rm centroids}|\sigma_h-\sigma|/p$", "v"),
    ]:
        ax.loglog(h, e[key], marker=marker, label=label)
    for order, key in [(1, "e_sigma"), (2, "e_u")]:
        c = e[key][-1] / h[-1] ** order * 0.5
        ax.loglog(h, [c * x ** order for x in h], "k--", lw=0.8)
        ax.text(h[0], c * h[0] ** order, "  slope %d" % order, va="top")
    ax.set_xlabel("mesh size h (mm)")
    ax.set_ylabel("relative error")
    ax.set_title("Lamé cylinder, P1 triangles: error against mesh size")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "convergence.png"), dpi=110)


def stresses(out):
    s = read(os.path.join(out, "stress_profile.csv"))
    order = sorted(range(len(s["r"])), key=lambda i: s["r"][i])
    r = [s["r"][i] for i in order]
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for key, label in [("sigma_tt", r"$\sigma_{\theta\theta}$"), ("sigma_rr", r"$\sigma_{rr}$")]:
        ax.plot(s["r"], s[key], ".", ms=4, alpha=0.5, label=label + " at the cell centroids")
        ax.plot(r, [s["exact_" + key][i] for i in order], "k-", lw=1)
    ax.plot([], [], "k-", label="Lamé (exact)")
    ax.set_xlabel("r (mm)")
    ax.set_ylabel("stress (MPa)")
    ax.set_title("Polar stresses against the radius (%d triangles)" % len(r))
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8, markerscale=2)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "stresses.png"), dpi=110)


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else "output"
    convergence(out)
    stresses(out)
