#!/usr/bin/env python3
"""Quick form of the convergence sweeps (a ctest, about a minute).

1. The extrapolation itself: richardson.py recovers q* and p from exact
   sequences q = q* + C h^p, with constant and with varying ratios of h,
   and says "not asymptotic" for an oscillating one; the equal-error
   ratios of analyse.py on two such sequences whose limits lie 1 % apart
   (the same relative errors, ten times the time): against the common
   value every tolerance is "not resolved", each against its own limit
   the ratio is 0.1, and a tolerance neither finest level reaches gives
   "not reached"; the bounds of equal_error.py on sequences with an exact
   value (q = 1 + C h^2, h = 1 ... 1/8, times 10 4^k and 100 4^k, the
   ratios worked out by hand below): a code within a tolerance on its
   coarsest level, or one that never reaches it, bounds the ratio from
   the right side, and the tally counts the bounds that decide the goal;
   GetFEM's time to each tolerance, by which the cells are classed, is
   its levels' time, interpolated, or its bound; analyse.py tells the
   same mesh from another by the dofs level by level.
2. Three coarse levels of the hertz_rigid_mu0_d_shaped family (the
   D-shaped body of prm/hertz_rigid_mu0_d_shaped.prm, 5 contact
   refinements and 0, 1, 2 global
   ones; 1638 to 19150 dofs) against an independent computation of the
   same body: GetFEM (nodal contact, Alart-Curnier, P1 triangles; harness
   getfem/hertz.py --body dshape, on its own gmsh mesh) at its finest
   level of the sitting of 2026-11-30 (history.md, "The 2D families re-run
   with GetFEM's memory"; 95066 dofs, element size 0.061 mm at the
   contact), whose values moved by less than 3e-5 (a_m) and 8e-5 (N_max)
   from the level before: a_m = 8.34183 mm, N_max = 15228.1 MPa. Asserted:
   - every level carries the whole load: resultant = 100000 N/mm to 1e-9;
   - the error of a_m decreases from level to level and is below 0.3 % at
     level 2. Bands: a_m integrates the pressure, whose error concentrates
     in the element at the contact edge, where p ~ sqrt(a - x); one
     element of size h there changes int x^2 p by O(h^(3/2)), so halving h
     should divide the error by about 2^(3/2) = 2.8 once h << a. The
     run of README.md gives 0.57 %, 0.24 %, 0.065 % at levels 0, 1, 2
     (4.3, 8.5, 17 contact elements over the half width); the bound 0.3 %
     leaves a factor 4.6;
   - N_max at level 2 within 0.3 % of N_MAX_REF (the run: 0.10 %; the
     piecewise constant traction of dpana's first element and GetFEM's
     largest nodal pressure both tend to the pressure at the axis).
   The two codes solve the same continuous problem, so their converged
   values agree within their discretisation errors (README.md).
3. The three coarse levels of the hertz_sphere_rigid_nested family (the
   quarter sphere of prm/hertz_sphere_rigid.prm on make_sphere.py
   --level -2 split 0, 1, 2 times; 1908 to 85839 dofs) against the 3D
   Hertz formula a = (3PR/(4E*))^(1/3) = 4.0506 mm. Asserted:
   - every level carries the whole load: resultant = 75000 N to 1e-9;
   - the error of a_m against Hertz decreases from level to level and is
     below 0.5 % at level 2. Band: Hertz assumes a << R; at a/R = 0.1 the
     sphere's own converged a_m lies +0.25 to +0.30 % above it (two nested
     families of README.md, extrapolated), and level 2's discretisation
     error is -0.39 % from that: -0.14 % against Hertz in the run of
     README.md (errors 4.8 %, 0.87 %, 0.14 % at levels 0, 1, 2), inside
     the bound with a margin of 3.5. The levels before the nesting (the
     level family) reach only -0.55 % at 82 536 dofs: the bound also
     fails if the refinement leaves the body under the cap coarse;
   - the peak pressure p0 of the elliptic fit (references.h: the least
     squares fit of p^2 = p0^2 (1 - r^2 / a_f^2) to every pressed
     element) against 3D Hertz, p0 = 3P / (2 pi a^2) = 8730.0 MPa: its
     error decreases from level to level, its observed order lies in the
     band of section 4, and it is below 1 % at level 2. Band: the
     sphere's own p0 lies below Hertz's by about twice the +0.25 to
     +0.30 % by which its a_m lies above (p0 ~ P / a^2 at a fixed load),
     -0.5 to -0.6 %; the run: +11.5 %, +2.7 %, +0.25 % at levels 0, 1, 2
     (order 1.85), and -0.35 % at level 3 (641 547 dofs), below Hertz as
     the limit should be. The largest element pressure N_max would not
     do: on these meshes it grows past Hertz's p0 with refinement
     (+0.23 % at level 2, +0.52 % at level 3) and has no limit yet
     (README.md).

4. A quick sweep of each scene family below: three coarse levels, each
   halving h, of one quantity. Asserted: every level carries the whole
   load (to 1e-9); the error against an independent reference decreases
   from level to level; and the observed order of the three levels,
   p = ln(|q1 - q0| / |q2 - q1|) / ln 2, lies in the band [1, 4].
   The band, from theory: the contact tractions of P1 displacements,
   piecewise constant on groups of faces, converge at the first order in
   h at least; where the pressure is smooth (a peak inside the contact
   zone) an element mean, the value at its centroid to O(h^2), can
   converge at the second order; the pressure integrals (x_p) carry the
   error of the element at the contact edge, where p ~ sqrt(a - x), of
   order h^(3/2). An observed order below 1 would be slower than the
   method; above twice the second order, 4, the levels are not
   converging at a rate the theory gives (errors of two sources
   cancelling by chance). The references: GetFEM's converged values of
   the same families (results/getfem_<family>.json, the sittings of
   README.md "Results of the latest sitting": on the same meshes for the
   blocks and the rigid plane, on its own graded meshes for the elastic
   block), an independent code. The families, levels and the run of
   README.md (errors in %, the observed order):
   - receding_2d_mu1, N_max, h = 5, 2.5, 1.25 (162 to 2178 dofs), GetFEM
     72.48709 MPa: +1.33, +0.19, -0.026; p = 2.4;
   - two_body_ratio_1, x_p, h = 10, 5, 2.5 (212 to 2756 dofs), GetFEM
     20.08167 mm: +0.91, +0.28, +0.055; p = 1.5;
   - hertz_rigid_mu0 (the circular body on the rigid plane), N_max,
     h = 4, 2, 1 (214 to 1652 dofs), GetFEM 14808.33 MPa: -13.5, -1.16,
     +0.031; p = 3.4;
   - hertz_ratio_1_mu0 (on an elastic block of equal modulus), N_max,
     h = 2, 1, 0.5 (1330 to 16346 dofs), GetFEM 10546.74 MPa: -2.49,
     -0.51, -0.15; p = 2.4;
   - hertz_ratio_1e3_mu0 (a rigid punch: the body 1000 times stiffer),
     N_max, h = 2, 1, 0.5, GetFEM 14796.05 MPa: -3.72, -1.36, -0.49;
     p = 1.5;
   - hertz_cavity_mu0 (the circular body in a cavity), a_m, h = 1, 0.5,
     0.25 (3998 to 50166 dofs): the two codes' converged values lie 1 %
     apart here (README.md, "Where the two codes' converged values
     differ": the linearised contact kinematics), so the reference is
     dpana's own converged value, as for a scene without a closed form:
     its finest level of the full sweep, 14.528706 mm (h = 0.0625,
     751 856 dofs; the two levels before 14.530624, 14.530645): -1.06,
     -0.063, +0.013; p = 3.7;
   - hertz_sphere_rigid_nested (3D, section 3's levels), a_m and the
     fitted p0 against 3D Hertz: p = 2.4 and 1.85.
   - receding_3d_L80 (the 3D block, nu = 0, mu = 1), x_p, k = 4, 8, 16
     bricks across (h = 10, 5, 2.5; 225 to 7803 dofs), against the plane
     limit 13.7429 mm (with nu = 0 the plane solution is the 3D one; both
     codes' plane models, families.py): +1.35, +0.32, -0.09; p = 1.3.
     Not N_max: the plane pressure falls steeply just past the stick-slip
     transition at x = 12.5 mm, and the element means of the 3D mesh
     overshoot next to it (84.6 MPa at k = 16 against 83.31 at the
     axis), so its error over these levels is -2.9, +0.17, +1.55 %.
   - the other families, each on the quantity and levels given in
     QUICK_SWEEPS, against GetFEM's converged value (the two spheres
     against 3D Hertz, as the one sphere): the two blocks with
     E1/E2 = 1e-3 (N_max, +1.30, +0.17, +0.042; p = 2.4) and 1e3 (x_p,
     the punch, whose N_max is singular: 0.44, 0.11, 0.013; p = 1.7);
     with friction, the circular body on the rigid plane (a_m, 15.6, 3.7,
     1.15; p = 2.2), on the equal block (N_max, 2.4, 0.51, 0.14;
     p = 2.3), on the soft (a_m, 3.7, 1.1, 0.037; p = 1.2) and on the
     stiff foundation (a_m, 5.5, 1.4, 0.25; p = 1.9); the frictionless
     body on the soft foundation, on the scene's graded block
     (hertz_ratio_1e-3_mu0_graded_block, N_max, 1.03, 0.18, 0.052;
     p = 2.7): on the uniform block (hertz_ratio_1e-3_mu0) its N_max
     errs by -1.18, +0.005, -0.067 % against its finest level, changing
     sign, so no three levels there decrease; the two spheres (a_m, 4.6,
     0.80, 0.11; p = 2.45; 4137 to 187 728 dofs).
   The cavity with friction is checked on its whole traction profile
   (section 6). The frictionless
   receding block (receding_2d_mu0) has no error to decrease: its exact
   uniform state is reproduced to 1e-10 (ContactRun.
   FrictionlessRecedingBlockIsUniform). The checks themselves fail on
   errors that grow and on orders of 0.42 and 9.8
   (check_order_checks()).
5. The circular body against Hertz, mu = 0, rigid plane
   (hertz_rigid_mu0): at the finest level of its quick sweep run to
   h = 0.25 (19350 dofs), N_max and a_m lie within the finite-a/R band.
   Hertz (N_max = 14680.7 MPa, a = 8.67289 mm) is the limit a/R -> 0 of
   a half-space; at a/R = 0.22 the finite body departs from it at the
   order (a/R)^2 = 5 %. The departure of this body is measured by an
   independent computation, GetFEM's converged values on the same meshes
   (N_max 14808.33, +0.87 %; a_m 8.573712, -1.14 %), and the band is that
   departure +-0.3 %: twice and more the discretisation error of the
   level (dpana's sweep: N_max +0.04 %, a_m -0.12 % against its own
   limit). The D-shaped body (+3.7 % in N_max) and Hertz itself lie
   outside it (check_order_checks() asserts that the check fails on
   them).
6. The cavity with friction (hertz_cavity_mu1), levels h = 1, 0.5, 0.25
   (3998 to 50166 dofs): the relative L1 distance of the normal traction
   profile to that of the family's level h = 0.0625 (751 856 dofs, run
   here too); traction_profile.py defines it and derives the band of
   the observed orders, [0.5, 1.5] about the first order. Not a_m or
   N_max: from h = 0.5 on they lie within 0.14 % of the finest level
   and move by less than that without a trend (a_m against the level
   h = 0.0625: -0.97, +0.029, +0.058, +0.028 % at h = 1 ... 0.125), so
   no three levels decrease at an order in the band of section 4. The run: 5.27, 2.05, 1.13 %
   (orders 1.37, 0.86); against the level h = 0.03125 (3.0 million dofs)
   5.25, 2.03, 1.12 %, so the reference's own error moves them by under
   0.02 %. The check fails on distances that grow and on orders of 0.07
   and 2.3 (traction_profile.self_check()).

  check_quick.py --dpana BUILD/dpana --prm-dir prm
"""

