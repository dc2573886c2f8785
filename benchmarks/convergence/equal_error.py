"""dpana against GetFEM at equal error, and the tally against the goal.

For one quantity and a relative tolerance, each code's time to bring the
quantity within the tolerance of a common reference
(richardson.time_to_tolerance(): the first level from which every finer
level stays within it, interpolated in log-log with the level before), and
the ratio of the two times, dpana over GetFEM. The goal of the benchmark
is dpana at least 5 times faster: a ratio of GOAL = 0.2 or less.

A code's time to a tolerance is known exactly where a level before the
first one within it exists. Otherwise it is known from one side only:
  - its coarsest level is already within the tolerance: the time is at
    most that level's (a coarser mesh might have done);
  - its finest level is not within it: the time is more than that level's
    (a finer one is needed).
The ratio is then a Bound: "≤" where dpana's time is at most its value or
GetFEM's more than its value, "≥" the other way round. Where both codes'
times are bounded from the same side nothing is known (None when both are
within the tolerance on their coarsest levels, "not reached" when neither
reaches it). An upper bound at or below GOAL meets the goal, a lower bound
above it misses it; the other bounds decide nothing. Counting only the
ratios would leave out cells whose verdict is known: a peer accurate on
its coarsest level is exactly where dpana may fall short, and a peer that
does not reach a tolerance where dpana does is where dpana is ahead.

The cells are also classed by GetFEM's time to the tolerance
(peer_time_class()): what the answer costs the peer, from the
milliseconds of a coarse mesh, where a fresh process's first use of the
code weighs on both timers, to seconds.
"""

import collections
import math
from typing import NamedTuple

import richardson

# The tolerances of the comparison (relative errors).
TOLERANCES = (0.01, 0.005, 0.002, 0.001)
# dpana's time over GetFEM's at equal error that the benchmark aims for.
GOAL = 0.2


class Bound(NamedTuple):
    """A ratio known only from one side: relation "≤" or "≥", value."""
    relation: str
    value: float

    def __str__(self):
        return f"{self.relation} {self.value:.3g}"


def time_to(study_times, reached):
    """A code's time to a tolerance as (t, side): side "=" exact, "≤" at most
    t (within it on the coarsest level), ">" more than t (not within it on
    the finest level, whose time is t); @p reached is the result of
    richardson.time_to_tolerance() on the levels' @p study_times."""
    if reached is None:
        return study_times[-1], ">"
    return reached[0], "≤" if reached[1] else "="


def time_ratio(td, tg):
    """dpana time / GetFEM time from two time_to() results: a float, a
    Bound, None (both within the tolerance on their coarsest levels) or
    "not reached" (neither reaches it)."""
    r = td[0] / tg[0]
    sides = (td[1], tg[1])
    if sides == ("=", "="):
        return r
    if sides == ("≤", "≤"):
        return None
    if sides == (">", ">"):
        return "not reached"
    # dpana's time at most its value, or GetFEM's more than its value: the
    # ratio is at most r; the other way round at least r.
    below = td[1] == "≤" or tg[1] == ">"
    return Bound("≤" if below else "≥", r)


def common_reference(sd, sg):
    """The value both codes are measured against at equal error: the exact
    value, or the mean of their converged values; and the relative distance
    between those."""
    if sd["exact"] is not None:
        return sd["exact"], 0.0
    ref = 0.5 * (sd["reference"] + sg["reference"])
    return ref, abs(sd["reference"] - sg["reference"]) / abs(ref)


def equal_error_cells(sd, sg):
    """Per tolerance, both codes against common_reference(): (time_ratio(),
    GetFEM's time_to()); a tolerance below twice the distance between the
    two converged values is ("not resolved", None)."""
    ref, spread = common_reference(sd, sg)
    out = {}
    for tol in TOLERANCES:
        if tol < 2 * spread:
            out[tol] = ("not resolved", None)
            continue
        td, tg = (time_to(s["times"], richardson.time_to_tolerance(
            s["times"], richardson.relative_errors(s["values"], ref), tol))
            for s in (sd, sg))
        out[tol] = (time_ratio(td, tg), tg)
    return out


