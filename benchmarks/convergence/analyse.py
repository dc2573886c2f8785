#!/usr/bin/env python3
"""Tables and plots of the convergence sweeps in a results directory.

For every family (results/<family>.json, and results/getfem_<family>.json
where the GetFEM harness ran it) and every quantity of the family:
the Richardson-extrapolated value of the three finest levels with its
observed order (richardson.py), the relative error of every level against
the exact value (where the scene has one) or the extrapolated value, and
the time to reach 1 % and 0.1 %. Writes results/convergence.md (the
tables), results/summary.json, results/<family>.png (error against solve
time and against dofs) and results/speed_vs_error.png (every family) and
results/getfem.png (dpana and GetFEM on the same axes, one panel per
family).

  analyse.py RESULTS_DIR
"""

import glob
import itertools
import json
import os
import sys

import equal_error
import families
import richardson
from equal_error import common_reference, equal_error_ratios, \
    own_limit_ratios
from richardson import relative_errors


def load(directory):
    runs = {}
    for path in sorted(glob.glob(os.path.join(directory, "*.json"))):
        with open(path) as f:
            data = json.load(f)
        if isinstance(data, dict) and "records" in data:
            # A level whose solver did not converge carries no answer: it
            # is listed by the sweep (NOT converged) but left out here.
            ok = [r for r in data["records"]
                  if "failed" not in r and r.get("converged", True)]
            runs[(data["code"], data["family"])] = {**data, "ok": ok}
    return runs


def study(run, quantity, exact):
    """Extrapolation, errors and times to tolerance of one quantity."""
    records = [r for r in run["ok"] if r.get(quantity) is not None]
    h = [r["h"] for r in records]
    q = [r[quantity] for r in records]
    extra = richardson.extrapolate(h, q)
    reference = exact if exact is not None else extra["value"]
    errors = relative_errors(q, reference)
    times = [r["solve_time"] for r in records]
    # Without an asymptotic extrapolation the finest level is the reference
    # and the errors are known only down to the difference of the two
    # finest levels: no time is claimed for a tolerance below it.
    floor = 0.0
    if exact is None and extra["order"] is None and len(q) >= 2 and q[-1]:
        floor = abs(q[-1] - q[-2]) / abs(q[-1])
    # The times to reach each relative error of equal_error.TOLERANCES: the
    # tables give 1 % and 0.1 %, the equal-error ratios all four.
    reach = {tol: (richardson.time_to_tolerance(times, errors, tol)
                   if tol >= floor else "unresolved")
             for tol in equal_error.TOLERANCES}
    return {"quantity": quantity, "values": q, "errors": errors,
            "times": times, "dofs": [r["dofs"] for r in records],
            "extrapolated": extra, "exact": exact, "reference": reference,
            "reach": reach}


def fmt_reach(r):
    if r == "unresolved":
        return "not resolved"
    if r is None:
        return "not reached"
    t, bound = r
    return f"≤ {t:.3g}" if bound else f"{t:.3g}"


def fmt(v, digits=6):
    return "—" if v is None else f"{v:.{digits}g}"


