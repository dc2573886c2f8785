#!/usr/bin/env python3
"""Runs the 3D Hertz scenes on the sphere meshes of several levels and
tabulates, per level, the contact elements (their number and the spread of
their areas), N_max, a_m and the approach against Hertz.

    sphere_levels.py [--dpana PATH] [--levels 0 1 2 3 4] [--scene rigid|two]
                     [--out DIR] [--split]

--scene rigid: prm/hertz_sphere_rigid.prm (quarter sphere on a rigid
plane); two: prm/hertz_two_spheres.prm (two equal quarter spheres). The
meshes are made by scripts/meshes/make_sphere.py --level L (as the scenes'
"# mesh:" lines, with the level replaced) into DIR/meshes, once. Each run's
output directory and log are kept under DIR/runs; the table (markdown) is
printed and written to DIR/sphere_<scene>.md. DIR defaults to
benchmarks/scenes/results.

--split also runs each level under P/8 and splits the measured approach
delta(P) = c1 P^(2/3) + c2 P into Hertz's part (the power 2/3 of his law,
c1 P^(2/3) = 8 delta(P/8) - delta(P)), compared with delta_H = a^2/R, and a
part linear in P (the compression of the bodies away from the contact,
c2 P = 2 (delta(P) - 4 delta(P/8))), compared with minus the Boussinesq
displacement u_B at the centres' depth. Hertz's law is the leading term
for a/R -> 0; the next terms of the approach are linear in P (the far
field of the load), so the split separates the two with what the run
itself measures. Written to DIR/sphere_<scene>_split.md.
"""
import argparse
import json
import os
import re
import shlex
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.abspath(os.path.join(HERE, "..", ".."))
SCENES = {"rigid": "hertz_sphere_rigid.prm", "two": "hertz_two_spheres.prm"}


def scale_load(text, factor):
    """The scene with its concentrated forces and Hertz load times
    `factor`."""
    def forces(m):
        pairs = []
        for pair in m.group(2).split(";"):
            point, force = pair.split(":")
            f = ", ".join("%.10g" % (factor * float(v))
                          for v in force.split(","))
            pairs.append(point + ": " + f)
        return m.group(1) + "; ".join(pairs)
    text = re.sub(r"(set Concentrated forces\s*=\s*)(.*)", forces, text)
    return re.sub(r"(set Hertz load\s*=\s*)(\S+)",
                  lambda m: m.group(1) + "%.10g" % (factor * float(m.group(2))),
                  text)


def leveled_prm(text, level, mesh_dir):
    """The scene with its meshes at `level` (made here) and its output
    directory `output`."""
    out = text
    for line in text.splitlines():
        m = re.match(r"#\s*mesh:\s*(\S+)(.*)$", line)
        if not m:
            continue
        options = shlex.split(m.group(2))
        i = options.index("--level")
        options[i + 1] = str(level)
        name = os.path.basename(m.group(1)).replace("L3", "L%d" % level)
        path = os.path.join(mesh_dir, name)
        subprocess.run(["python3", os.path.join(TOP, "scripts", "meshes",
                                                "make_sphere.py"), path]
                       + options, check=True, stdout=subprocess.DEVNULL)
        out = out.replace("= " + m.group(1), "= " + path)
    return re.sub(r"set Directory\s*=.*", "set Directory = output", out)


def element_areas(csv_path):
    """Smallest and largest contact element area (column 'area')."""
    with open(csv_path) as f:
        header = f.readline().strip().split(",")
        col = header.index("area") if "area" in header else None
        if col is None:
            return None
        areas = [float(line.split(",")[col]) for line in f if line.strip()]
    return min(areas), max(areas)


