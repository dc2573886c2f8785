"""Tabulate the contact scenes run by benchmarks/scenes/run.sh.

Usage: table.py OUT SCENE...

Reads OUT/runs/output/SCENE/summary.json (and contact.csv) of every scene
and writes OUT/scenes.md (a Markdown table), OUT/scenes.csv and
OUT/hertz.png (the normal tractions of the Hertz scenes, N / N_Hertz
against s / a_Hertz, with the Hertz profile sqrt(1 - x^2)).
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def zones_text(zones):
    short = {"stick": "stick", "slip": "slip", "separated": "sep."}
    return ", ".join(
        "%s %.3g–%.3g" % (short.get(z["status"], z["status"]), z["s_from"], z["s_to"])
        for z in zones
    )


def reference_text(refs):
    """The references of a run and its relative errors against them."""
    texts, errors = [], []
    for v in refs:
        if v["type"] == "uniform":
            texts.append("exact N = %g" % v["N"])
            errors.append("max |ΔN|/|N| %.1e, max |T|/|N| %.1e" % (v["max_N_error"], v["max_T"]))
        elif v["type"] == "hertz":
            texts.append("Hertz a = %.4g, N_max = %.5g" % (v["a"], v["N_max"]))
            text = "Hertz: a %+.1f %%, N_max %+.1f %%" % (100 * v["a_error"],
                                                          100 * v["N_max_error"])
            if "a_moment_error" in v:
                text += ", a_m %+.2f %%" % (100 * v["a_moment_error"])
            if "a_fit_error" in v:
                text += ", a_f %+.2f %%" % (100 * v["a_fit_error"])
            errors.append(text)
        elif v["type"] == "published table":
            texts.append("reference table a = %.4g, N_max = %.5g" % (v["a"], v["N_max"]))
            errors.append("reference table: a %+.1f %%, N_max %+.1f %%"
                          % (100 * v["a_difference"], 100 * v["N_max_difference"]))
        elif v["type"] == "comparison file":
            texts.append("2D run %s" % os.path.basename(os.path.dirname(v["file"])))
            errors.append("max |ΔN|/N_max %.1e, max |ΔT|/N_max %.1e"
                          % (v["max_N_difference"], v["max_T_difference"]))
    if not texts:
        return "—", ""
    return "; ".join(texts), "; ".join(errors)


def hertz_reference(refs):
    for v in refs:
        if v["type"] == "hertz":
            return v
    return None


def cell(text):
    """A Markdown table cell: the pipes of |x| escaped."""
    return str(text).replace("|", "\\|")


def main():
    out = sys.argv[1]
    scenes = sys.argv[2:]
    phases = ["mesh", "assembly", "contact surface", "factorization", "condensation", "contact solve",
              "recovery", "output"]
    rows = []
    for s in scenes:
        path = os.path.join(out, "runs", "output", s, "summary.json")
        if not os.path.exists(path):
            print("table.py: no summary for %s (the run failed?)" % s, file=sys.stderr)
            continue
        with open(path) as f:
            summary = json.load(f)
        # The contact answer, with the sizes of the bodies and the timings
        # of the whole run.
        m = dict(summary["contact"])
        m["dofs"] = [b["dofs"] for b in summary["bodies"]]
        m["timings"] = summary["timings"]
        rows.append((s, m))

    with open(os.path.join(out, "scenes.md"), "w") as md:
        md.write(
            "| scene | dofs | elements | μ | iterations | residual | a (mm) | element at a (mm) "
            "| N_max (MPa) "
            "| zones | reference | error | "
            + " | ".join(p + " (s)" for p in phases)
            + " |\n"
        )
        md.write("|" + "---|" * (12 + len(phases)) + "\n")
        for s, m in rows:
            ref, err = reference_text(m.get("references", []))
            t = m["timings"]
            md.write(
                "| %s | %s | %d | %g | %d%s | %.1e | %.4g | %.2g | %.5g | %s | %s | %s | %s |\n"
                % (
                    s,
                    " + ".join(str(d) for d in m.get("dofs", [])),
                    m["contact_elements"],
                    m["friction_coefficient"],
                    m["iterations"],
                    "" if m["converged"] else " (NOT converged)",
                    m["residual"],
                    m["contact_half_width"],
                    m.get("contact_half_width_element", 0),
                    m["max_normal_traction"],
                    zones_text(m["zones"]),
                    cell(ref),
                    cell(err),
                    " | ".join("%.3g" % t.get(p, 0.0) for p in phases),
                )
            )
    with open(os.path.join(out, "scenes.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(
            ["scene", "dofs", "elements", "mu", "converged", "iterations", "residual",
             "a", "element_at_a", "N_max", "zones", "reference", "error"] + phases
        )
        for s, m in rows:
            ref, err = reference_text(m.get("references", []))
            w.writerow(
                [s, " + ".join(str(d) for d in m.get("dofs", [])), m["contact_elements"],
                 m["friction_coefficient"], m["converged"], m["iterations"], m["residual"],
                 m["contact_half_width"], m.get("contact_half_width_element", 0),
                 m["max_normal_traction"], zones_text(m["zones"]),
                 ref, err] + [m["timings"].get(p, 0.0) for p in phases]
            )

    # The Hertz scenes: normalised tractions against the Hertz profile.
    fig, ax = plt.subplots(figsize=(8, 5))
    x = [i / 200 for i in range(201)]
    ax.plot(x, [(1 - v * v) ** 0.5 for v in x], "k-", lw=2, label="Hertz")
    for s, m in rows:
        ref = hertz_reference(m.get("references", []))
        if not ref:
            continue
        with open(os.path.join(out, "runs", "output", s, "contact.csv")) as f:
            data = list(csv.DictReader(f))
        sx = [float(r["s"]) / ref["a"] for r in data]
        n = [-float(r["N"]) / ref["N_max"] for r in data]
        ax.step(sx, n, where="mid", ls="-" if m["friction_coefficient"] == 0 else "--",
                label=s)
    ax.set_xlim(0, 1.4)
    ax.set_xlabel("s / a (Hertz)")
    ax.set_ylabel("-N / N_max (Hertz)")
    ax.set_title("Hertz scenes: contact pressure (element means) against Hertz")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "hertz.png"), dpi=120)
    print(open(os.path.join(out, "scenes.md")).read())


if __name__ == "__main__":
    main()
