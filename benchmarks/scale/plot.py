#!/usr/bin/env python3
"""Log-log plots of the scale runs (results.csv of scale.py): the time and
the peak memory of every phase against the dofs and against the contact
unknowns, one line a phase, with the exponent of a least-squares fit
t ~ n^p over the runs of each scene (phases under 0.05 s left out of the
fit). Writes scale.png and exponents.md next to results.csv.

    plot.py results.csv
"""
import csv
import math
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PHASES = ["mesh", "assembly", "contact surface", "factorization", "condensation",
          "contact solve", "recovery", "output"]


def fit(xs, ys):
    pts = [(math.log(x), math.log(y)) for x, y in zip(xs, ys)
           if x > 0 and y > 0.05]
    if len(pts) < 2:
        return float("nan")
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    if sxx == 0:
        return float("nan")
    return sum((p[0] - mx) * (p[1] - my) for p in pts) / sxx


def main():
    path = sys.argv[1]
    rows = [r for r in csv.DictReader(open(path)) if r.get("n_dofs")]
    scenes = defaultdict(list)
    for r in rows:
        scenes[r["scene"].split()[0]].append(r)
    out = os.path.dirname(os.path.abspath(path))
    fig, axes = plt.subplots(2, 2, figsize=(12, 9))
    lines = ["| scene | quantity | against | " + " | ".join(PHASES) +
             " | total |", "|---" * (len(PHASES) + 4) + "|"]
    for scene, rs in scenes.items():
        rs.sort(key=lambda r: float(r["n_dofs"]))
        for col, (xkey, xname) in enumerate([("n_dofs", "dofs"),
                                             ("n_c", "contact unknowns")]):
            xs = [float(r[xkey]) for r in rs]
            for row, (prefix, yname) in enumerate([("t ", "time [s]"),
                                                   ("mb ", "peak memory [MB]")]):
                ax = axes[row][col]
                exps = []
                for p in PHASES:
                    ys = [float(r[prefix + p]) for r in rs]
                    e = fit(xs, ys)
                    exps.append(e)
                    if prefix == "mb " and p not in ("factorization",
                                                     "condensation",
                                                     "contact solve"):
                        continue
                    ax.loglog(xs, ys, "o-",
                              label="%s %s (p = %.2f)" % (scene, p, e))
                total = [float(r["total"] if prefix == "t " else r["peak_mb"])
                         for r in rs]
                et = fit(xs, total)
                ax.loglog(xs, total, "k--",
                          label="%s %s (p = %.2f)" % (
                              scene, "total" if prefix == "t " else "peak",
                              et))
                ax.set_xlabel(xname)
                ax.set_ylabel(yname)
                ax.grid(True, which="both", alpha=0.3)
                ax.legend(fontsize=7)
                lines.append("| %s | %s | %s | " % (
                    scene, "time" if prefix == "t " else "memory", xname) +
                    " | ".join("%.2f" % e for e in exps) + " | %.2f |" % et)
    fig.suptitle("dpana 3D scale runs: time and peak memory per phase, "
                 "log-log, fitted exponents p (t ~ n^p)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "scale.png"), dpi=110)
    open(os.path.join(out, "exponents.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