def level_table(run, studies):
    qs = [s["quantity"] for s in studies]
    head = ["level", "h", "dofs", "contact unknowns", "iterations",
            "solve (s)", "mesh (s)", "wall (s)", "peak (MB)"]
    for q in qs:
        head += [q, f"error {q}"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for i, r in enumerate(run["ok"]):
        row = [str(r["level"]), f"{r['h']:.4g}", str(r["dofs"]),
               str(r["contact_unknowns"]), str(r.get("iterations", "")),
               f"{r['solve_time']:.3g}",
               f"{r['mesh_time']:.3g}" if "mesh_time" in r else "in solve",
               f"{r.get('wall', 0):.3g}",
               fmt(r.get("peak_memory_mb"), 4)]
        for s in studies:
            e = s["errors"][i] if i < len(s["errors"]) else None
            row += [fmt(s["values"][i] if i < len(s["values"]) else None, 7),
                    "—" if e is None else f"{e:.2e}"]
        lines.append("| " + " | ".join(row) + " |")
    return lines


def quantity_table(rows):
    head = ["quantity", "code", "converged value", "order (3 finest)",
            "order (3 before)", "asymptotic", "Hertz", "time to 1 % (s)",
            "time to 0.1 % (s)"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for code, s, hertz in rows:
        x = s["extrapolated"]
        if s["exact"] is not None:
            value, order, prev, asym = \
                f"{s['exact']:.7g} ({s['label']})", "—", "—", "—"
        else:
            value = fmt(x["value"], 7)
            order, prev = fmt(x["order"], 3), fmt(x["previous_order"], 3)
            asym = "yes" if x["asymptotic"] else "no: " + x["note"]
        h = "—" if hertz is None else \
            f"{hertz:.6g} ({(s['reference'] - hertz) / hertz:+.2%})"
        lines.append("| " + " | ".join([
            s["quantity"], code, value, order, prev, asym, h,
            fmt_reach(s["reach"][0.01]), fmt_reach(s["reach"][0.001])]) + " |")
    return lines


def plot_family(ax_t, ax_d, studies, style, label, colour=None):
    for s in studies:
        pts = [(t, d, e) for t, d, e in zip(s["times"], s["dofs"],
                                             s["errors"]) if e and e > 0]
        if not pts:
            continue
        t, d, e = zip(*pts)
        name = f"{label} {s['quantity']}"
        ax_t.loglog(t, e, style, label=name, color=colour)
        ax_d.loglog(d, e, style, label=name, color=colour)


def decorate(ax_t, ax_d, title):
    for ax, xl in ((ax_t, "solve time (s)"), (ax_d, "degrees of freedom")):
        ax.set_xlabel(xl)
        ax.set_ylabel("relative error")
        ax.axhline(0.01, color="grey", lw=0.5, ls=":")
        ax.axhline(0.001, color="grey", lw=0.5, ls=":")
        ax.grid(True, which="both", lw=0.2)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7)
    ax_t.set_title(title, fontsize=9)


def family_of(name):
    if name in families.BY_NAME:
        return families.BY_NAME[name]
    # GetFEM-only families (the circular body): the quantities of the
    # Hertz scenes.
    return families.Family(name, "—", 2, [], quantities=families.HERTZ_Q,
                           plot=("N_max", "a_m"),
                           exact={"resultant": 100000.0}, hertz=True,
                           note="circular body, force at the far pole "
                                "(GetFEM only)")


def hertz_values(run):
    for r in run["ok"]:
        if "hertz" in r:
            return r["hertz"]
    return None


def mesh_apart(records):
    """Whether the solve times of these records leave the mesh out (the
    records carry mesh_time): sweeps before the mesh was timed apart
    counted it in the solve time, dpana its generation or reading, GetFEM
    its import (2D Hertz: the gmsh meshing itself was never counted)."""
    return all("mesh_time" in r for r in records)


# Level by level, dofs of the two codes within this fraction: the same mesh
# (the graded gmsh meshes of the two codes differ by under 2 %).
SAME_MESH = 0.02


def mesh_pairing(codes):
    """"same mesh" where, at every mesh size h that both codes ran, their
    dofs differ by at most SAME_MESH; otherwise "dpana's own mesh" (its
    scene's mesh against GetFEM's, with the same element size on the
    contact surface and another mesh away from it); with the ratios of the
    dofs, dpana's over GetFEM's, at the common h."""
    d = {round(r["h"], 9): r["dofs"] for r in codes["dpana"]["records"]}
    ratios = [d[round(g["h"], 9)] / g["dofs"]
              for g in codes["getfem"]["records"] if round(g["h"], 9) in d]
    if ratios and all(abs(x - 1) <= SAME_MESH for x in ratios):
        return "same mesh", ratios
    return "dpana's own mesh", ratios


def analyse_runs(runs):
    """Per family (in the order of families.py) and code: the studies of
    its quantities, its records and the scene's Hertz values."""
    order = [f.name for f in families.FAMILIES]
    names = sorted({name for _, name in runs},
                   key=lambda n: order.index(n) if n in order else 99)
    summary = {}
    for name in names:
        fam = family_of(name)
        for code in ("dpana", "getfem"):
            run = runs.get((code, name))
            if run is None or len(run["ok"]) == 0:
                continue
            # The Hertz values of the scene, from either code's records.
            hertz = (hertz_values(run) or hertz_values(
                runs.get(("dpana", name), {"ok": []})) or fam.hertz_values) \
                if fam.hertz else None
            summary.setdefault(name, {})[code] = {
                "studies": [{**study(run, q, fam.exact.get(q)),
                             "label": fam.exact_label.get(q, "exact")}
                            for q in fam.quantities
                            if any(q in r for r in run["ok"])],
                "records": run["ok"], "hertz": hertz}
    return summary


def family_section(name, codes, directory, plt):
    """The tables of one family, and its plot <family>.png."""
    fam = family_of(name)
    md = [f"## {name}", "", f"Scene `prm/{fam.prm}`. {fam.note}", ""]
    rows = []
    fig, (ax_t, ax_d) = plt.subplots(1, 2, figsize=(11, 4.5))
    for code, style in (("dpana", "o-"), ("getfem", "s--")):
        if code not in codes:
            continue
        c = codes[code]
        md += [f"{code}:", ""] + level_table(
            {"ok": c["records"]}, c["studies"]) + [""]
        for s in c["studies"]:
            key = "a" if s["quantity"] == "a_m" else s["quantity"]
            rows.append((code, s, c["hertz"].get(key) if c["hertz"]
                         else None))
        plot_family(ax_t, ax_d, [s for s in c["studies"]
                                 if s["quantity"] in fam.plot], style, code)
    decorate(ax_t, ax_d, name)
    fig.tight_layout()
    fig.savefig(os.path.join(directory, f"{name}.png"), dpi=80)
    plt.close(fig)
    return md + quantity_table(rows) + ["", f"![{name}]({name}.png)", ""]


def plot_all(summary, directory, plt):
    """speed_vs_error.png: the first plotted quantity of every family
    (dpana), unless its errors are round-off."""
    fig, (ax_t, ax_d) = plt.subplots(1, 2, figsize=(12, 5.5))
    # More families than the 20 colours: colours and markers cycle
    # (the pairs repeat only after 40 families).
    colours = itertools.cycle(plt.get_cmap("tab20").colors)
    markers = itertools.cycle(["o-", "s-", "^-", "v-", "D-", "<-", ">-",
                               "p-"])
    for name, codes in summary.items():
        if "dpana" not in codes:
            continue
        first = [s for s in codes["dpana"]["studies"]
                 if s["quantity"] == family_of(name).plot[0]
                 and max(s["errors"]) > 1e-8]
        plot_family(ax_t, ax_d, first, next(markers), name, next(colours))
    decorate(ax_t, ax_d, "dpana: error of the first quantity of each "
             "family (against the extrapolated value)")
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "speed_vs_error.png"), dpi=80)
    plt.close(fig)