import argparse
import json
import math
import os
import sys
import tempfile

import analyse
import equal_error
import families
import records
import richardson
import traction_profile
from sweep import run_level

A_M_REF = 8.34183
A_HERTZ_SPHERE = 4.050638   # (3 P R (1 - nu^2) / (4 E))^(1/3), P = 300 kN
P0_HERTZ_SPHERE = 3 * 300e3 / (2 * math.pi * A_HERTZ_SPHERE ** 2)  # 8730.0
N_MAX_REF = 15228.1
LEVELS = (1.0, 0.5, 0.25)    # h of the levels: 0, 1, 2 global refinements
# The band of observed orders of the quick sweeps (section 4).
ORDER_BAND = (1.0, 4.0)
# The quick sweeps (section 4): family, quantity, the h of its three
# levels, the whole load, the reference (GetFEM's converged value; in the
# cavity dpana's own).
QUICK_SWEEPS = (
    ("receding_2d_mu1", "N_max", (5.0, 2.5, 1.25), 2000.0, 72.48709),
    ("two_body_ratio_1", "x_p", (10.0, 5.0, 2.5), 2000.0, 20.08167),
    ("hertz_rigid_mu0", "N_max", (4.0, 2.0, 1.0), 1e5, 14808.33),
    ("hertz_ratio_1_mu0", "N_max", (2.0, 1.0, 0.5), 1e5, 10546.74),
    ("hertz_ratio_1e3_mu0", "N_max", (2.0, 1.0, 0.5), 1e5, 14796.05),
    ("hertz_cavity_mu0", "a_m", (1.0, 0.5, 0.25), 1e5, 14.528706),
    ("receding_3d_L80", "x_p", (10.0, 5.0, 2.5), 80000.0, 13.7429),
    ("two_body_ratio_1e-3", "N_max", (5.0, 2.5, 1.25), 2000.0, 72.43137),
    ("two_body_ratio_1e3", "x_p", (5.0, 2.5, 1.25), 2000.0, 24.11147),
    ("hertz_rigid_mu1", "a_m", (4.0, 2.0, 1.0), 1e5, 7.794099),
    ("hertz_ratio_1_mu1", "N_max", (2.0, 1.0, 0.5), 1e5, 10547.42),
    ("hertz_ratio_1e-3_mu0_graded_block", "N_max", (2.0, 1.0, 0.5), 1e5,
     14808.31),
    ("hertz_ratio_1e-3_mu1", "a_m", (2.0, 1.0, 0.5), 1e5, 7.801532),
    ("hertz_ratio_1e3_mu1", "a_m", (2.0, 1.0, 0.5), 1e5, 7.644785),
    ("hertz_two_spheres_nested", "a_m", (2.0, 1.0, 0.5), 75000.0,
     A_HERTZ_SPHERE),
)
# Section 6: the cavity with friction, three levels and the reference.
CAVITY_LEVELS, CAVITY_REFERENCE_H = (1.0, 0.5, 0.25), 0.0625
# Section 5: Hertz on the rigid plane, and the circular body's departure
# from it measured by GetFEM: the band is the departure +- 0.3 %.
N_MAX_HERTZ, A_HERTZ = 14680.7, 8.67289
CIRCULAR_BAND = {"N_max": (0.0087 - 0.003, 0.0087 + 0.003),
                 "a_m": (-0.0114 - 0.003, -0.0114 + 0.003)}


