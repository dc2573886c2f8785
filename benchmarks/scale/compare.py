#!/usr/bin/env python3
"""Two dpana executables side by side on the same scenes.

    compare.py --before OLD/dpana --after NEW/dpana --out DIR [--repeats N]
               SCENE.prm ...

Runs every scene with the two executables in turn (before, after, before,
after, ...: both see the same load), N times each, and tabulates the
minimum over the repeats of the time of each phase and of the peak memory
from each run's summary.json, with the ratio after / before. Each run is
made in DIR/NAME/{before,after}/ (a generated mesh named by a `# mesh:` line
is made there first). The contact answers of the two are compared as well:
the largest difference of the normal tractions of contact.csv, relative to
their largest value. Writes DIR/compare.md and prints it.
"""
import argparse
import csv
import json
import os
import shutil
import subprocess
import sys

PHASES = ["mesh", "assembly", "factorization", "condensation", "contact solve",
          "recovery", "output"]
MESHES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                      "scripts", "meshes", "make_meshes.py")


def run(dpana, prm, workdir):
    """One run of dpana on prm in workdir: its summary and contact.csv."""
    os.makedirs(workdir, exist_ok=True)
    name = os.path.basename(prm)
    text = open(prm).read()
    open(os.path.join(workdir, name), "w").write(text)
    # A generated mesh is made once, in the scene's folder, and shared by
    # both executables (gmsh's parallel mesher may differ from run to run).
    if "# mesh:" in text:
        scene_dir = os.path.dirname(os.path.abspath(workdir))
        if not os.path.exists(os.path.join(scene_dir, "meshes")):
            shutil.copy(prm, scene_dir)
            subprocess.check_call([sys.executable, MESHES, name],
                                  cwd=scene_dir)
        if not os.path.exists(os.path.join(workdir, "meshes")):
            os.symlink(os.path.join(scene_dir, "meshes"),
                       os.path.join(workdir, "meshes"))
    out = [d for d in os.listdir(workdir) if d.startswith("output")]
    for d in out:
        shutil.rmtree(os.path.join(workdir, d))
    with open(os.path.join(workdir, "log.txt"), "w") as log:
        status = subprocess.call([dpana, name], cwd=workdir, stdout=log,
                                 stderr=subprocess.STDOUT)
    if status != 0:
        sys.exit("compare.py: %s %s exited with %d" % (dpana, prm, status))
    found = subprocess.check_output(["find", workdir, "-name",
                                     "summary.json"]).decode().split()
    summary = json.load(open(found[0]))
    rows = list(csv.DictReader(open(os.path.join(os.path.dirname(found[0]),
                                                 "contact.csv"))))
    return summary, rows


def traction_difference(a, b):
    key = [k for k in a[0] if k.strip().startswith("N")][0]
    na = [float(r[key]) for r in a]
    nb = [float(r[key]) for r in b]
    scale = max(abs(v) for v in na) or 1.0
    return max(abs(x - y) for x, y in zip(na, nb)) / scale


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--before", required=True)
    ap.add_argument("--after", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--repeats", type=int, default=2)
    ap.add_argument("scenes", nargs="+")
    args = ap.parse_args()
    lines = ["| scene | dofs | n_c | " +
             " | ".join("%s before / after [s] (ratio)" % p for p in PHASES)
             + " | peak MB before / after | max dN/N | load |",
             "|---" * (len(PHASES) + 6) + "|"]
    for prm in args.scenes:
        name = os.path.splitext(os.path.basename(prm))[0]
        best = {"before": {}, "after": {}}
        answers = {}
        loads = []
        for _ in range(args.repeats):
            for which in ("before", "after"):
                exe = os.path.abspath(getattr(args, which))
                loads.append(open("/proc/loadavg").read().split()[0])
                s, rows = run(exe, os.path.abspath(prm),
                              os.path.join(args.out, name, which))
                answers[which] = rows
                b = best[which]
                for p in PHASES:
                    t = s["timings"].get(p, 0.0)
                    b[p] = min(b.get(p, t), t)
                peak = max(s["peak_memory_mb"].values())
                b["peak"] = min(b.get("peak", peak), peak)
                b["dofs"] = sum(x["dofs"] for x in s["bodies"])
                b["n_c"] = s["contact"]["contact_elements"] * s["dimension"]
        bb, aa = best["before"], best["after"]
        cells = ["%.3g / %.3g (%.2f)" % (bb[p], aa[p],
                                         aa[p] / bb[p] if bb[p] else 1.0)
                 for p in PHASES]
        lines.append("| %s | %d | %d | %s | %.0f / %.0f | %.1e | %s-%s |" % (
            name, aa["dofs"], aa["n_c"], " | ".join(cells), bb["peak"],
            aa["peak"], traction_difference(answers["before"],
                                             answers["after"]),
            min(loads), max(loads)))
        open(os.path.join(args.out, "compare.md"), "w").write(
            "\n".join(lines) + "\n")
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