def write_summary(summary, directory):
    """summary.json: per family, code and quantity the converged value,
    the observed order and the times to 1 % and 0.1 %."""
    out = {name: {code: {s["quantity"]: {
        "converged": s["reference"], "order": s["extrapolated"]["order"],
        "asymptotic": s["extrapolated"]["asymptotic"],
        "time_1pc": s["reach"][0.01], "time_01pc": s["reach"][0.001]}
        for s in c["studies"]} for code, c in codes.items()}
        for name, codes in summary.items()}
    with open(os.path.join(directory, "summary.json"), "w") as f:
        json.dump(out, f, indent=1)


def main():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    directory = sys.argv[1]
    runs = load(directory)
    summary = analyse_runs(runs)
    loads = sorted({" ".join(r["loadavg"]) for r in runs.values()})
    md = ["# Convergence sweeps: tables of one run", "",
          f"Load average at the start of the sweeps: {'; '.join(loads)}.",
          ""] + overview(summary)
    for name, codes in summary.items():
        md += family_section(name, codes, directory, plt)
    md += both_codes_section(summary) + comparison_section(summary)
    plot_all(summary, directory, plt)
    plot_peer(summary, directory, plt)
    with open(os.path.join(directory, "convergence.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    write_summary(summary, directory)
    print(f"analyse.py: wrote {directory}/convergence.md")


def peer_curves(codes, fam):
    """(quantity, [(study, style, code)], reference) of the plotted
    quantities that GetFEM solves, dpana's study next to GetFEM's where
    both exist; quantities whose errors are round-off are left out."""
    mates = {s["quantity"]: s for s in
             codes.get("dpana", {}).get("studies", [])}
    for sg in codes["getfem"]["studies"]:
        if sg["quantity"] not in fam.plot or max(sg["errors"]) < 1e-8:
            continue
        sd = mates.get(sg["quantity"])
        ref = common_reference(sd, sg)[0] if sd else sg["reference"]
        pairs = [(sg, "s--" if sd else "s:", "GetFEM")]
        if sd:
            pairs.append((sd, "o-", "dpana"))
        yield sg["quantity"], pairs, ref


def plot_peer(summary, directory, plt):
    """getfem.png: one panel per family that GetFEM solves, error against
    solve time, dpana (circles, solid) and GetFEM (squares, dashed; dotted
    without a dpana family) against the common reference; the tables give
    the families that are exact on every level."""
    names = [n for n, c in summary.items() if "getfem" in c and any(
        True for _ in peer_curves(c, family_of(n)))]
    if not names:
        return
    cols = 3
    rows = (len(names) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.4 * rows),
                             squeeze=False)
    for ax, name in zip(axes.flat, names):
        for k, (q, pairs, ref) in enumerate(
                peer_curves(summary[name], family_of(name))):
            for s, style, code in pairs:
                pts = [(t, e) for t, e in zip(
                    s["times"], relative_errors(s["values"], ref)) if e > 0]
                if pts:
                    ax.loglog(*zip(*pts), style, color=f"C{k}",
                              label=f"{code} {q}")
        ax.axhline(0.01, color="grey", lw=0.5, ls=":")
        ax.axhline(0.001, color="grey", lw=0.5, ls=":")
        ax.grid(True, which="both", lw=0.2)
        ax.set_title(name, fontsize=9)
        ax.set_xlabel("solve time (s)", fontsize=8)
        ax.set_ylabel("relative error", fontsize=8)
        ax.legend(fontsize=6)
    for ax in list(axes.flat)[len(names):]:
        ax.axis("off")
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "getfem.png"), dpi=70)
    plt.close(fig)


