#!/usr/bin/env python3
"""Whole dpana runs of the 3D scale scenes at growing sizes.

For each size the driver writes the scene (a .prm of prm/scale/ with its mesh
entries changed), runs `dpana` on it as a user would, and reads the run's
summary.json: the time and peak resident memory of every phase, the memory
estimate made before the factorisation, the dofs, the contact unknowns,
n_Gamma, and the machine the run reports (processor, OpenBLAS kernels). It
writes results.csv (one row a run) and results.md (the table, then the
machine).

    scale.py --dpana build/dpana --prm-dir prm --out DIR [--sizes quick|default|full]
             [--scenes receding,hertz_sphere] [--size M,H ...]

Scenes:
  receding      prm/scale/receding_3d_1M.prm: m x h x m subdivisions of the
                block, one contact element per square of the contact face
                (n_c = 3 m^2, n_Gamma about 3 (m+1)^2);
  hertz_sphere  prm/hertz_sphere_rigid.prm if present: the sphere on a
                rigid plane, its gmsh mesh at levels 2..4 (--full: ..5),
                made by scripts/meshes/make_meshes.py in the run's folder;
                skipped with a note otherwise;
  layer         prm/scale/receding_layer_1M.prm: the 2 mm layer pressed
                onto a rigid foundation over a square, n x h x n bricks
                (cells of 40/n mm across, h = 8n/200 layers), the candidate
                square |x|, |z| <= 11.6 mm of the bottom one contact
                element per square: n = 40, 80 (--quick), .. 160 (default),
                .. 200 (--full: 1.09 million unknowns, 10 092 contact
                unknowns), or the n of --bricks;
  sphere_scale  prm/scale/hertz_sphere_scale.prm: the same sphere on the
                graded meshes of the scale family, levels 0, 2 (--quick),
                .. 4 (default), .. 6 (--full: 1.16 million unknowns, about
                10^4 contact unknowns), or the levels of --level.

--contact-iterations N ends the contact solve after N outer iterations
(Contact / Maximum iterations = N, Fallback = false, Allow non-converged =
true): the run then times the condensation side (factorisation,
condensation, recovery, output) at full size without waiting for a contact
solve that does not yet scale; its row says converged = False.
"""
import argparse
import csv
import json
import os
import re
import resource
import subprocess
import sys
import time

# (m, h): m x m squares on the contact face, h layers over the height.
RECEDING_SIZES = {
    "quick": [(8, 16), (12, 24)],
    "default": [(12, 24), (16, 40), (24, 56), (36, 76)],
    "full": [(12, 24), (16, 40), (24, 56), (36, 76), (46, 86), (58, 96)],
}
PHASES = ["mesh", "assembly", "contact surface", "factorization", "condensation",
          "contact solve", "recovery", "output"]


def receding_cases(prm_dir, sizes, chosen=None):
    template = os.path.join(prm_dir, "scale", "receding_3d_1M.prm")
    text = open(template).read()
    for m, h in chosen or RECEDING_SIZES[sizes]:
        label = "receding %dx%dx%d" % (m, h, m)
        body = re.sub(r"set Subdivisions\s*=.*",
                      "set Subdivisions = %d, %d, %d" % (m, h, m), text)
        yield label, body


def layer_cases(prm_dir, sizes, chosen=None):
    """The layer of prm/scale/receding_layer_1M.prm with n x h x n bricks:
    the physical scene stays (2 mm layer, 4 mm patch, candidate square of
    11.6 mm), the mesh is refined across and through the thickness
    together."""
    text = open(os.path.join(prm_dir, "scale",
                             "receding_layer_1M.prm")).read()
    bricks = {"quick": [40, 80], "default": [40, 80, 120, 160],
              "full": [40, 80, 120, 160, 200]}
    for n in chosen or bricks[sizes]:
        h = max(2, int(round(8 * n / 200.)))
        body = re.sub(r"set Subdivisions\s*=.*",
                      "set Subdivisions          = %d, %d, %d" % (n, h, n),
                      text)
        yield "layer %dx%dx%d" % (n, h, n), body


