"""The distance between two normal traction profiles of a 2D scene, and
the check of a quick sweep on it (check_quick.py, section 6).

A 2D run's contact.csv holds one row per contact element: the arc length
coordinate s of its centroid, its length |e| (column "area") and its
normal traction N, constant over the element. The elements tile the
candidate surface, element e covering [s - |e|/2, s + |e|/2]. The
relative L1 distance of a profile N_h to a reference profile N_ref,

    d(N_h, N_ref) = int |N_h - N_ref| ds / int |N_ref| ds,

is integrated exactly over the union of both profiles' element edges,
each profile 0 beyond its last element.

Why this measure converges at the first order in h: an element's mean
of a pressure p differs from p by about h |p'| over the element, so the
L1 distance of the element means to p is O(h) where p is smooth; at the
contact edge, where p ~ sqrt(a - s), the element that holds the edge and
the uncertainty of the edge's position within it add O(h^(3/2)); the
normal traction is continuous across the stick-slip transition. So
d(h) / d(h/2) tends to 2, an order of 1. The band of the check, [0.5,
1.5], leaves half an order either way for the coarse levels and for the
reference's own error (a level four times finer than the last one
checked). An order below 0.5 would converge slower than the pressure's
own square-root edge allows; above 1.5, faster than element means can
follow a pressure that varies.
"""

import bisect
import math

PROFILE_ORDER_BAND = (0.5, 1.5)


def _pieces(rows):
    """(start, end, N) of each contact element, in order along s."""
    return sorted((r["s"] - r["area"] / 2, r["s"] + r["area"] / 2, r["N"])
                  for r in rows)


def _value(pieces, starts, s):
    i = bisect.bisect_right(starts, s) - 1
    if i < 0 or s >= pieces[i][1]:
        return 0.0
    return pieces[i][2]


def l1_distance(rows, reference):
    """d(N_h, N_ref) of the module docstring; @p rows and @p reference are
    rows of contact.csv (quantities.read_contact_csv())."""
    a, b = _pieces(rows), _pieces(reference)
    starts_a, starts_b = [p[0] for p in a], [p[0] for p in b]
    edges = sorted({e for p in a + b for e in p[:2]})
    distance = norm = 0.0
    for lo, hi in zip(edges, edges[1:]):
        mid = 0.5 * (lo + hi)
        value = _value(b, starts_b, mid)
        distance += abs(_value(a, starts_a, mid) - value) * (hi - lo)
        norm += abs(value) * (hi - lo)
    return distance / norm


def check_distances(label, distances, fail, ratio=2.0):
    """Fails unless @p distances, of levels whose h shrinks by @p ratio,
    decrease and each observed order ln(d_i / d_i+1) / ln(ratio) lies in
    PROFILE_ORDER_BAND."""
    orders = [math.log(d0 / d1) / math.log(ratio) if d0 > 0 and d1 > 0
              else None for d0, d1 in zip(distances, distances[1:])]
    print(f"{label}: L1 distances of the normal traction to the reference "
          + ", ".join(f"{d:.3%}" for d in distances) + "; observed orders "
          + ", ".join("none" if p is None else f"{p:.2f}" for p in orders))
    if any(d1 >= d0 for d0, d1 in zip(distances, distances[1:])):
        fail(f"{label}: the L1 distances do not decrease: {distances}")
    low, high = PROFILE_ORDER_BAND
    if any(p is None or not low <= p <= high for p in orders):
        fail(f"{label}: observed orders {orders} outside {low} to {high}")


def self_check(fail):
    """l1_distance() on profiles worked out by hand, and check_distances()
    failing where it should: distances that grow, orders 0.07 and 2.3."""
    one = [{"s": 1.0, "area": 2.0, "N": -1.0}]
    two = [{"s": 0.5, "area": 1.0, "N": -1.0},
           {"s": 2.0, "area": 2.0, "N": -0.5}]
    # |N| 1 on [0, 2] against 1 on [0, 1] and 0.5 on [1, 3]: the
    # difference is 0.5 on [1, 3], integral 1, over the norm 2 of either;
    # against 0.25 on [0, 4], differences 0.75 on [0, 2] and 0.25 on
    # [2, 4], integral 2, over the norm 1.
    quarter = [{"s": 2.0, "area": 4.0, "N": -0.25}]
    for rows, reference, expected in ((one, one, 0.0), (two, one, 0.5),
                                      (one, two, 0.5),
                                      (one, quarter, 2.0)):
        got = l1_distance(rows, reference)
        if abs(got - expected) > 1e-14:
            fail(f"l1_distance: {got} instead of {expected}")

    def failures(distances):
        found = []
        check_distances("self-check", distances, found.append)
        return len(found)

    for distances, expected in (([0.05, 0.025, 0.0125], 0),
                                ([0.05, 0.02, 0.019], 1),
                                ([0.05, 0.01, 0.002], 1),
                                ([0.01, 0.02, 0.005], 2)):
        if failures(distances) != expected:
            fail(f"check_distances of {distances}: not {expected} "
                 f"failure(s)")