def overview(summary):
    """One row per family and plotted quantity of dpana."""
    md = ["## Overview (dpana)", "",
          "| family | quantity | converged value | order | asymptotic | "
          "Hertz | time to 1 % (s) | time to 0.1 % (s) | finest level: dofs,"
          " solve (s) |", "|---|---|---|---|---|---|---|---|---|"]
    for name, codes in summary.items():
        if "dpana" not in codes:
            continue
        fam = family_of(name)
        last = codes["dpana"]["records"][-1]
        for s in codes["dpana"]["studies"]:
            if s["quantity"] not in fam.plot:
                continue
            x = s["extrapolated"]
            exact = s["exact"] is not None
            value = f"{s['reference']:.7g}" + (
                f" ({s['label']})" if exact else "")
            hertz = codes["dpana"]["hertz"]
            key = "a" if s["quantity"] == "a_m" else s["quantity"]
            h = f"{(s['reference'] - hertz[key]) / hertz[key]:+.2%}" \
                if hertz and key in hertz else "—"
            md.append("| " + " | ".join([
                name, s["quantity"], value,
                "—" if exact else fmt(x["order"], 3),
                "—" if exact else ("yes" if x["asymptotic"] else "no"), h,
                fmt_reach(s["reach"][0.01]), fmt_reach(s["reach"][0.001]),
                f"{last['dofs']}, {last['solve_time']:.3g}"]) + " |")
    return md + ["", "![speed against error](speed_vs_error.png)", ""]


def converged_cell(s):
    """A study's converged value with its observed order: "value (exact)",
    "value, order p", or "value (finest level)" where the three finest
    levels give no order."""
    if s["exact"] is not None:
        return f"{s['exact']:.7g} ({s['label']})"
    order = s["extrapolated"]["order"]
    return f"{s['reference']:.7g}, " + (
        f"order {order:.2g}" if order is not None else "finest level")