def check_richardson(fail):
    for h in ([1, 0.5, 0.25, 0.125], [1.0, 0.6, 0.3, 0.2]):
        for p in (0.5, 1.0, 1.5, 2.0):
            q = [7.0 + 3.0 * x ** p for x in h]
            r = richardson.extrapolate(h, q)
            if abs(r["value"] - 7.0) > 1e-8 or abs(r["order"] - p) > 1e-6 \
                    or not r["asymptotic"]:
                fail(f"richardson: h = {h}, p = {p}: got {r}")
    r = richardson.extrapolate([1, 0.5, 0.25], [1.0, 2.0, 1.5])
    if r["asymptotic"] or r["order"] is not None:
        fail(f"richardson: oscillating sequence taken as asymptotic: {r}")


def check_equal_error(fail):
    h = [1.0, 0.5, 0.25, 0.125]
    levels = [{"h": x, "dofs": 1, "solve_time": 10.0 * 4 ** k,
               "q": 1.0 + 0.08 * x ** 2} for k, x in enumerate(h)]
    peer = [{**r, "solve_time": 10 * r["solve_time"], "q": 1.01 * r["q"]}
            for r in levels]
    sd, sg = (analyse.study({"ok": r}, "q", None) for r in (levels, peer))
    common = analyse.equal_error_ratios(sd, sg)
    if set(common.values()) != {"not resolved"}:
        fail(f"equal error: limits 1 % apart resolved at {common}")
    own = analyse.own_limit_ratios(sd, sg)
    expected = {0.01: 0.1, 0.005: 0.1, 0.002: 0.1, 0.001: "not reached"}
    if any(not same_ratio(own[t], v) for t, v in expected.items()):
        fail(f"equal error: own-limit ratios {own}, expected {expected}")