def equal_error_ratios(sd, sg):
    """The ratios of equal_error_cells()."""
    return {tol: c[0] for tol, c in equal_error_cells(sd, sg).items()}


def own_limit_ratios(sd, sg):
    """dpana time / GetFEM time at equal discretisation error: each code
    against its own converged value (the studies' times to reach), a
    tolerance that either study does not resolve "not resolved". It
    compares what converging costs where the two limits are too far apart
    for a common reference."""
    return {tol: "not resolved" if "unresolved" in (sd["reach"][tol],
                                                    sg["reach"][tol])
            else time_ratio(time_to(sd["times"], sd["reach"][tol]),
                            time_to(sg["times"], sg["reach"][tol]))
            for tol in TOLERANCES}


# What the answer costs the peer: classes of GetFEM's time to a tolerance,
# split at PEER_TIME_EDGES (s), named by PEER_TIME_LABELS.
PEER_TIME_EDGES = (0.01, 0.1, 1.0)
PEER_TIME_LABELS = ("under 0.01 s", "0.01 to 0.1 s", "0.1 to 1 s",
                    "1 s or more")


def peer_time_class(tg):
    """The index in PEER_TIME_LABELS of GetFEM's time_to() @p tg. A bound
    counts by its value: the coarsest level's time where GetFEM is within
    the tolerance there, the finest level's where it does not reach it."""
    return sum(tg[0] >= e for e in PEER_TIME_EDGES)


def verdict(ratio):
    """"met", "missed" or None (nothing known against GOAL) for one cell."""
    if isinstance(ratio, Bound):
        if ratio.relation == "≤" and ratio.value <= GOAL:
            return "met"
        if ratio.relation == "≥" and ratio.value > GOAL:
            return "missed"
        return None
    if isinstance(ratio, float):
        return "met" if ratio <= GOAL else "missed"
    return None


def tally(cells):
    """Per quantity (and "all") from (quantity, ratio) pairs: the number of
    ratios ("ratios"), how many of them meet GOAL, their geometric mean,
    the bounds that meet or miss it, the cells that decide nothing (a bound
    on the wrong side of GOAL, or both codes on their coarsest levels), and
    those not reached or not resolved."""
    out = collections.OrderedDict()
    for quantity, ratio in cells:
        for key in (quantity, "all"):
            t = out.setdefault(key, {"ratios": [], "bounds met": 0,
                                     "bounds missed": 0, "undecided": 0,
                                     "not reached": 0, "not resolved": 0})
            if isinstance(ratio, float):
                t["ratios"].append(ratio)
            elif isinstance(ratio, str):
                t[ratio] += 1
            else:
                t[{"met": "bounds met", "missed": "bounds missed",
                   None: "undecided"}[verdict(ratio)]] += 1
    out.move_to_end("all")
    for t in out.values():
        r = t.pop("ratios")
        t["ratios"] = len(r)
        t["met"] = sum(v <= GOAL for v in r)
        t["geometric mean"] = math.exp(sum(map(math.log, r)) / len(r)) \
            if r else None
    return out


def tally_table(cells, key="quantity"):
    """Markdown rows of tally(); @p key names what the cells are grouped
    by (the first element of each pair)."""
    md = [f"| {key} | ratios | at 0.2 or below | geometric mean | bounds "
          "that meet the goal (≤ x, x at most 0.2) | bounds that miss it "
          "(≥ x, x above 0.2) | undecided | not reached | not resolved |",
          "|---|---|---|---|---|---|---|---|---|"]
    for q, t in tally(cells).items():
        g = "—" if t["geometric mean"] is None else \
            f"{t['geometric mean']:.3f}"
        md.append(f"| {q} | {t['ratios']} | {t['met']} | {g} | "
                  f"{t['bounds met']} | {t['bounds missed']} | "
                  f"{t['undecided']} | {t['not reached']} | "
                  f"{t['not resolved']} |")
    return md
