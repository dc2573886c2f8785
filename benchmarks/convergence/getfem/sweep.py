#!/usr/bin/env python3
"""Runs the GetFEM harness over its refinement levels, one process per
level, and writes results/getfem_<family>.json in the record format of the
dpana sweep (code "getfem").

Families (each compared with the dpana family of the same name,
families.py):
  hertz_rigid_mu0_graded    hertz.py --body circle (the circular body on
                            gmsh's graded mesh, which dpana's graded family
                            reads too)
  hertz_rigid_mu0, hertz_rigid_mu1, hertz_rigid_mu0_r10
                            hertz.py --body circle [--mu 1] --mesh: the
                            circular body on dpana's own level meshes (the
                            right half disc with contact refinements within
                            14 mm, or 10 mm for _r10), which dpana writes
                            for each level first (ON_DPANA_MESH; needs
                            --dpana)
  hertz_rigid_mu0_d_shaped  hertz.py --body dshape --mesh (the quarter
                            disc below the centre, on dpana's level meshes)
  receding_2d_mu0           receding.py
  receding_2d_mu1           receding.py --mu 1
  two_body_ratio_1, _1e-3, _1e3
                            two_body.py --ratio 1, 1e-3, 1e3 (the block on
                            the elastic foundation, mu = 1)
  hertz_ratio_1_mu0_graded_block
                            hertz.py --body circle --ratio 1 (the circular
                            body on the elastic block, equal moduli; gmsh's
                            meshes of both bodies, which dpana reads too)
  hertz_ratio_1e-3_mu0_graded_block, hertz_ratio_1e3_mu0_graded_block
                            hertz.py --body circle --ratio 1e-3, 1e3 (the
                            body on a block 1000 times stiffer, softer)
  hertz_rigid_mu1_graded, hertz_ratio_*_mu1_graded_block
                            the same with --mu 1 (Coulomb friction)
  hertz_cavity_mu0_graded, hertz_cavity_mu1_graded
                            hertz.py --body circle --cavity [--mu 1] (the
                            circular body in the cavity R = 120 mm, on
                            gmsh's meshes, which dpana reads too)
  hertz_ratio_*_mu0, hertz_ratio_*_mu1, hertz_ratio_1_mu0_graded,
  hertz_cavity_mu0, hertz_cavity_mu1
                            the same sweeps (paired with dpana's scene
                            meshes: on those GetFEM's nodal contact between
                            non-matching meshes gives an N_max that does not
                            converge, history.md)
  hertz_rigid_*_vertices, hertz_sphere_rigid_vertices,
  hertz_two_spheres_vertices
                            the same as the family without _vertices
                            (paired with dpana's patches around the
                            vertices)
  receding_3d_L80           receding_3d.py (mu = 1, nu = 0)
  hertz_sphere_rigid        sphere.py (the quarter sphere on the rigid plane)
  hertz_sphere_rigid_nested sphere.py --nested -2 (the same on the nested
                            meshes: level k = make_sphere.py --level -2
                            --refine k)
  hertz_sphere_rigid_nested3
                            sphere.py --nested -3 (level -3 split k times;
                            k = 3, 420 543 dofs, with --full)
  hertz_two_spheres, hertz_two_spheres_mu03
                            sphere.py --two [--mu 0.3] (two equal spheres)
  hertz_two_spheres_nested  sphere.py --two --nested -2 (the same on nested
                            meshes)

  sweep.py --out results [--full] [--repeat N] [--dpana BUILD/dpana]
           [FAMILY ...]
"""

import importlib.util
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
import families as dpana_families  # noqa: E402  (benchmarks/convergence/)
import prm_edit  # noqa: E402
import records as records_io  # noqa: E402

# dpana's sweep.py, by its path: this file has the same module name.
_spec = importlib.util.spec_from_file_location(
    "dpana_sweep", os.path.join(os.path.dirname(HERE), "sweep.py"))
dpana_sweep = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(dpana_sweep)

PRM_DIR = os.path.join(HERE, "..", "..", "..", "prm")


def circle_on_block(ratio, *options):
    """The circular body on the elastic block, E1/E2 = ratio, from level -1
    as dpana's level meshes and its graded disc and block (families.py): on
    level 0 both codes are often within 1 % already."""
    return (["hertz.py", "--body", "circle", "--ratio", ratio, *options],
            range(-1, 4), [4])