def same_ratio(got, expected):
    """equal_error's cells: the same kind, and values equal to 1e-9."""
    def close(a, b):
        return abs(a / b - 1) < 1e-9
    if expected is None or isinstance(expected, str):
        return got == expected
    if isinstance(expected, equal_error.Bound):
        return isinstance(got, equal_error.Bound) and \
            got.relation == expected.relation and \
            close(got.value, expected.value)
    return isinstance(got, float) and close(got, expected)


def check_bounds(fail):
    """Errors 0.003 h^2 (times 10 4^k) against 0.08 h^2 (times 100 4^k),
    h = 1, 1/2, 1/4, 1/8, both against the exact value 1. At 1 % the first
    is within on its coarsest level (time at most 10), the second from
    between levels 1 and 2 (errors 0.02 and 0.005, times 400 and 1600: 800
    in log-log): ratio at most 10/800. At 0.2 % the first takes 15
    (between 0.003 and 0.00075: 10 4^(ln(2/3) / ln(1/4))), the second 4000
    (between 0.005 and 0.00125: 1600 4^(ln 0.4 / ln 0.25)): 0.00375. At
    0.1 % the first takes 30 (10 4^(ln 3 / ln 4)), the second never (its
    finest level, at 6400, errs by 0.00125): ratio at most 30/6400.
    Swapped, the same bounds turn into lower ones; both within on their
    coarsest levels decide nothing."""
    h = [1.0, 0.5, 0.25, 0.125]

    def levels(c, t0):
        return [{"h": x, "dofs": 1, "solve_time": t0 * 4 ** k,
                 "q": 1.0 + c * x ** 2} for k, x in enumerate(h)]

    fast, slow = (analyse.study({"ok": levels(c, t0)}, "q", 1.0)
                  for c, t0 in ((0.003, 10.0), (0.08, 100.0)))
    Bound = equal_error.Bound
    cases = [
        ((fast, slow), {0.01: Bound("≤", 10 / 800), 0.002: 15 / 4000,
                        0.001: Bound("≤", 30 / 6400)}),
        ((slow, fast), {0.01: Bound("≥", 80.0), 0.002: 4000 / 15,
                        0.001: Bound("≥", 6400 / 30)}),
        ((fast, fast), {0.01: None})]
    for (sd, sg), expected in cases:
        got = equal_error.equal_error_ratios(sd, sg)
        for tol, v in expected.items():
            if not same_ratio(got[tol], v):
                fail(f"equal error bounds at {tol}: got {got[tol]}, "
                     f"expected {v}")
    # GetFEM's times to the tolerances, from which the cells are classed by
    # what the answer costs the peer: slow at 1 % 800 (above), at 0.5 %
    # 1600 (level 2 errs by 0.005 exactly), at 0.2 % 4000, at 0.1 % more
    # than its finest level's 6400.
    peer = {tol: c[1] for tol, c in
            equal_error.equal_error_cells(fast, slow).items()}
    expected = {0.01: (800.0, "="), 0.005: (1600.0, "="),
                0.002: (4000.0, "="), 0.001: (6400.0, ">")}
    if any(peer[t][1] != v[1] or abs(peer[t][0] / v[0] - 1) > 1e-9
           for t, v in expected.items()):
        fail(f"equal error: GetFEM's times {peer}, expected {expected}")
    classes = [equal_error.peer_time_class(tg) for tg in (
        (0.005, "="), (0.01, "="), (0.099, "≤"), (0.1, "="), (6400.0, ">"))]
    if classes != [0, 1, 1, 2, 3]:
        fail(f"peer time classes {classes}, expected [0, 1, 1, 2, 3]")
    t = equal_error.tally(
        [("q", r) for r in equal_error.equal_error_ratios(fast, slow).values()]
        + [("q", r) for r in equal_error.equal_error_ratios(slow, fast)
           .values()])["all"]
    # fast/slow: <= 0.0125, <= 0.00625 (0.5 %: 10/1600), 0.00375, <= 0.0047;
    # slow/fast: >= 80, >= 160, 267, >= 213.
    if (t["ratios"], t["met"], t["bounds met"], t["bounds missed"]) != \
            (2, 1, 3, 3):
        fail(f"equal error tally: {t}")