def both_codes_section(summary):
    """Per family and plotted quantity, the two codes side by side: each
    one's converged value and observed order, each one's time to 1 %
    against its own converged value, and the ratio of solve times at equal
    error (1 % and 0.1 %, against the common reference of
    equal_error.common_reference())."""
    md = ["## Per family: both codes", "",
          "Per family and plotted quantity: the converged value of each "
          "code with the observed order of its three finest levels, each "
          "code's time to 1 % of its own converged value, and the ratio of "
          "solve times, dpana / GetFEM, at equal error against the common "
          "reference (the last table's cells at 1 and 0.1 %).", "",
          "| family | quantity | dpana: converged, order | GetFEM: "
          "converged, order | time to 1 %, dpana (s) | time to 1 %, GetFEM "
          "(s) | ratio at 1 % | ratio at 0.1 % |",
          "|---|---|---|---|---|---|---|---|"]
    for name, sd, sg in compared_studies(summary):
        if sd["quantity"] not in family_of(name).plot:
            continue
        ratios = equal_error_ratios(sd, sg)
        md.append("| " + " | ".join([
            name, sd["quantity"], converged_cell(sd), converged_cell(sg),
            fmt_reach(sd["reach"][0.01]), fmt_reach(sg["reach"][0.01]),
            ratio_cell(ratios[0.01]), ratio_cell(ratios[0.001])]) + " |")
    return md + [""]


def compared_studies(summary):
    """(family, dpana's study, GetFEM's study) of every quantity both
    codes report, the resultant left out."""
    for name, codes in summary.items():
        if "getfem" not in codes or "dpana" not in codes:
            continue
        sd_all = {s["quantity"]: s for s in codes["dpana"]["studies"]}
        for sg in codes["getfem"]["studies"]:
            sd = sd_all.get(sg["quantity"])
            if sd is not None and sg["quantity"] != "resultant":
                yield name, sd, sg


def ratio_cell(v):
    """A ratio, a bound ("≤ 0.05"), "not reached", "not resolved", or "—"
    (both codes within the tolerance on their coarsest levels)."""
    if v is None:
        return "—"
    if isinstance(v, (str, equal_error.Bound)):
        return str(v)
    return f"{v:.3g}"


def ratio_cells(ratios):
    return [ratio_cell(v) for v in ratios.values()]


def comparison_kind(name, codes):
    """mesh_pairing(), and whether dpana's contact elements are patches
    around the vertices (families.VERTICES) instead of groups of faces."""
    fam = family_of(name)
    patches = any(e.get(k) == v for _, e in fam.levels
                  for k, v in families.VERTICES.items())
    return mesh_pairing(codes)[0] + (", patches around the vertices"
                                     if patches else "")


def own_mesh_range(summary):
    """"(x to y times GetFEM's dofs, family by family at equal h)" over
    the families where dpana ran its scene's own mesh."""
    r = []
    for codes in summary.values():
        if "getfem" in codes and "dpana" in codes:
            pairing, ratios = mesh_pairing(codes)
            if pairing != "same mesh":
                r += ratios
    return f"({min(r):.2g} to {max(r):.2g} times GetFEM's dofs at equal h)" \
        if r else ""


