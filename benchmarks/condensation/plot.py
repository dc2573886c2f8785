#!/usr/bin/env python3
"""Plot the results of condensation_benchmark (the CSV it writes) as a PNG.

One panel per scene (the 3D receding block, the 2D Hertz cylinder): wall
time against the number of degrees of freedom, log-log, of the factorisation
and of the condensation of both routes (blocked solves, Schur complement) and
of the Schur route with MUMPS as its factorisation (if the CSV has it).
The number of contact unknowns is written next to each point of the Schur
condensation.

Usage: plot.py results.csv [output.png]
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SERIES = [
    ("blocked_factor", "factorisation (blocked route)", "tab:green", "s", "-"),
    ("blocked_condense", "condensation, blocked solves", "tab:red", "v", "-"),
    ("schur_factor", "factorisation (Gamma_c last)", "tab:green", "s", "--"),
    ("schur_condense", "condensation, Schur", "tab:blue", "o", "--"),
    ("mumps_factor", "factorisation (MUMPS, Schur)", "tab:purple", "D", ":"),
    ("mumps_condense", "condensation, Schur (MUMPS)", "tab:orange", "^", ":"),
]


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    out = sys.argv[2] if len(sys.argv) > 2 else "condensation.png"
    with open(sys.argv[1], newline="") as f:
        rows = list(csv.DictReader(f))
    scenes = sorted({r["scene"].split()[0] for r in rows})
    fig, axes = plt.subplots(1, len(scenes), figsize=(6 * len(scenes), 4.5),
                             squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        part = sorted((r for r in rows if r["scene"].startswith(scene)),
                      key=lambda r: int(r["n_dofs"]))
        n = [int(r["n_dofs"]) for r in part]
        for key, label, color, marker, style in SERIES:
            if key not in part[0]:
                continue
            ax.loglog(n, [float(r[key]) for r in part], marker=marker,
                      color=color, linestyle=style, label=label)
        for r in part:
            ax.annotate("n_c=" + r["n_contact"],
                        (int(r["n_dofs"]), float(r["schur_condense"])),
                        fontsize=7, textcoords="offset points",
                        xytext=(4, -10))
        ax.set_title(scene)
        ax.set_xlabel("degrees of freedom")
        ax.set_ylabel("wall time [s]")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print("wrote", out)


if __name__ == "__main__":
    main()