def check_mesh_pairing(fail):
    """analyse.mesh_pairing() on records made up here: dofs equal or 1 %
    apart at every common h are the same mesh; one level 3 % apart, or
    three times the dofs, are not; levels of one code alone do not count."""
    def codes(dpana_dofs, getfem_dofs):
        return {"dpana": {"records": [{"h": 2.0 ** -k, "dofs": n}
                                      for k, n in enumerate(dpana_dofs)]},
                "getfem": {"records": [{"h": 2.0 ** -k, "dofs": n}
                                       for k, n in enumerate(getfem_dofs)]}}
    cases = [(([100, 400, 1600], [100, 404, 1600, 6400]), "same mesh"),
             (([100, 400, 1600], [100, 412, 1600]), "dpana's own mesh"),
             (([300, 1200], [100, 400]), "dpana's own mesh")]
    for (d, g), expected in cases:
        got = analyse.mesh_pairing(codes(d, g))[0]
        if got != expected:
            fail(f"mesh pairing of dofs {d} and {g}: {got}, expected "
                 f"{expected}")


def check_a_m(dpana, prm_dir, family, levels, load, a_ref, bound, label,
              fail):
    """Runs the levels of family (run_levels()); fails unless the error of
    a_m against a_ref decreases from level to level and is at most bound
    at the last. Returns the levels' records, or None when a level failed
    to run."""
    runs = run_levels(dpana, prm_dir, family, levels, load, label, fail)
    if runs is None:
        return None
    errors = [abs(r["a_m"] - a_ref) / a_ref for r in runs]
    for level, (r, e) in enumerate(zip(runs, errors)):
        print(f"{label} level {level}: dofs {r['dofs']}, a_m {r['a_m']:.6f} "
              f"(error {e:.2e}), N_max {r['N_max']:.6g}")
    if any(e1 >= e0 for e0, e1 in zip(errors, errors[1:])):
        fail(f"{label} a_m errors do not decrease: {errors}")
    if errors[-1] > bound:
        fail(f"{label} a_m error at level {len(errors) - 1}: "
             f"{errors[-1]:.2e} > {bound:g}")
    return runs


