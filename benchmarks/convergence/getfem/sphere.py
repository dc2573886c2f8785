#!/usr/bin/env python3
"""GetFEM harness: the 3D Hertz sphere of prm/hertz_sphere_rigid.prm. The
quarter x >= 0, z >= 0 of an elastic sphere R = 40 mm (E = 130000 MPa,
nu = 0.2) touching the rigid plane y = 0 at the origin, loaded by P/4 =
75 kN at its far pole (0, 2R, 0), frictionless. The mesh is dpana's: the
gmsh mesh of scripts/meshes/make_sphere.py --level L (P1 tetrahedra, made
once into the sweep's cache directory and not timed), imported with its
physical groups: symmetry_x (1) and symmetry_z (2) carry the normal
symmetry conditions, the cap `contact` (3, r <= 6 mm) the candidate nodes.
3D Hertz: a = (3 P R / (4 E*))^(1/3) = 4.050 mm, p0 = 3 P / (2 pi a^2) =
8730 MPa, 1/E* = (1 - nu^2) / E.

  --two     the two spheres of prm/hertz_two_spheres.prm: below the
            upper sphere (the one above) its mirror image, centre
            (0, -R, 0), on dpana's mesh of it (make_sphere.py --side -1
            --set CapRadius=7.5: a contact cap of 7.5 mm, which covers the
            upper one's), symmetric in x and z, fixed on its far cap
            `pole` (4, r <= 4 mm around (0, -2R, 0)); GetFEM's nodal brick
            between non-matching meshes, the upper cap the slave side, the
            lower cap the master side, augmentation r = E. Hertz with
            1/R* = 2/R and 1/E* = 2 (1 - nu^2)/E: the same a and p0.
  --mu MU   Coulomb friction MU (hertz_two_spheres_mu03.prm: 0.3).
  --nested BASE
            the nested meshes of the families hertz_sphere_rigid_nested[3]
            and hertz_two_spheres_nested: --level k is the mesh of
            make_sphere.py --level BASE --refine k (with --two, the lower
            sphere's too).
Residual 1e-10 of the load.

Prints one JSON record (see hertz.py).
"""

import argparse
import math
import os
import sys
import time

from contact_model import ElasticBody, emit, meshing

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from families import SphereMesh  # noqa: E402  (benchmarks/convergence/)

R, E, NU, P = 40.0, 130000.0, 0.2, 300000.0
SYM_X, SYM_Z, CONTACT, POLE = 1, 2, 3, 4
# dpana's mesh options of the lower sphere (prm/hertz_two_spheres.prm)
LOWER = ("--side", "-1", "--set", "CapRadius=7.5")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--level", type=int, required=True)
    parser.add_argument("--two", action="store_true",
                        help="two spheres instead of one on the plane")
    parser.add_argument("--mu", type=float, default=0.0,
                        help="Coulomb friction coefficient (default 0)")
    parser.add_argument("--nested", type=float, metavar="BASE",
                        help="--level k: the mesh of level BASE split k "
                        "times")
    args = parser.parse_args()
    if args.mu < 0:
        parser.error("--mu must be >= 0")
    if args.nested is not None and args.level < 0:
        parser.error("--nested needs --level >= 0 (refinements)")
    prm = os.path.join(HERE, "..", "..", "..", "prm")
    start = time.perf_counter()
    if args.nested is not None:
        base = int(args.nested) if args.nested.is_integer() else args.nested
        level, refine = base, ("--refine", str(args.level))
    else:
        level, refine = args.level, ()
    msh = [SphereMesh(level, *refine).path(prm)]
    if args.two:
        msh.append(SphereMesh(level, *LOWER, *refine).path(prm))
    gmsh_time = time.perf_counter() - start
    import getfem as gf
    start = time.perf_counter()
    with meshing():
        upper = gf.Mesh("import", "gmsh", msh[0])
        lower = gf.Mesh("import", "gmsh", msh[1]) if args.two else None
    body = ElasticBody(upper, E, NU)
    body.symmetry(SYM_X)
    body.symmetry(SYM_Z)
    dofs = body.mfu.nbdof()
    if args.two:
        lower = ElasticBody(lower, E, NU,
                            model=body.md, name="v", held=True)
        lower.symmetry(SYM_X)
        lower.symmetry(SYM_Z)
        lower.fixed(POLE)
        body.contact_with(lower, CONTACT, CONTACT, E, args.mu)
        dofs += lower.mfu.nbdof()
    else:
        body.contact(CONTACT, E, args.mu)
    body.point_force((0.0, 2 * R, 0.0), 1, -P / 4)
    # 1e-10 of the load: at level 3, 1e-12 of it is below the round-off
    # floor (100 iterations without convergence, the answers to 7 digits
    # those of 1e-10, reached in 10 iterations).
    nit, converged = body.solve(1e-10 * P)
    # Hertz: E* and R* both halve for two equal spheres, a and p0 stay.
    a = (3 * P * R * (1 - NU * NU) / (4 * E)) ** (1 / 3)
    emit(body.record(nit, converged, dofs, meshing_time=gmsh_time, hertz={
        "a": a, "N_max": 3 * P / (2 * math.pi * a * a)}), start)


if __name__ == "__main__":
    main()