def comparison_section(summary):
    md = ["## dpana against GetFEM at equal error", "",
          "Ratio of solve times, dpana / GetFEM, at equal relative error "
          "(< 1: dpana faster; both codes measured against the mean of "
          "their converged values, or the exact value; '≤ x': dpana is "
          "within the tolerance on its coarsest level, or GetFEM is not "
          "within it on its finest, so x bounds the ratio from above; "
          "'≥ x': the other way round, x bounds it from below; '—': both "
          "codes are within it on their coarsest levels; 'not reached': "
          "neither is within it on its finest level; 'not resolved': the "
          "two converged values lie too far apart for the tolerance). "
          "Solve time: from a "
          "mesh in memory to the answers, the mesh timed apart for both "
          "codes, both with malloc's huge pages (README, 'The peer'); † a "
          "pair of sweeps from before the mesh was timed apart, whose "
          "solve times count the mesh: dpana's reading of its gmsh file, "
          "GetFEM's import of the same file or its grid, both without huge "
          "pages.",
          "", "| family | quantity | 1 % | 0.5 % | 0.2 % | 0.1 % | "
          "converged dpana | converged GetFEM | difference |",
          "|---|---|---|---|---|---|---|---|---|"]
    apart, cells, by_mesh, by_time = [], [], [], []
    for name, sd, sg in compared_studies(summary):
        both = equal_error.equal_error_cells(sd, sg)
        ratios = {tol: c[0] for tol, c in both.items()}
        cells += [(sg["quantity"], v) for v in ratios.values()]
        by_time += [(equal_error.peer_time_class(tg), v)
                    for v, tg in both.values() if tg is not None]
        by_mesh += [(comparison_kind(name, summary[name]), v)
                    for v in ratios.values()]
        codes = summary[name]
        label = name if all(mesh_apart(codes[c]["records"])
                            for c in ("dpana", "getfem")) else name + " †"
        if "not resolved" in ratios.values():
            apart.append((name, sd, sg))
        diff = (sd["reference"] - sg["reference"]) / sg["reference"] \
            if sg["reference"] else sd["reference"] - sg["reference"]
        md.append("| " + " | ".join(
            [label, sg["quantity"], *ratio_cells(ratios),
             fmt(sd["reference"], 7), fmt(sg["reference"], 7),
             f"{diff:+.2e}"]) + " |")
    md += ["", "The goal, dpana at least 5 times faster at equal error (a "
           "ratio of 0.2 or less), over the cells above, per quantity: the "
           "ratios, and the bounds, which meet the goal where dpana's "
           "coarsest level is within the tolerance and its time is at most "
           "0.2 of GetFEM's, and miss it where GetFEM's coarsest level is "
           "within the tolerance and dpana needs more than 0.2 of that "
           "level's time; the other bounds, and the cells where both codes "
           "are within the tolerance on their coarsest levels, decide "
           "nothing (equal_error.py).", ""] + equal_error.tally_table(cells)
    md += ["", "The same cells by the meshes the two codes ran and by "
           "dpana's contact elements: the same mesh (dofs within 2 % at "
           "every common h), or dpana on its scene's own mesh, with the "
           "same element size on the contact surface as GetFEM's and "
           "another mesh away from it " + own_mesh_range(summary) + "; "
           "groups of faces (the default) or patches around the vertices "
           "(`Contact elements = vertices`).", ""] + \
        equal_error.tally_table(sorted(by_mesh, key=lambda c: c[0]),
                                "meshes, contact elements")
    md += ["", "The same cells by what the answer costs the peer: GetFEM's "
           "time to the tolerance (a bound by its value: the time of "
           "GetFEM's coarsest level where that level is within the "
           "tolerance, of its finest where it does not reach it; the cells "
           "not resolved left out).", ""] + \
        equal_error.tally_table(
            [(equal_error.PEER_TIME_LABELS[k], v)
             for k, v in sorted(by_time, key=lambda c: c[0])],
            "GetFEM's time to the tolerance")
    md += ["", "Where a tolerance is not resolved above (the converged values "
           "of the codes lie too far apart for a common reference), each "
           "code against its own converged value: the ratio of the times in "
           "which each brings its own discretisation error below the "
           "tolerance. It compares the cost of converging, not the answers "
           "(their difference is the last column above); 'not resolved': "
           "below the difference of the two finest levels of a code without "
           "an extrapolated value.", "",
           "| family | quantity | 1 % | 0.5 % | 0.2 % | 0.1 % |",
           "|---|---|---|---|---|---|"]
    md += ["| " + " | ".join([name, sg["quantity"], *ratio_cells(
        own_limit_ratios(sd, sg))]) + " |" for name, sd, sg in apart]
    md += ["", "Solve times level by level (same h: the same mesh for the "
           "receding block; the same element size on the contact surface "
           "for the Hertz bodies, whose meshes differ away from it):", "",
           "| family | h | dofs dpana | dofs GetFEM | solve dpana (s) | "
           "solve GetFEM (s) | dpana / GetFEM |",
           "|---|---|---|---|---|---|---|"]
    for name, codes in summary.items():
        if "getfem" not in codes or "dpana" not in codes:
            continue
        d = {round(r["h"], 9): r for r in codes["dpana"]["records"]}
        for g in codes["getfem"]["records"]:
            r = d.get(round(g["h"], 9))
            if r is None:
                continue
            md.append(f"| {name} | {g['h']:.4g} | {r['dofs']} | {g['dofs']} "
                      f"| {r['solve_time']:.3g} | {g['solve_time']:.3g} | "
                      f"{r['solve_time'] / g['solve_time']:.3g} |")
    return md + ["", "![dpana and GetFEM](getfem.png)", ""]


if __name__ == "__main__":
    main()