def observed_order(values, ratio=2.0):
    """The order of three levels whose h shrinks by @p ratio each time:
    ln(|q1 - q0| / |q2 - q1|) / ln(ratio); None where a difference is 0."""
    d0, d1 = values[1] - values[0], values[2] - values[1]
    if d0 == 0 or d1 == 0:
        return None
    return math.log(abs(d0 / d1)) / math.log(ratio)


def run_levels(dpana, prm_dir, family, levels, load, label, fail,
               tractions=False):
    """The records of @p levels, (h, edits) pairs of @p family (with
    @p tractions, each with its rows of contact.csv); fails unless each
    carries the whole load (to 1e-9). None when a level failed to run."""
    runs = []
    for level, (h, edits) in enumerate(levels):
        r = run_level(dpana, family, prm_dir, level, h, edits, 300,
                      tractions)
        if "failed" in r:
            fail(f"{label} level {level}: {r['failed']}")
            return None
        if abs(r["resultant"] - load) > 1e-9 * load:
            fail(f"{label} level {level}: resultant {r['resultant']}")
        runs.append(r)
    return runs


def check_decrease_and_order(label, quantity, values, reference, fail,
                             ratio=2.0):
    """Fails unless the relative errors of @p values against @p reference
    decrease and the observed order lies in ORDER_BAND."""
    errors = [abs(v - reference) / abs(reference) for v in values]
    p = observed_order(values, ratio)
    print(f"{label} {quantity}: " + ", ".join(f"{v:.7g}" for v in values) +
          "; errors " + ", ".join(f"{e:.2e}" for e in errors) +
          f"; observed order {p if p is None else round(p, 2)}")
    if any(e1 >= e0 for e0, e1 in zip(errors, errors[1:])):
        fail(f"{label} {quantity}: errors do not decrease: {errors}")
    if p is None or not ORDER_BAND[0] <= p <= ORDER_BAND[1]:
        fail(f"{label} {quantity}: observed order {p} outside "
             f"{ORDER_BAND}")