def sphere_cases(prm_dir, sizes, chosen=None):
    """The 3D sphere on a rigid plane, prm/hertz_sphere_rigid.prm, at
    several levels of its gmsh mesh: its `# mesh: meshes/NAME.msh --level N`
    line and its `Mesh file` are set to the level, and run_case() has the
    mesh made by scripts/meshes/make_meshes.py before the run."""
    scene = os.path.join(prm_dir, "hertz_sphere_rigid.prm")
    if not os.path.exists(scene):
        print("scale.py: no prm/hertz_sphere_rigid.prm: sphere scene skipped")
        return
    text = open(scene).read()
    if not re.search(r"^#\s*mesh:", text, re.M):
        print("scale.py: %s has no '# mesh:' line: skipped" % scene)
        return
    levels = {"quick": [2, 3], "default": [2, 3, 4], "full": [2, 3, 4, 5]}
    for level in levels[sizes]:
        mesh = "meshes/hertz_sphere_L%d.msh" % level
        body = re.sub(r"^#\s*mesh:.*$", "# mesh: %s --level %d" % (mesh, level),
                      text, flags=re.M)
        body = re.sub(r"set Mesh file\s*=.*", "set Mesh file = " + mesh, body)
        yield "hertz_sphere level %d" % level, body


def sphere_scale_cases(prm_dir, sizes, chosen=None):
    """The graded sphere of prm/scale/hertz_sphere_scale.prm at the levels
    of its family: the level is set in its `# mesh:` line and its `Mesh
    file`, and run_case() has the mesh made in the run's folder."""
    text = open(os.path.join(prm_dir, "scale", "hertz_sphere_scale.prm")).read()
    levels = {"quick": [0, 2], "default": [0, 2, 4], "full": [0, 2, 4, 6]}
    for level in chosen or levels[sizes]:
        mesh = "meshes/hertz_sphere_scale_L%d.msh" % level
        body = re.sub(r"^(#\s*mesh:\s*)\S+(.*--level )\d+",
                      r"\g<1>%s\g<2>%d" % (mesh, level), text, flags=re.M)
        body = re.sub(r"set Mesh file\s*=.*", "set Mesh file = " + mesh, body)
        yield "sphere scale level %d" % level, body


def limit_contact_solve(text, iterations):
    """The scene with its contact solve ended after @p iterations outer
    iterations, not converged but allowed to finish."""
    return re.sub(r"^subsection Contact\s*$",
                  "subsection Contact\n"
                  "  set Maximum iterations = %d\n"
                  "  set Fallback = false\n"
                  "  set Allow non-converged = true" % iterations,
                  text, count=1, flags=re.M)


def loadavg():
    return open("/proc/loadavg").read().split()[0]


def run_case(dpana, label, text, out):
    name = re.sub(r"[^A-Za-z0-9]+", "_", label).strip("_")
    workdir = os.path.join(out, "runs", name)
    os.makedirs(workdir, exist_ok=True)
    text = re.sub(r"set Directory\s*=.*", "set Directory = output", text)
    prm = os.path.join(workdir, name + ".prm")
    open(prm, "w").write(text)
    # Generated meshes ("# mesh:" lines) are made in the run's folder.
    make_meshes = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                               "..", "..", "scripts", "meshes",
                               "make_meshes.py")
    if re.search(r"^#\s*mesh:", text, re.M) and os.path.exists(make_meshes):
        subprocess.check_call([sys.executable, make_meshes, name + ".prm"],
                              cwd=workdir)
    load_before = loadavg()
    start = time.time()
    cpu_start = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(os.path.join(workdir, "log.txt"), "w") as log:
        status = subprocess.call([dpana, name + ".prm"], cwd=workdir,
                                 stdout=log, stderr=subprocess.STDOUT)
    wall = time.time() - start
    cpu_end = resource.getrusage(resource.RUSAGE_CHILDREN)
    # The processor time of the run (all its threads): on a machine shared
    # with other jobs the wall times of the phases include the waits for a
    # core, the processor time does not.
    cpu = (cpu_end.ru_utime - cpu_start.ru_utime +
           cpu_end.ru_stime - cpu_start.ru_stime)
    row = {"scene": label, "status": status, "wall": wall, "cpu": cpu,
           "load_before": load_before, "load_after": loadavg()}
    summary = os.path.join(workdir, "output", "summary.json")
    if status != 0 or not os.path.exists(summary):
        print("scale.py: %s: dpana exited with %d (see %s/log.txt)"
              % (label, status, workdir))
        return row
    s = json.load(open(summary))
    row["n_dofs"] = sum(b["dofs"] for b in s["bodies"])
    row["n_c"] = s["contact"]["contact_elements"] * s["dimension"]
    est = s.get("memory_estimate_mb", [])
    row["n_gamma"] = sum(e["n_gamma"] for e in est)
    row["estimate_mb"] = max([e["total"] for e in est] or [0])
    row["converged"] = s["contact"]["converged"]
    row["iterations"] = s["contact"]["iterations"]
    for p in PHASES:
        row["t " + p] = s["timings"].get(p, 0.0)
        row["mb " + p] = s["peak_memory_mb"].get(p, 0.0)
    row["peak_mb"] = max(s["peak_memory_mb"].values())
    # What the times depend on besides the scene (summary.json's machine,
    # since 2026-11-29): the processor and the BLAS kernels.
    machine = s.get("machine") or {}
    row["processor"] = machine.get("processor")
    row["blas_kernels"] = machine.get("blas_kernels")
    row["total"] = sum(s["timings"].values())
    return row


