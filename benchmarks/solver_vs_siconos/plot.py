#!/usr/bin/env python3
"""Plot the results of solver_vs_siconos (the CSV it writes) as a PNG.

One panel per problem family (random / indenter, 2D / 3D) and friction
coefficient; in each panel, grouped bars give the wall time of every solver
for every problem size (log scale). dpana's solvers are drawn in blue tones,
Siconos' in orange tones; a solver that did not reach the target residual is
drawn hatched and marked with an x.

Usage: plot.py results.csv [output.png]
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_rows(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        r["n"] = int(r["n"])
        r["mu"] = float(r["mu"])
        r["seconds"] = float(r["seconds"])
        r["reached"] = r["reached"] == "1"
    return rows


def main():
    if len(sys.argv) < 2:
        sys.exit("usage: plot.py results.csv [output.png]")
    rows = read_rows(sys.argv[1])
    output = sys.argv[2] if len(sys.argv) > 2 else "solver_vs_siconos.png"

    families = []
    for r in rows:
        if r["problem"] not in families:
            families.append(r["problem"])
    mus = sorted({r["mu"] for r in rows})

    fig, axes = plt.subplots(
        len(mus), len(families), figsize=(4.2 * len(families), 3.6 * len(mus)),
        squeeze=False)
    dpana_colors = plt.cm.Blues([0.45, 0.6, 0.75, 0.9])
    peer_colors = plt.cm.Oranges([0.4, 0.55, 0.7, 0.85])

    for i, mu in enumerate(mus):
        for j, family in enumerate(families):
            ax = axes[i][j]
            sub = [r for r in rows if r["problem"] == family and r["mu"] == mu]
            sizes = sorted({r["n"] for r in sub})
            solvers = []
            for r in sub:
                if r["solver"] not in solvers:
                    solvers.append(r["solver"])
            width = 0.8 / max(len(solvers), 1)
            n_peer = n_dpana = 0
            for k, solver in enumerate(solvers):
                is_peer = solver.startswith("siconos")
                if is_peer:
                    color = peer_colors[n_peer % len(peer_colors)]
                    n_peer += 1
                else:
                    color = dpana_colors[n_dpana % len(dpana_colors)]
                    n_dpana += 1
                for s, n in enumerate(sizes):
                    match = [r for r in sub
                             if r["solver"] == solver and r["n"] == n]
                    if not match:
                        continue
                    r = match[0]
                    x = s + (k - (len(solvers) - 1) / 2) * width
                    ax.bar(x, r["seconds"], width, color=color,
                           hatch=None if r["reached"] else "//",
                           edgecolor="black" if not r["reached"] else color,
                           label=solver if s == 0 else None)
                    if not r["reached"]:
                        ax.plot(x, r["seconds"], "kx")
            ax.set_yscale("log")
            ax.set_xticks(range(len(sizes)))
            ax.set_xticklabels([f"n={n}" for n in sizes])
            ax.set_title(f"{family}, mu = {mu:g}")
            ax.set_ylabel("time [s]")
            ax.grid(axis="y", which="both", alpha=0.3)
            if i == 0:
                ax.legend(fontsize=6, loc="upper left")
    fig.suptitle("dpana vs Siconos: time to reach the same residual "
                 "(dpana's natural map); hatched/x = target missed")
    fig.tight_layout()
    fig.savefig(output, dpi=120)
    print(f"wrote {output}")


if __name__ == "__main__":
    main()