def check_order_checks(fail):
    """The checks of sections 4 and 5 fail where they should: errors that
    grow, orders of 0.42 and 9.8, Hertz itself and the D-shaped body's
    N_max; and pass a sequence of order 2."""
    def failures(check):
        found = []
        check(found.append)
        return len(found)

    def order(values, reference):
        return failures(lambda f: check_decrease_and_order(
            "self-check", "q", values, reference, f))

    cases = (([1.4, 1.1, 1.025], 1.0, 0), ([1.4, 1.1, 1.025], 1.08, 1),
             ([1.1, 1.06, 1.03], 1.0, 1), ([1.1, 1.01, 1.0099], 1.0, 1))
    for values, reference, expected in cases:
        if order(values, reference) != expected:
            fail(f"order check of {values} against {reference}: not "
                 f"{expected} failure(s)")
    for n_max, a_m, expected in ((N_MAX_HERTZ * 1.009, A_HERTZ * 0.987, 0),
                                 (N_MAX_HERTZ, A_HERTZ * 0.987, 1),
                                 (N_MAX_HERTZ * 1.037, A_HERTZ * 0.987, 1),
                                 (N_MAX_HERTZ * 1.009, A_HERTZ, 1)):
        record = {"h": 0.25, "N_max": n_max, "a_m": a_m}
        if failures(lambda f: check_circular_body(record, f)) != expected:
            fail(f"Hertz band check of {record}: not {expected} "
                 f"failure(s)")


def check_quick_sweeps(dpana, prm_dir, fail):
    """Section 4, and section 5 on the rigid plane's sweep continued to
    h = 0.25."""
    for name, quantity, hs, load, reference in QUICK_SWEEPS:
        family = families.BY_NAME[name]
        more = (0.5, 0.25) if name == "hertz_rigid_mu0" else ()
        levels = [(h, e) for h, e in family.levels if h in hs + more]
        if [h for h, _ in levels] != list(hs + more):
            fail(f"{name}: no levels {hs + more}")
            continue
        runs = run_levels(dpana, prm_dir, family, levels, load, name, fail)
        if runs is None:
            continue
        check_decrease_and_order(name, quantity,
                                 [r[quantity] for r in runs[:3]],
                                 reference, fail)
        if more:
            check_circular_body(runs[-1], fail)


def check_cavity_profile(dpana, prm_dir, fail):
    """Section 6: the cavity with friction, its normal traction profile
    against its own level h = 0.0625."""
    family = families.BY_NAME["hertz_cavity_mu1"]
    hs = CAVITY_LEVELS + (CAVITY_REFERENCE_H,)
    levels = [(h, e) for h, e in family.levels if h in hs]
    if [h for h, _ in levels] != list(hs):
        fail(f"hertz_cavity_mu1: no levels {hs}")
        return
    runs = run_levels(dpana, prm_dir, family, levels, 1e5,
                      "hertz_cavity_mu1", fail, tractions=True)
    if runs is None:
        return
    reference = runs[-1]["tractions"]
    traction_profile.check_distances(
        "hertz_cavity_mu1",
        [traction_profile.l1_distance(r["tractions"], reference)
         for r in runs[:-1]], fail)


