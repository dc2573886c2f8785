#!/usr/bin/env python3
"""Figures of step-6 from its output/ (mortar.csv, cavity.csv, ratios.csv):

    mortar.png   the two arcs of the cavity scene near the contact point,
                 Body 1's vertices projected onto Body 2 (the cuts)
    cavity.png   the pressure in the cavity against Hertz
    ratios.png   a and N_max against E1/E2, with Hertz and the reference
                 formulation's tables

    python3 plot.py OUTPUT_DIR
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def mortar(out):
    data = rows(os.path.join(out, "mortar.csv"))
    x_max = 1.5
    fig, ax = plt.subplots(figsize=(7.0, 3.6))
    lift = 0.005  # Body 1 drawn above Body 2, so that the cuts show
    for kind, colour, dy in (("face1", "C0", lift), ("face2", "C1", 0.0)):
        for r in data:
            if r["kind"] != kind:
                continue
            x0, x1 = float(r["x_from"]), float(r["x_to"])
            y0, y1 = float(r["y_from"]) + dy, float(r["y_to"]) + dy
            if min(x0, x1) > x_max:
                continue
            ax.plot([x0, x1], [y0, y1], "-", color=colour, lw=1)
            ax.plot([x0, x1], [y0, y1], "|", color=colour, ms=10)
    # The cuts: the projections of Body 1's vertices onto Body 2, along n.
    cuts = set()
    for r in data:
        if r["kind"] == "piece2":
            cuts.update((float(r["x_from"]), float(r["x_to"])))
    for x in sorted(cuts):
        if x <= x_max:
            ax.axvline(x, color="grey", lw=0.4, ls=":")
    # The contact elements: two faces of Body 1 each.
    ends = {}
    for r in data:
        if r["kind"] == "face1":
            j = int(r["element"])
            xs = (float(r["x_from"]), float(r["x_to"]))
            lo, hi = ends.get(j, (min(xs), max(xs)))
            ends[j] = (min(lo, *xs), max(hi, *xs))
    for lo, hi in ends.values():
        for x in (lo, hi):
            if x <= x_max:
                ax.axvline(x, color="C2", lw=1.0, alpha=0.5)
    ax.plot([], [], "-", color="C2", alpha=0.5, label="contact element ends")
    ax.plot([], [], "-|", color="C0", label="Body 1 (cylinder), lifted by 0.005 mm")
    ax.plot([], [], "-|", color="C1", label="Body 2 (cavity)")
    ax.plot([], [], ":", color="grey", label="ends of the pieces of Body 2")
    ax.set_xlim(0, x_max)
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.set_title("Mortar projection: cylinder of R = 40 in a cavity of R = 120")
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "mortar.png"), dpi=110)


def cavity(out):
    data = rows(os.path.join(out, "cavity.csv"))
    a, p = float(data[0]["hertz_a"]), float(data[0]["hertz_max_pressure"])
    s = [float(r["s"]) for r in data]
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    ax.step(s, [float(r["pressure"]) for r in data], where="mid",
            label="dpana, element tractions")
    xs = [a * i / 200 for i in range(201)]
    ax.plot(xs, [p * math.sqrt(max(0.0, 1 - (x / a) ** 2)) for x in xs], "k--",
            label="Hertz, R = 60 mm")
    ax.set_xlim(0, max(s))
    ax.set_xlabel("s (mm)")
    ax.set_ylabel("pressure -N (MPa)")
    ax.set_title("Cylinder in a cavity: contact pressure")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "cavity.png"), dpi=110)


def ratios(out):
    data = [{k: float(v) for k, v in r.items()}
            for r in rows(os.path.join(out, "ratios.csv"))]
    ratio = [r["ratio"] for r in data]
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9.0, 3.8))
    for ax, key, table, hertz, unit in (
        (ax1, "a", "table_a", "hertz_a", "a (mm)"),
        (ax2, "max_pressure", "table_max_pressure", "hertz_max_pressure",
         "N_max (MPa)"),
    ):
        ax.semilogx(ratio, [r[key] for r in data], "o-", label="dpana")
        ax.semilogx(ratio, [r[hertz] for r in data], "k--", label="Hertz")
        tabled = [r for r in data if r[table] > 0]
        ax.semilogx([r["ratio"] for r in tabled], [r[table] for r in tabled],
                    "s", mfc="none", label="reference formulation, tables 4.1-4.3")
        ax.set_xlabel("E1 / E2")
        ax.set_ylabel(unit)
        ax.legend(fontsize=7)
    ax1.set_title("half width")
    ax2.set_title("maximum pressure")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "ratios.png"), dpi=110)


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else "output"
    mortar(out)
    cavity(out)
    ratios(out)