def run_level(dpana, scene, level, out, factor=1.0):
    run_dir = os.path.join(out, "runs", "sphere_%s_L%d%s" % (
        scene, level, "" if factor == 1 else "_P%g" % factor))
    os.makedirs(run_dir, exist_ok=True)
    text = scale_load(open(os.path.join(TOP, "prm", SCENES[scene])).read(),
                      factor)
    prm = os.path.join(run_dir, "scene.prm")
    with open(prm, "w") as f:
        f.write(leveled_prm(text, level, os.path.join(out, "meshes")))
    start = time.time()
    with open(os.path.join(run_dir, "log"), "w") as log:
        subprocess.run([dpana, "scene.prm"], cwd=run_dir, stdout=log,
                       stderr=subprocess.STDOUT, check=True)
    wall = time.time() - start
    summary = json.load(open(os.path.join(run_dir, "output",
                                          "summary.json")))
    c = summary["contact"]
    ref = [r for r in c["references"] if r["type"] == "hertz sphere"][0]
    areas = element_areas(os.path.join(run_dir, "output", "contact.csv"))
    return {"level": level,
            "dofs": sum(b["dofs"] for b in summary["bodies"]),
            "elements": c["contact_elements"], "areas": areas,
            "N_max": c["max_normal_traction"], "N_err": ref["N_max_error"],
            "a_m": ref["a_moment"], "a_m_err": ref["a_moment_error"],
            "delta": c.get("estimates", {}).get("approach"),
            "delta_err": ref.get("approach_error"),
            "delta_c_err": ref.get("approach_at_centres_error"),
            "delta_H": ref["approach"], "a_H": ref["a"],
            "delta_c": ref.get("approach_at_centres"),
            "p0": ref["N_max"], "wall": wall}


def pct(x):
    return "—" if x is None else "%+.2f %%" % (100 * x)


def table(rows):
    lines = ["| L | dofs | contact elements | area max/min | N_max (MPa) | "
             "N_max − p0 | a_m (mm) | a_m − a | δ (mm) | δ − δ_H | "
             "δ − (δ_H − u_B) | wall (s) |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        spread = "%.2f" % (r["areas"][1] / r["areas"][0]) if r["areas"] \
            else "—"
        delta = "—" if r["delta"] is None else "%.4f" % r["delta"]
        lines.append("| %d | %d | %d | %s | %.0f | %s | %.4f | %s | %s | %s "
                     "| %s | %.1f |" % (
                         r["level"], r["dofs"], r["elements"], spread,
                         r["N_max"], pct(r["N_err"]), r["a_m"],
                         pct(r["a_m_err"]), delta, pct(r["delta_err"]),
                         pct(r["delta_c_err"]), r["wall"]))
    r = rows[0]
    lines.append("")
    lines.append("Hertz: a = %.4f mm, p0 = %.1f MPa, δ_H = %.4f mm." %
                 (r["a_H"], r["p0"], r["delta_H"]))
    return "\n".join(lines)


def split_table(rows, eighths):
    """Hertz's part and the linear part of the approach, from the runs under
    P (rows) and P/8 (eighths)."""
    lines = ["| L | δ(P) (mm) | δ(P/8) (mm) | Hertz part 8δ(P/8) − δ(P) (mm) "
             "| against δ_H | linear part 2(δ(P) − 4δ(P/8)) (mm) | −u_B (mm) |",
             "|---|---|---|---|---|---|---|"]
    for r, e in zip(rows, eighths):
        hertz = 8 * e["delta"] - r["delta"]
        linear = 2 * (r["delta"] - 4 * e["delta"])
        lines.append("| %d | %.4f | %.5f | %.4f | %s | %.4f | %.4f |" % (
            r["level"], r["delta"], e["delta"], hertz,
            pct(hertz / r["delta_H"] - 1), linear,
            r["delta_c"] - r["delta_H"]))
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--dpana", default=os.path.join(
        os.environ.get("DPANA_BUILD_DIR", os.path.join(TOP, "build")),
        "dpana"))
    parser.add_argument("--levels", type=int, nargs="+",
                        default=[0, 1, 2, 3, 4])
    parser.add_argument("--scene", choices=sorted(SCENES), default="rigid")
    parser.add_argument("--out", default=os.path.join(HERE, "results"))
    parser.add_argument("--split", action="store_true")
    args = parser.parse_args()
    if not os.access(args.dpana, os.X_OK):
        sys.exit("sphere_levels.py: error: --dpana %s is not an executable"
                 % args.dpana)
    out = os.path.abspath(args.out)
    rows = []
    for level in args.levels:
        rows.append(run_level(os.path.abspath(args.dpana), args.scene, level,
                              out))
        print("level %d done (%.1f s)" % (level, rows[-1]["wall"]),
              file=sys.stderr)
    text = table(rows)
    with open(os.path.join(out, "sphere_%s.md" % args.scene), "w") as f:
        f.write(text + "\n")
    print(text)
    if args.split:
        eighths = [run_level(os.path.abspath(args.dpana), args.scene, level,
                             out, 0.125) for level in args.levels]
        text = split_table(rows, eighths)
        with open(os.path.join(out, "sphere_%s_split.md" % args.scene),
                  "w") as f:
            f.write(text + "\n")
        print(text)


if __name__ == "__main__":
    main()
