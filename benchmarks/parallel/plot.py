#!/usr/bin/env python3
"""The strong-scaling runs of run.sh (results.csv): the time of every phase
(stacked) and the peak resident memory of every rank, for np = 1 and 2 at
each size. Writes parallel.png.

    plot.py results.csv OUT_DIR
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PHASES = ["mesh", "assembly", "contact surface", "factorization", "condensation",
          "contact solve", "recovery", "output"]


def main():
    rows = list(csv.DictReader(open(sys.argv[1])))
    labels = ["%s\nnp=%s" % (r["scene"].replace("receding_", ""), r["np"])
              for r in rows]
    fig, (ax_t, ax_m) = plt.subplots(1, 2, figsize=(12, 4.5))
    bottom = [0.0] * len(rows)
    for p in PHASES:
        values = [float(r["t " + p]) for r in rows]
        ax_t.bar(labels, values, bottom=bottom, label=p)
        bottom = [b + v for b, v in zip(bottom, values)]
    ax_t.set_ylabel("time [s] (rank 0)")
    ax_t.set_title("time per phase")
    ax_t.legend(fontsize=7)
    width = 0.35
    for k in range(2):
        values = []
        for r in rows:
            peaks = r["rank_peaks_mb"].split()
            values.append(float(peaks[k]) if k < len(peaks) else 0.0)
        ax_m.bar([i + (k - 0.5) * width for i in range(len(rows))], values,
                 width, label="rank %d" % k)
    ax_m.set_xticks(range(len(rows)))
    ax_m.set_xticklabels(labels)
    ax_m.set_ylabel("peak resident memory [MB]")
    ax_m.set_title("peak memory per rank")
    ax_m.legend(fontsize=7)
    fig.suptitle("MPI route, receding 3D block (loaded 2-core machine)")
    fig.tight_layout()
    fig.savefig(os.path.join(sys.argv[2], "parallel.png"), dpi=100)


if __name__ == "__main__":
    main()
