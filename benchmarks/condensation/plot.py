#!/usr/bin/env python3
"""Plot the results of condensation_benchmark (the CSV it writes) as a PNG.

One panel per body (2D block, 3D box): wall time against the number of
contact unknowns, log-log, for the CHOLMOD factorisation, the blocked
solves, the one-column-at-a-time solves (open markers where they were
sampled and scaled) and the whole condensation through the Condenser. The
number of degrees of freedom is written next to each condensation point.

Usage: plot.py results.csv [output.png]
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SERIES = [
    ("t_factor", "factorisation", "tab:green", "s"),
    ("t_blocked", "blocked solves", "tab:blue", "o"),
    ("t_single", "one-column solves", "tab:red", "v"),
    ("t_condense", "condensation (Condenser)", "black", "D"),
]


def read_rows(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for key in ("n_dofs", "n_contact", "single_columns"):
            r[key] = int(r[key])
        for key, _, _, _ in SERIES:
            r[key] = float(r[key])
    return rows


def main():
    if len(sys.argv) < 2:
        sys.exit("usage: plot.py results.csv [output.png]")
    rows = read_rows(sys.argv[1])
    output = sys.argv[2] if len(sys.argv) > 2 else "condensation.png"

    problems = []
    for r in rows:
        if r["problem"] not in problems:
            problems.append(r["problem"])
    fig, axes = plt.subplots(1, len(problems),
                             figsize=(5.2 * len(problems), 4.2), squeeze=False)
    for ax, problem in zip(axes[0], problems):
        sub = sorted((r for r in rows if r["problem"] == problem),
                     key=lambda r: r["n_contact"])
        x = [r["n_contact"] for r in sub]
        for key, label, color, marker in SERIES:
            ax.plot(x, [r[key] for r in sub], color=color, marker=marker,
                    label=label)
            if key == "t_single":
                sampled = [r for r in sub
                           if r["single_columns"] < r["n_contact"]]
                if sampled:
                    ax.plot([r["n_contact"] for r in sampled],
                            [r[key] for r in sampled], linestyle="none",
                            marker=marker, markersize=10, markerfacecolor="w",
                            color=color, label="(sampled, scaled)")
        for r in sub:
            ax.annotate(f"{r['n_dofs']} dofs", (r["n_contact"], r["t_condense"]),
                        textcoords="offset points", xytext=(4, 6), fontsize=7)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("contact unknowns (columns of V)")
        ax.set_ylabel("wall time [s]")
        ax.set_title(problem)
        ax.grid(which="both", alpha=0.3)
        ax.legend(fontsize=7, loc="upper left")
    fig.suptitle("dpana: cost of the condensation A = V^T K^-1 V")
    fig.tight_layout()
    fig.savefig(output, dpi=120)
    print(f"wrote {output}")


if __name__ == "__main__":
    main()
