#!/usr/bin/env python3
"""GetFEM harness: the Hertz cylinder R = 40 mm (E = 130000 MPa, nu = 0.2,
plane strain) on a rigid plane, frictionless, half model x >= 0, loaded
along its axis by half the line load P = 200 kN/mm:
  --body circle   the circular body, force at its far pole (0, 2R);
  --body dshape   the quarter disc below the centre (dpana's hertz_rigid
                  scenes), force at the centre (0, R).
Level L: element size h_c = (pi R / 4) / 2^(L + 5) within 14 mm of the
contact point (the boundary chord of dpana's quarter disc with L global
and 5 contact refinements), growing to 32 h_c (at most R/4) at 28 mm.
Candidate contact nodes: the arc within x <= 15 mm.

Prints one JSON record: sizes, Newton iterations, the time of the GetFEM
work (mesh import, assembly and solve; the gmsh meshing is timed apart)
and the quantities of pressure_quantities().
"""

import argparse
import json
import math
import sys
import tempfile
import time

from contact_model import ElasticBody, boundary_faces, pressure_quantities
from mesh import hertz_mesh

R, E, NU, P = 40.0, 130000.0, 0.2, 200000.0
CONTACT, AXIS = 10, 11


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--body", choices=("circle", "dshape"),
                        default="circle")
    parser.add_argument("--level", type=int, required=True)
    args = parser.parse_args()
    hc = (math.pi * R / 4) / 2 ** (args.level + 5)
    with tempfile.TemporaryDirectory(prefix="getfem_hertz_") as tmp:
        start = time.perf_counter()
        msh = hertz_mesh(args.body, R, hc, min(32 * hc, R / 4), 14.0, tmp)
        meshing = time.perf_counter() - start
        import getfem as gf
        start = time.perf_counter()
        mesh = gf.Mesh("import", "gmsh", msh)
    mesh.set_region(CONTACT, boundary_faces(
        mesh, lambda x, y: x <= 15 + 1e-9 and y < R
        and abs(math.hypot(x, y - R) - R) < 1e-6 * R))
    mesh.set_region(AXIS, boundary_faces(mesh, lambda x, y: abs(x) < 1e-9))
    body = ElasticBody(mesh, E, NU)
    body.symmetry(AXIS)
    body.contact(CONTACT, E)
    pole = (0.0, 2 * R) if args.body == "circle" else (0.0, R)
    nodes = body.mfu.basic_dof_nodes()
    dist = (nodes[0] - pole[0]) ** 2 + (nodes[1] - pole[1]) ** 2
    ydof = [d for d in range(body.mfu.nbdof()) if d % 2 == 1]
    load = [0.0] * body.mfu.nbdof()
    load[min(ydof, key=lambda d: dist[d])] = -P / 2
    body.md.add_explicit_rhs("u", load)
    # Residual 1e-8 of the load: answers and Newton iterations are the same
    # as with 1e-11 of it (checked on levels 2 and 3); 1e-14 of it is below
    # the round-off floor and does not converge.
    nit, converged = body.solve(1e-8 * P)
    record = {"dofs": int(body.mfu.nbdof()),
              "contact_unknowns": len(body.contact_dofs),
              "iterations": nit, "converged": converged,
              "h_c": hc}
    record.update(pressure_quantities(*body.nodal_pressures()))
    record["solve_time"] = time.perf_counter() - start
    # Plane Hertz: a = sqrt(4 P R (1 - nu^2) / (pi E)), p0 = 2 P / (pi a).
    a = math.sqrt(4 * P * R * (1 - NU * NU) / (math.pi * E))
    record["hertz"] = {"a": a, "N_max": 2 * P / (math.pi * a)}
    record["meshing_time"] = meshing
    json.dump(record, sys.stdout)
    print()


if __name__ == "__main__":
    main()
