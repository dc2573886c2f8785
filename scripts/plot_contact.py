#!/usr/bin/python3
"""Plot the contact tractions N and T along the candidate contact surface.

Usage: plot_contact.py contact.csv contact.png

The CSV is the one written by a dpana contact run (columns s, N, T or T1, T2,
u_N, u_T, status). In 3D only the first row of contact elements (smallest t,
the symmetry plane of the quarter models) is plotted. N and T are constant
per contact element; they are drawn as steps over each element's extent
estimated from the neighbouring centroids.
"""
import csv
import sys

# Exit status 3 without matplotlib: dpana then warns "no plot" (one python
# start per run instead of a second one to test the import).
NO_MATPLOTLIB = 3
try:
    import matplotlib
except ImportError:
    sys.exit(NO_MATPLOTLIB)

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: plot_contact.py contact.csv contact.png")
    with open(sys.argv[1]) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit("plot_contact.py: no rows in " + sys.argv[1])
    if "t" in rows[0]:
        tmin = min(float(r["t"]) for r in rows)
        rows = [r for r in rows if abs(float(r["t"]) - tmin) < 1e-9 * (1 + abs(tmin))]
    rows.sort(key=lambda r: float(r["s"]))
    s = [float(r["s"]) for r in rows]
    tkey = "T" if "T" in rows[0] else "T1"
    ukey = "u_T" if "u_T" in rows[0] else "u_T1"
    N = [float(r["N"]) for r in rows]
    T = [float(r[tkey]) for r in rows]
    uN = [float(r["u_N"]) for r in rows]
    uT = [float(r[ukey]) for r in rows]
    status = [r["status"] for r in rows]

    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    ax1.step(s, N, where="mid", label="N (normal)")
    ax1.step(s, T, where="mid", label="T (tangential)")
    colours = {"separated": "0.85", "stick": "tab:green", "slip": "tab:orange"}
    for i, st in enumerate(status):
        lo = s[i] - (s[i] - s[i - 1]) / 2 if i > 0 else s[i]
        hi = s[i] + (s[i + 1] - s[i]) / 2 if i + 1 < len(s) else s[i]
        ax1.axvspan(lo, hi, color=colours.get(st, "white"), alpha=0.25, lw=0)
    ax1.set_ylabel("traction (MPa)")
    ax1.legend(title="shaded: green stick, orange slip, grey separated")
    ax1.grid(True, alpha=0.3)
    ax2.plot(s, uN, "o-", ms=3, label="u_N (mean, gap included)")
    ax2.plot(s, uT, "s-", ms=3, label="u_T (mean)")
    ax2.set_xlabel("s (mm) along the contact surface")
    ax2.set_ylabel("displacement (mm)")
    ax2.legend()
    ax2.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=120)


if __name__ == "__main__":
    main()
