#!/usr/bin/env python3
"""Figures of tutorial step 7 from the CSV data its run wrote.

    plot.py OUTPUT_DIR

receding_3d.png: N and T_x of every contact element of the three 3D blocks
(all rows t) against the plane solution, along s.
sphere.png (if the sphere ran): -N of every contact element of the sphere
against the distance r of its centroid from the axis, with Hertz's
p0 sqrt(1 - r^2/a^2).
polygon.png: the excess of friction capacity of the s-gon dragged towards a
vertex, measured and 1/cos(pi/s) - 1.
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def rows(path):
    with open(path, newline="") as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def plot_block(out):
    plane = rows(os.path.join(out, "plane.csv"))
    block = rows(os.path.join(out, "block_3d.csv"))
    fig, ax = plt.subplots(figsize=(7, 4.2))
    s = [r["s"] for r in plane]
    ax.step(s, [r["N"] for r in plane], where="mid", color="k", label="2D: N")
    ax.step(s, [r["Tx"] for r in plane], where="mid", color="k", ls="--",
            label="2D: $T_x$")
    for L, m in ((80, "o"), (160, "s"), (320, "^")):
        sel = [r for r in block if r["L"] == L]
        ax.plot([r["s"] for r in sel], [r["N"] for r in sel], m, mfc="none",
                color="C0", ms=5, label=f"3D L = {L}: N (all rows)")
        ax.plot([r["s"] for r in sel], [r["Tx"] for r in sel], m, mfc="none",
                color="C3", ms=5, label=f"3D L = {L}: $T_x$ (all rows)")
    ax.set_xlabel("s (mm)")
    ax.set_ylabel("traction (MPa)")
    ax.set_title("Receding block, nu = 0, mu = 1: 3D rows against the plane run")
    ax.legend(fontsize=7, ncol=2)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "receding_3d.png"), dpi=110)


def plot_polygon(out):
    data = [r for r in rows(os.path.join(out, "polygon.csv"))
            if r["sides"] > 0 and r["phi"] > 0]
    s = [r["sides"] for r in data]
    fine = [3.5 * 1.05 ** k for k in range(80)]
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.loglog(fine, [1 / math.cos(math.pi / x) - 1 for x in fine], "k-",
              label="1/cos(pi/s) - 1")
    ax.loglog(s, [r["measured"] for r in data], "o", color="C3",
              label="measured (drag towards a vertex)")
    ax.set_xlabel("sides s of the friction polygon")
    ax.set_ylabel("excess friction capacity")
    ax.set_xticks([4, 8, 16, 32])
    ax.set_xticklabels(["4", "8", "16", "32"])
    ax.legend()
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "polygon.png"), dpi=110)


def plot_sphere(out):
    path = os.path.join(out, "sphere.csv")
    if not os.path.exists(path):
        return
    data = rows(path)
    hertz = rows(os.path.join(out, "hertz.csv"))[0]
    a, p0 = hertz["a"], hertz["p0"]
    r = [a * k / 200 for k in range(201)]
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(r, [p0 * math.sqrt(max(0.0, 1 - (x / a) ** 2)) for x in r], "k-",
            label="Hertz, $p_0\\sqrt{1 - r^2/a^2}$")
    ax.plot([d["r"] for d in data], [d["p"] for d in data], "o", color="C0",
            mfc="none", ms=5, label="dpana, element means of $-N$")
    ax.set_xlabel("r (mm), distance of the element centroid from the axis")
    ax.set_ylabel("pressure (MPa)")
    ax.set_title(f"Sphere R = 10 mm on a rigid plane, P = {hertz['P']:.0f} N")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "sphere.png"), dpi=110)


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else "output"
    plot_block(out)
    plot_polygon(out)
    plot_sphere(out)
