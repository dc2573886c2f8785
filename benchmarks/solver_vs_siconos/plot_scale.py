#!/usr/bin/env python3
"""Plot of scale_results.csv: the processor time of Siconos' FC3D_NSN_AC and
of dpana's default solver (before and after the partition sweeps, and with
the N-step through the separated set) against the contact unknowns, one
line per problem family, log-log.

    plot_scale.py [scale_results.csv] [scale.png]
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
source = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
    here, "scale_results.csv")
target = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "scale.png")
rows = list(csv.DictReader(open(source)))
series = [("siconos_nsn_ac", "Siconos FC3D_NSN_AC", "s"),
          ("dpana_before", "dpana default, before", "v"),
          ("dpana_after", "dpana default, after", "o"),
          ("dpana_separated_set", "dpana default, separated-set N-step", "^")]
styles = {"scale": "-", "receding_3d_L80": "--"}
fig, ax = plt.subplots(figsize=(7, 5))
for family, line in styles.items():
    chosen = [r for r in rows if r["family"] == family]
    for key, label, marker in series:
        points = [(int(r["unknowns"]), float(r[key])) for r in chosen
                  if r.get(key, "") not in ("", "nan")]
        if points:
            x, y = zip(*sorted(points))
            ax.loglog(x, y, line, marker=marker,
                      label="%s (%s)" % (label, family))
ax.set_xlabel("contact unknowns")
ax.set_ylabel("processor time of the solve [s]")
ax.set_title("3D receding block, mu = 1, target residual 1e-8")
ax.grid(True, which="both", alpha=0.3)
ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(target, dpi=120)
print("wrote", target)
