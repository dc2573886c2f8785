"""The quantities of interest of one dpana run, read from its output
directory (summary.json and contact.csv).

Size and cost: degrees of freedom of all bodies, contact unknowns (the
traction components: dim per contact element), the time of every phase
(the solve time is their sum from a mesh in memory to the answers: without
the mesh phase, the generation or reading of the mesh, which GetFEM's
harness does not time either, and without the output phase, which writes
files and plots and does not depend on the method), the peak memory.

Answers, from the tractions of contact.csv (piecewise constant, one value
per contact element of length or area |e|; compressive N < 0, p = -N):
  N_max       the largest p of a contact element (MPa);
  N_first     p of the first contact element (on the symmetry axis);
  resultant   the normal force sum(p |e|) (N/mm in 2D, N in 3D): it must
              equal the load carried by contact, a check of equilibrium;
  a           the contact half width at element resolution (outer edge of
              the last element in contact; summary.json);
  a_m         the moment estimate of the half width, 2 sqrt(int x^2 p /
              int p), exact for the elliptic Hertz law p ~ sqrt(1 - x^2/a^2)
              on [0, a]; each element's integral of x^2 is taken exactly
              over its extent in x (centroid x_c, width w_x: x_c^2 + w_x^2/12);
              in 3D (contact plane x-z) the radius sqrt(5/2 int r^2 p /
              int p) of the Hertz disc: dpana's own (a_moment of the
              Hertz sphere reference in summary.json), which integrates
              r^2 exactly over each element; without that reference, r^2
              at the element centroids (a midpoint rule, low by about
              the elements' second moment about their centroids: 0.05 %
              at 818 elements on the sphere's cap);
  x_p         the centroid of the pressure in x, int x p / int p (in 3D
              the x coordinate of the centroid in the contact plane x-z:
              with the element centroids, exact for piecewise constant p
              on flat elements);
  uniform_error  max |N - N_exact| / |N_exact| for a scene whose exact
              solution is a uniform traction.
"""

import csv
import json
import math
import os

PHASES = ("assembly", "contact surface", "factorization", "condensation",
          "contact solve", "recovery")


def read_contact_csv(path):
    with open(path, newline="") as f:
        return [{k: (v if k == "status" else float(v)) for k, v in row.items()}
                for row in csv.DictReader(f)]


def _x_widths(rows):
    """The extent in x of each 2D contact element: its length times dx/ds,
    the slope of x against the arc length s between its neighbours."""
    widths = []
    for i, r in enumerate(rows):
        lo, hi = rows[max(i - 1, 0)], rows[min(i + 1, len(rows) - 1)]
        ds = hi["s"] - lo["s"]
        slope = abs(hi["x"] - lo["x"]) / ds if ds > 0 else 1.0
        widths.append(r["area"] * slope)
    return widths


def traction_quantities(rows, dim, exact_normal=None):
    p = [-r["N"] for r in rows]
    force = [pi * r["area"] for pi, r in zip(p, rows)]
    q = {"N_max": max(p), "N_first": p[0], "resultant": sum(force)}
    if dim == 2 and q["resultant"] > 0:
        widths = _x_widths(rows)
        m0 = sum(force)
        m1 = sum(f * r["x"] for f, r in zip(force, rows))
        m2 = sum(f * (r["x"] ** 2 + w * w / 12) for f, r, w in
                 zip(force, rows, widths))
        q["x_p"] = m1 / m0
        q["a_m"] = 2 * math.sqrt(m2 / m0)
    if dim == 3 and q["resultant"] > 0:
        # Contact plane x-z (contact direction -y): int r^2 p / int p is
        # 2 a^2 / 5 for the Hertz law p ~ sqrt(1 - r^2/a^2) on a disc.
        m2 = sum(f * (r["x"] ** 2 + r["z"] ** 2) for f, r in zip(force, rows))
        q["a_m"] = math.sqrt(2.5 * m2 / q["resultant"])
        q["x_p"] = sum(f * r["x"] for f, r in zip(force, rows)) \
            / q["resultant"]
    if exact_normal is not None:
        q["uniform_error"] = max(abs(r["N"] - exact_normal) for r in rows) \
            / abs(exact_normal)
    return q


def run_quantities(directory, dim, exact_normal=None):
    """Everything the sweep records of the run in directory."""
    with open(os.path.join(directory, "summary.json")) as f:
        summary = json.load(f)
    contact = summary["contact"]
    timings = summary["timings"]
    record = {
        "dofs": sum(b["dofs"] for b in summary["bodies"]),
        "contact_elements": contact["contact_elements"],
        "contact_unknowns": dim * contact["contact_elements"],
        "converged": contact["converged"],
        "iterations": contact["iterations"],
        "residual": contact["residual"],
        "timings": {k: timings.get(k, 0.0) for k in PHASES},
        "mesh_time": timings.get("mesh", 0.0),
        "solve_time": sum(timings.get(k, 0.0) for k in PHASES),
        "peak_memory_mb": max(summary["peak_memory_mb"].values()),
        "a": contact.get("contact_half_width"),
        "a_element": contact.get("contact_half_width_element"),
        # The processor and BLAS kernels the run reports (runs before
        # 2026-11-29 do not).
        "machine": summary.get("machine"),
    }
    rows = read_contact_csv(os.path.join(directory, "contact.csv"))
    record.update(traction_quantities(rows, dim, exact_normal))
    for ref in contact.get("references", []):
        if ref.get("type") in ("hertz", "hertz sphere"):
            # Plane Hertz: a and N_max; 3D Hertz: the radius a and p0.
            record["hertz"] = {"a": ref["a"], "N_max": ref["N_max"]}
        if ref.get("type") == "hertz sphere" and "a_moment" in ref:
            record["a_m"] = ref["a_moment"]
            # The peak pressure of the elliptic fit (references.h), where
            # the fit exists.
            if "fit_max_pressure" in ref:
                record["p0_fit"] = ref["fit_max_pressure"]
    # contact.csv holds 8 significant digits; the summary holds these two
    # to full precision.
    record["N_max"] = contact["max_normal_traction"]
    record["resultant"] = contact["normal_resultant"]
    return record