def write_outputs(rows, out):
    keys = []
    for r in rows:
        keys += [k for k in r if k not in keys]
    with open(os.path.join(out, "results.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)
    short = {"mesh": "mesh", "assembly": "assembly", "contact surface": "surface",
             "factorization": "factor", "condensation": "condense",
             "contact solve": "solve", "recovery": "recovery",
             "output": "output"}
    lines = ["| scene | dofs | n_c | n_Γ | " +
             " | ".join(short[p] + " [s]" for p in PHASES) +
             " | total [s] | CPU [s] | peak [MB] | estimate [MB] | load |",
             "|---" * (len(PHASES) + 9) + "|"]
    for r in rows:
        if "n_dofs" not in r:
            lines.append("| %s | failed (status %d) |" % (r["scene"],
                                                            r["status"]))
            continue
        lines.append(
            "| %s | %d | %d | %d | " % (r["scene"], r["n_dofs"], r["n_c"],
                                        r["n_gamma"]) +
            " | ".join("%.3g" % r["t " + p] for p in PHASES) +
            " | %.4g | %.4g | %.0f | %.0f | %s-%s |" % (
                r["total"], r["cpu"], r["peak_mb"], r["estimate_mb"],
                r["load_before"], r["load_after"]))
    machines = sorted({"%s, OpenBLAS %s kernels" % (r["processor"],
                                                    r["blas_kernels"])
                       for r in rows if r.get("processor")})
    lines += [""] + ["Machine: " + m for m in machines]
    open(os.path.join(out, "results.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--dpana", required=True)
    ap.add_argument("--prm-dir", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--sizes", default="default",
                    choices=sorted(RECEDING_SIZES))
    ap.add_argument("--scenes", default="receding,hertz_sphere")
    ap.add_argument("--size", action="append", default=[],
                    help="M,H: run the receding block at these subdivisions "
                    "only (repeatable)")
    ap.add_argument("--level", action="append", type=int, default=[],
                    help="run the sphere scale family at this level only "
                    "(repeatable)")
    ap.add_argument("--bricks", action="append", type=int, default=[],
                    help="run the layer at n x h x n bricks for this n only "
                    "(repeatable)")
    ap.add_argument("--contact-iterations", type=int, default=0,
                    help="end the contact solve after this many outer "
                    "iterations (0: solve to convergence)")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    dpana = os.path.abspath(args.dpana)
    generators = {"receding": receding_cases, "hertz_sphere": sphere_cases,
                  "sphere_scale": sphere_scale_cases, "layer": layer_cases}
    rows = []
    for scene in args.scenes.split(","):
        if scene not in generators:
            sys.exit("scale.py: error: unknown scene '%s' (--scenes)" % scene)
        chosen = [tuple(int(v) for v in x.split(",")) for x in args.size]
        if scene == "sphere_scale":
            chosen = args.level
        if scene == "layer":
            chosen = args.bricks
        for label, text in generators[scene](args.prm_dir, args.sizes,
                                             chosen):
            if args.contact_iterations > 0:
                text = limit_contact_solve(text, args.contact_iterations)
            print("scale.py: running %s ..." % label, flush=True)
            rows.append(run_case(dpana, label, text, args.out))
            write_outputs(rows, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
