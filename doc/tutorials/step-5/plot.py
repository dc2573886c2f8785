#!/usr/bin/env python3
"""Figures of step-5 from its output/ (convergence.csv, profiles.csv):

    profiles.png      the pressure of every mesh against Hertz's ellipse
    convergence.png   relative errors of a and N_max against the element size
    time_error.png    the same errors against the wall time of the run

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
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def main(out):
    table = rows(os.path.join(out, "convergence.csv"))
    profiles = rows(os.path.join(out, "profiles.csv"))
    a_h, p_h = table[0]["hertz_a"], table[0]["hertz_max_pressure"]

    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for r in table:
        n = r["contact_refinements"]
        pts = [(p["s"], p["pressure"]) for p in profiles
               if p["contact_refinements"] == n]
        ax.step([s for s, _ in pts], [p for _, p in pts], where="mid",
                label=f"{int(n)} refinements, h = {r['h']:.2f} mm")
    xs = [a_h * i / 200 for i in range(201)]
    ax.plot(xs, [p_h * math.sqrt(max(0.0, 1 - (x / a_h) ** 2)) for x in xs],
            "k--", label="Hertz")
    ax.set_xlim(0, 1.4 * a_h)
    ax.set_xlabel("s (mm)")
    ax.set_ylabel("pressure -N (MPa)")
    ax.set_title("Cylinder on a rigid plane: contact pressure")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "profiles.png"), dpi=110)

    h = [r["h"] for r in table]
    t = [r["seconds"] for r in table]
    errors(out, table, a_h, p_h, h, "contact element size h (mm)",
           "Mesh convergence", "convergence.png", reference_slope=True)
    errors(out, table, a_h, p_h, t, "wall time of the run (s)",
           "Time against error", "time_error.png")


def errors(out, table, a_h, p_h, x, xlabel, title, name,
           reference_slope=False):
    """The relative errors of a and N_max of every mesh against x."""
    n_fine = table[-1]["max_pressure"]
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.loglog(x, [abs(r["a"] / a_h - 1) for r in table], "o-",
              label="|e_a|, a = edge of last element")
    ax.loglog(x, [abs(r["a_fit"] / a_h - 1) for r in table], "s-",
              label="|e_a|, a from the elliptic fit")
    e_n = [abs(r["max_pressure"] / p_h - 1) for r in table]
    ax.loglog(x, e_n, "^-", label="|e_N|, N_max")
    ax.loglog(x[:-1], [abs(r["max_pressure"] / n_fine - 1) for r in table[:-1]],
              "v--", label="|N_max / N_max(finest) - 1|")
    if reference_slope:
        ax.loglog(x, [h / a_h for h in x], "k:", label="h / a")
    for xi, y, r in zip(x, e_n, table):
        ax.annotate(f"{int(r['n_elements'])} el.", (xi, y), fontsize=7,
                    textcoords="offset points", xytext=(3, 3))
    ax.set_xlabel(xlabel)
    ax.set_ylabel("relative error against Hertz")
    ax.set_title(title)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, name), dpi=110)

if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "output")