def check_circular_body(record, fail):
    """Section 5: N_max and a_m of the finest level against Hertz."""
    for quantity, hertz in (("N_max", N_MAX_HERTZ), ("a_m", A_HERTZ)):
        e = (record[quantity] - hertz) / hertz
        low, high = CIRCULAR_BAND[quantity]
        print(f"circular body, h = {record['h']}: {quantity} "
              f"{record[quantity]:.7g}, {e:+.3%} against Hertz (band "
              f"{low:+.2%} to {high:+.2%})")
        if not low <= e <= high:
            fail(f"circular body {quantity} against Hertz: {e:+.3%} "
                 f"outside {low:+.2%} to {high:+.2%}")


def check_hertz(dpana, prm_dir, fail):
    family = families.BY_NAME["hertz_rigid_mu0_d_shaped"]
    levels = [(h, e) for h, e in family.levels if h in LEVELS]
    runs = check_a_m(dpana, prm_dir, family, levels, 1e5, A_M_REF, 3e-3,
                     "hertz", fail)
    if runs is None:
        return None
    n_error = abs(runs[-1]["N_max"] - N_MAX_REF) / N_MAX_REF
    if n_error > 3e-3:
        fail(f"N_max error at level 2: {n_error:.2e} > 3e-3")
    return runs


def check_results_file(runs, fail):
    """The records of a family through records.write() and analyse.load()."""
    with tempfile.TemporaryDirectory() as out:
        records.write(out, "hertz_rigid_mu0_d_shaped", "dpana", runs,
                      records.load_average())
        with open(os.path.join(out, "hertz_rigid_mu0_d_shaped.json")) as f:
            data = json.load(f)
        if len(data["loadavg"]) != 3 or "blas_kernels" not in data:
            fail(f"results file: load average or BLAS kernels missing: "
                 f"{ {k: v for k, v in data.items() if k != 'records'} }")
        back = analyse.load(out).get(("dpana", "hertz_rigid_mu0_d_shaped"))
        if back is None or back["ok"] != runs:
            fail("results file: the records read back differ from those "
                 "written")


def check_sphere_nested(dpana, prm_dir, fail):
    """a_m against 3D Hertz on the three coarse nested levels."""
    family = families.BY_NAME["hertz_sphere_rigid_nested"]
    runs = check_a_m(dpana, prm_dir, family, family.levels[:3], 75000.0,
                     A_HERTZ_SPHERE, 5e-3, "sphere", fail)
    if runs is None:
        return
    check_decrease_and_order("sphere", "a_m", [r["a_m"] for r in runs],
                             A_HERTZ_SPHERE, fail)
    if any("p0_fit" not in r for r in runs):
        fail("sphere: a level without the elliptic fit's p0")
        return
    p0 = [r["p0_fit"] for r in runs]
    check_decrease_and_order("sphere", "p0 of the elliptic fit", p0,
                             P0_HERTZ_SPHERE, fail)
    error = abs(p0[-1] - P0_HERTZ_SPHERE) / P0_HERTZ_SPHERE
    if error > 1e-2:
        fail(f"sphere: p0 of the elliptic fit at level 2 errs by "
             f"{error:.2e} > 1e-2 against Hertz")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--dpana", required=True)
    parser.add_argument("--prm-dir", required=True)
    args = parser.parse_args()
    failures = []

    def fail(message):
        print("FAIL: " + message)
        failures.append(message)

    check_richardson(fail)
    check_equal_error(fail)
    check_bounds(fail)
    check_mesh_pairing(fail)
    check_order_checks(fail)
    traction_profile.self_check(fail)
    runs = check_hertz(args.dpana, args.prm_dir, fail)
    if runs is not None:
        check_results_file(runs, fail)
    check_sphere_nested(args.dpana, args.prm_dir, fail)
    check_quick_sweeps(args.dpana, args.prm_dir, fail)
    check_cavity_profile(args.dpana, args.prm_dir, fail)
    print("check_quick: " + ("FAILED" if failures else "passed"))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
