"""Richardson extrapolation of a sequence of mesh levels, and the time
needed to reach a relative error.

A quantity q(h) in the asymptotic range behaves as q(h) = q* + C h^p. Three
levels h1 > h2 > h3 determine q*, C and the observed order p: p solves

    (q1 - q2) / (q2 - q3) = (h1^p - h2^p) / (h2^p - h3^p),

(= r^p for a constant ratio r = h1/h2 = h2/h3), and

    q* = q3 + (q3 - q2) h3^p / (h2^p - h3^p).

The three levels are in the asymptotic range only if the differences keep
their sign and shrink as some order p > 0 allows, and the order agrees with
the one of the previous three levels; extrapolate() says when they do not.
"""

import math


def _ratio(p, h1, h2, h3):
    return (h1 ** p - h2 ** p) / (h2 ** p - h3 ** p)


def observed_order(h, q):
    """Observed order of the three levels (h, q) = ((h1, h2, h3), (q1, q2,
    q3)), or None when no positive order fits: the differences change sign,
    or shrink less than any p > 0 allows (for p -> 0 the ratio of the
    differences tends to log(h1/h2) / log(h2/h3), 1 for a constant ratio
    of h)."""
    d1, d2 = q[0] - q[1], q[1] - q[2]
    lo, hi = 1e-3, 30.0
    if d2 == 0 or d1 / d2 <= _ratio(lo, *h):
        return None
    target = d1 / d2
    if _ratio(hi, *h) < target:
        return hi
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if _ratio(mid, *h) < target:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def extrapolate(h, q):
    """Richardson value of the three finest levels of (h, q), coarse to
    fine. Returns a dict: value, order (None if not asymptotic), order of
    the previous three levels, asymptotic (bool) and note."""
    if len(q) < 3:
        return {"value": q[-1], "order": None, "previous_order": None,
                "asymptotic": False, "note": "fewer than 3 levels"}
    p = observed_order(h[-3:], q[-3:])
    prev = observed_order(h[-4:-1], q[-4:-1]) if len(q) >= 4 else None
    if p is None:
        return {"value": q[-1], "order": None, "previous_order": prev,
                "asymptotic": False,
                "note": "differences of the 3 finest levels change sign or "
                        "grow: finest level taken as the reference"}
    h2p, h3p = h[-2] ** p, h[-1] ** p
    value = q[-1] + (q[-1] - q[-2]) * h3p / (h2p - h3p)
    asymptotic = prev is not None and abs(prev - p) <= 0.5 * p
    note = "" if asymptotic else (
        "order differs from the previous 3 levels: not yet asymptotic"
        if prev is not None else "previous 3 levels oscillate: "
        "not yet asymptotic")
    return {"value": value, "order": p, "previous_order": prev,
            "asymptotic": asymptotic, "note": note}


def relative_errors(values, reference):
    """|v - reference| / |reference|; a quantity whose exact value is 0 is
    itself a relative error."""
    return [abs(v - reference) / abs(reference) if reference else abs(v)
            for v in values]


def time_to_tolerance(times, errors, tol):
    """Time at which the error falls below tol for good: the first level
    from which every finer level stays below tol, interpolated in log-log
    with the level before it. None if the finest level is above tol;
    (t, True) when the coarsest level is already below (an upper bound)."""
    n = len(errors)
    first = n
    for i in reversed(range(n)):
        if errors[i] is not None and errors[i] <= tol:
            first = i
        else:
            break
    if first == n:
        return None
    if first == 0:
        return times[0], True
    e0, e1 = errors[first - 1], errors[first]
    t0, t1 = times[first - 1], times[first]
    if e1 <= 0 or e0 <= 0 or e0 == e1:
        return t1, False
    s = (math.log(tol) - math.log(e0)) / (math.log(e1) - math.log(e0))
    return math.exp(math.log(t0) + s * (math.log(t1) - math.log(t0))), False