# family: (script arguments, default levels, extra levels of --full).
# The default levels stop where a GetFEM level takes about a minute on the
# loaded 2-core machine (the two-body brick between non-matching meshes
# grows about eightfold per level, the 3D levels fourfold).
FAMILIES = {
    "hertz_rigid_mu0_graded": (["hertz.py", "--body", "circle"],
                               range(-2, 5), [5]),
    "hertz_rigid_mu0": (["hertz.py", "--body", "circle"], range(-2, 5),
                        [5]),
    "hertz_rigid_mu0_d_shaped": (["hertz.py", "--body", "dshape"],
                                 range(-2, 5), [5]),
    "receding_2d_mu0": (["receding.py"], range(0, 6), [6, 7]),
    "receding_2d_mu1": (["receding.py", "--mu", "1"], range(0, 6), [6]),
    "two_body_ratio_1": (["two_body.py", "--ratio", "1"], range(0, 5), [5]),
    "two_body_ratio_1e-3": (["two_body.py", "--ratio", "1e-3"], range(0, 5),
                            [5]),
    "two_body_ratio_1e3": (["two_body.py", "--ratio", "1e3"], range(0, 5),
                           [5]),
    "hertz_ratio_1_mu0": circle_on_block("1"),
    "hertz_ratio_1e-3_mu0": circle_on_block("1e-3"),
    "hertz_ratio_1e3_mu0": circle_on_block("1e3"),
    "hertz_rigid_mu1_graded": (["hertz.py", "--body", "circle", "--mu",
                                "1"], range(-2, 5), [5]),
    "hertz_rigid_mu1": (["hertz.py", "--body", "circle", "--mu", "1"],
                        range(-2, 5), [5]),
    "hertz_cavity_mu0": (["hertz.py", "--body", "circle", "--cavity"],
                         range(0, 4), [4]),
    "hertz_cavity_mu1": (["hertz.py", "--body", "circle", "--cavity", "--mu",
                          "1"], range(0, 4), [4]),
    "receding_3d_L80": (["receding_3d.py"], range(0, 5), [5]),
    "hertz_sphere_rigid": (["sphere.py"], range(-2, 4), [4]),
    # Level 3 (641 547 dofs) is not run: level 2 peaks at 1.5 GB, and a
    # 3D factor of 7.5 times the unknowns grows about 15 times.
    "hertz_sphere_rigid_nested": (["sphere.py", "--nested", "-2"],
                                  range(0, 3), []),
    # Level 3 of the coarser nested family (420 543 dofs) fits (about
    # 11 GB): four GetFEM levels.
    "hertz_sphere_rigid_nested3": (["sphere.py", "--nested", "-3"],
                                   range(0, 3), [3]),
    "hertz_two_spheres": (["sphere.py", "--two"], range(-2, 3), [3]),
    "hertz_two_spheres_nested": (["sphere.py", "--two", "--nested", "-2"],
                                 range(0, 3), []),
    "hertz_two_spheres_mu03": (["sphere.py", "--two", "--mu", "0.3"],
                               range(-2, 3), [3]),
}
for ratio in ("1", "1e-3", "1e3"):
    FAMILIES[f"hertz_ratio_{ratio}_mu1"] = circle_on_block(ratio, "--mu", "1")
# The same GetFEM runs for dpana's other meshes of the same problem: its
# leaner disc (_r10, on that disc: ON_DPANA_MESH below), its graded disc on
# the scene's block (_graded), its graded disc and graded foundation or
# cavity (_graded_block, the cavity's _graded).
for name, base in (("hertz_rigid_mu0_r10", "hertz_rigid_mu0"),
                   ("hertz_ratio_1_mu0_graded", "hertz_ratio_1_mu0"),
                   ("hertz_cavity_mu0_graded", "hertz_cavity_mu0"),
                   ("hertz_cavity_mu1_graded", "hertz_cavity_mu1")):
    FAMILIES[name] = FAMILIES[base]
for name in ("hertz_ratio_1_mu0", "hertz_ratio_1_mu1", "hertz_ratio_1e3_mu0",
             "hertz_ratio_1e3_mu1", "hertz_ratio_1e-3_mu0",
             "hertz_ratio_1e-3_mu1"):
    FAMILIES[name + "_graded_block"] = FAMILIES[name]
# The same GetFEM sweeps, paired with dpana's patches around the vertices
# (families.py VERTEX_VARIANTS).
for name in ("hertz_rigid_mu0", "hertz_rigid_mu1", "hertz_rigid_mu0_graded",
             "hertz_rigid_mu1_graded", "hertz_rigid_mu0_r10",
             "hertz_rigid_mu0_d_shaped", "hertz_sphere_rigid",
             "hertz_two_spheres"):
    FAMILIES[name + "_vertices"] = FAMILIES[name]
# Families whose body GetFEM solves on dpana's own mesh of each level
# (hertz.py --mesh), so that both codes solve the same discretisation: dpana
# writes it first (dpana_meshes(); the patches around the vertices do not
# change the mesh).
ON_DPANA_MESH = tuple(
    name + variant for name in ("hertz_rigid_mu0", "hertz_rigid_mu1",
                                "hertz_rigid_mu0_r10",
                                "hertz_rigid_mu0_d_shaped")
    for variant in ("", "_vertices"))
# h of a level, in the units of the dpana family (families.py).
H = {"hertz.py": lambda level: 2.0 ** -level,
     "receding.py": lambda level: 40.0 / (4 * 2 ** level),
     "two_body.py": lambda level: 40.0 / (4 * 2 ** level),
     "receding_3d.py": lambda level: 40.0 / [4, 8, 12, 16, 24, 32][level],
     "sphere.py": lambda level: 2.0 ** (-level / 2)}


