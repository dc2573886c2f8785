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
    e_a = [abs(r["a"] / a_h - 1) for r in table]
    e_fit = [abs(r["a_fit"] / a_h - 1) for r in table]
    e_n = [abs(r["max_pressure"] / p_h - 1) for r in table]
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.loglog(h, e_a, "o-", label="|e_a|, a = edge of last element")
    ax.loglog(h, e_fit, "s-", label="|e_a|, a from the elliptic fit")
    ax.loglog(h, e_n, "^-", label="|e_N|, N_max")
    n_fine = table[-1]["max_pressure"]
    ax.loglog(h[:-1], [abs(r["max_pressure"] / n_fine - 1) for r in table[:-1]],
              "v--", label="|N_max / N_max(finest) - 1|")
    ax.loglog(h, [x / a_h for x in h], "k:", label="h / a")
    ax.set_xlabel("contact element size h (mm)")
    ax.set_ylabel("relative error against Hertz")
    ax.set_title("Mesh convergence")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "convergence.png"), dpi=110)

    t = [r["seconds"] for r in table]
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.loglog(t, e_a, "o-", label="|e_a|, a = edge of last element")
    ax.loglog(t, e_fit, "s-", label="|e_a|, elliptic fit")
    ax.loglog(t, e_n, "^-", label="|e_N|")
    ax.loglog(t[:-1], [abs(r["max_pressure"] / n_fine - 1) for r in table[:-1]],
              "v--", label="|N_max / N_max(finest) - 1|")
    for x, y, r in zip(t, e_n, table):
        ax.annotate(f"{int(r['n_elements'])} el.", (x, y), fontsize=7,
                    textcoords="offset points", xytext=(3, 3))
    ax.set_xlabel("wall time of the run (s)")
    ax.set_ylabel("relative error against Hertz")
    ax.set_title("Time against error")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "time_error.png"), dpi=110)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "output")