def h_of(args, level):
    """h of a level; sphere.py --nested BASE: level k is the mesh of level
    BASE split k times, h = 2^(-BASE/2 - k) (families.nested_sphere)."""
    if "--nested" in args:
        base = float(args[args.index("--nested") + 1])
        return 2.0 ** (-base / 2 - level)
    return H[args[0]](level)


def machine_environment():
    """The environment of a GetFEM run: as dpana's (the dpana command asks
    malloc for transparent huge pages and names OpenBLAS' kernels where
    OpenBLAS would run its generic ones, source/launcher/launcher.cc), so
    that the two codes pay the same page faults and compute their dense
    blocks on the same instructions."""
    env = dict(os.environ)
    given = env.get("GLIBC_TUNABLES", "")
    if "glibc.malloc.hugetlb" not in given:
        env["GLIBC_TUNABLES"] = ":".join(
            t for t in (given, "glibc.malloc.hugetlb=1") if t)
    kernels = records_io.blas_kernels()
    if kernels is not None:
        env["OPENBLAS_CORETYPE"] = kernels
    return env


def run_level(python, args, level, timeout):
    start = time.perf_counter()
    try:
        proc = subprocess.run([python, *args, "--level", str(level)],
                              cwd=HERE, capture_output=True, text=True,
                              timeout=timeout, env=machine_environment())
    except subprocess.TimeoutExpired:
        return {"level": level, "failed": f"timeout {timeout} s"}
    wall = time.perf_counter() - start
    if proc.returncode != 0:
        return {"level": level, "failed": proc.stderr[-300:]}
    record = json.loads(proc.stdout.strip().splitlines()[-1])
    record.update({"level": level, "h": h_of(args, level), "wall": wall})
    return record


# Families with a level longer than the sweep's --timeout: at least this
# many seconds per run (the sphere's level 3: 10 Newton steps, each a
# MUMPS factorisation of 420 543 unknowns: 1 437 s in all).
TIMEOUTS = {"hertz_sphere_rigid_nested3": 3600}


def dpana_meshes(dpana, family, h, directory, timeout):
    """Runs dpana on the level of @p family (families.py) of mesh size @p h
    in @p directory with `Output / Write mesh`, and returns the paths of the
    bodies' meshes, body_1.msh (and body_2.msh). Not timed: it stands for
    GetFEM's gmsh meshing."""
    fam = dpana_families.BY_NAME[family]
    edits = [e for hh, e in fam.levels + fam.full if abs(hh - h) <= 1e-9 * h]
    if not edits:
        raise SystemExit(f"getfem/sweep.py: error: {family} has no dpana "
                         f"level of h = {h}")
    text = prm_edit.set_entry(dpana_sweep.level_text(fam, PRM_DIR, edits[0]),
                              "Output/Write mesh", "true")
    with open(os.path.join(directory, "scene.prm"), "w") as f:
        f.write(text)
    subprocess.run([os.path.abspath(dpana), "scene.prm"], cwd=directory,
                   check=True, capture_output=True, timeout=timeout)
    paths = [os.path.join(directory, "output", f"body_{b}.msh")
             for b in (1, 2)]
    return [p for p in paths if os.path.exists(p)]


def run(python, family, full, timeout, repeat, dpana=None):
    """The levels of family, each run repeat times (a short one more:
    records.fastest_of_runs), the fastest kept; on dpana's mesh of the level
    for the families of ON_DPANA_MESH."""
    args, levels, extra = FAMILIES[family]
    timeout = max(timeout, TIMEOUTS.get(family, 0))
    records = []
    for level in list(levels) + (list(extra) if full else []):
        with tempfile.TemporaryDirectory(prefix="getfem_dpana_mesh_") as tmp:
            level_args = args
            if family in ON_DPANA_MESH:
                level_args = args + ["--mesh", *dpana_meshes(
                    dpana, family, h_of(args, level), tmp, timeout)]
            records.append(records_io.fastest_of_runs(
                lambda: run_level(python, level_args, level, timeout),
                repeat))
        if not records_io.progress(records[-1]):
            break
    return records


def main():
    parser = records_io.parser(__doc__.splitlines()[0])
    parser.add_argument("--dpana", default=None,
                        help="the dpana binary, which writes the meshes of "
                        "the families on dpana's meshes (ON_DPANA_MESH)")
    args = parser.parse_args()
    names = args.family or list(FAMILIES)
    for name in names:
        if name not in FAMILIES:
            sys.exit(f"getfem/sweep.py: error: unknown family {name}")
        if name in ON_DPANA_MESH and args.dpana is None:
            sys.exit(f"getfem/sweep.py: error: {name} solves on dpana's "
                     "meshes: give --dpana BUILD/dpana")
    os.makedirs(args.out, exist_ok=True)
    load = records_io.load_average()
    for name in names:
        print(f"== GetFEM {name}", flush=True)
        records = run(sys.executable, name, args.full, args.timeout,
                      args.repeat, args.dpana)
        records_io.write(args.out, name, "getfem", records, load)


if __name__ == "__main__":
    main()
