#!/usr/bin/env python3
"""GetFEM harness: the Hertz cylinder R = 40 mm (E = 130000 MPa, nu = 0.2,
plane strain) on a rigid plane, frictionless (see --mu), half model
x >= 0, loaded along its axis by half the line load P = 200 kN/mm:
  --body circle   the circular body, force at its far pole (0, 2R);
  --body dshape   the quarter disc below the centre (dpana's hertz_rigid
                  scenes), force at the centre (0, R).
Level L: element size h_c = (pi R / 4) / 2^(L + 5) within 14 mm of the
contact point (the boundary chord of dpana's quarter disc with L global
and 5 contact refinements), growing to 32 h_c (at most R/4) at 28 mm.
Candidate contact nodes: the arc within x <= 15 mm.
  --ratio E1/E2   instead of the rigid plane, the elastic foundation of
                  prm/hertz_ratio_*, the softer of the two bodies with
                  E = 130000 MPa as in those scenes (E1 = E max(1, ratio),
                  E2 = E1 / ratio): [0, 80] x [-80, 0] (symmetry on x = 0,
                  fixed at its base), meshed by gmsh with the same size
                  field around the contact point as the body (whose
                  refinement radius becomes dpana's 17 mm there);
                  GetFEM's nodal brick between non-matching meshes, the
                  arc x <= 16 mm the slave side, the foundation's top
                  x <= 20 mm the master side.
  --cavity        instead, the body with the cylindrical cavity of
                  prm/hertz_cavity_* (equal moduli, E = 130000 MPa): the
                  lower right quarter of the ring 120 <= r <= 360 around
                  (0, 120), symmetry on x = 0, fixed on its outer circle,
                  held vertically on its cut y = 120; the size field of
                  both bodies within dpana's refinement radius there,
                  21 mm; the arc x <= 20 mm (dpana's candidate half width)
                  the slave side, the cavity's arc x <= 24 mm the master.
  --mu MU         Coulomb friction MU (the *_mu1 scenes: 1) in the same
                  nodal brick (its tangential multipliers), residual 1e-10
                  of the load instead of 1e-8 (see solve()).
  --mesh FILE [FILE2]
                  the meshes from these files instead of gmsh's: the body's,
                  and with --ratio or --cavity the foundation's or the
                  cavity's; the meshes dpana solved a level on, written by
                  its `Output / Write mesh` (gmsh format 1), so that both
                  codes solve the same discretisation; the level only names
                  h_c.
Between two bodies the pressures are the nodal forces along y (see
contact_model.ElasticBody.master_directions).

Prints one JSON record: sizes, Newton iterations, the time of the GetFEM
work (assembly and solve; the gmsh meshing and the mesh import with its
regions are timed apart)
and the quantities of pressure_quantities().
"""

import argparse
import math
import tempfile
import time

from contact_model import ElasticBody, boundary_faces, emit, meshing
from mesh import hertz_mesh

R, E, NU, P = 40.0, 130000.0, 0.2, 200000.0
CONTACT, AXIS, F_TOP, F_LEFT, F_BASE, F_CUT = 10, 11, 20, 21, 22, 23
# The cavity: radius and centre of its inner circle, its outer radius.
R_CAVITY, Y_CAVITY, R_OUTER = 3 * R, 3 * R, 9 * R


@meshing()
def foundation(gf, msh):
    """The elastic block below the contact point and its regions."""
    mesh = gf.Mesh("import", "gmsh", msh)
    mesh.set_region(F_TOP, boundary_faces(
        mesh, lambda x, y: abs(y) < 1e-9 and x <= 20 + 1e-9))
    mesh.set_region(F_LEFT, boundary_faces(mesh, lambda x, y: abs(x) < 1e-9))
    mesh.set_region(F_BASE, boundary_faces(
        mesh, lambda x, y: abs(y + 2 * R) < 1e-9))
    return mesh


@meshing()
def cavity(gf, msh):
    """The body with the cavity and its regions: the inner arc near the
    contact point (master side), the axis, the outer circle, the cut."""
    mesh = gf.Mesh("import", "gmsh", msh)

    def on_circle(x, y, radius):
        return abs(math.hypot(x, y - Y_CAVITY) - radius) < 1e-6 * radius

    mesh.set_region(F_TOP, boundary_faces(
        mesh, lambda x, y: x <= 24 + 1e-9 and on_circle(x, y, R_CAVITY)))
    mesh.set_region(F_LEFT, boundary_faces(mesh, lambda x, y: abs(x) < 1e-9))
    mesh.set_region(F_BASE, boundary_faces(
        mesh, lambda x, y: on_circle(x, y, R_OUTER)))
    mesh.set_region(F_CUT, boundary_faces(
        mesh, lambda x, y: abs(y - Y_CAVITY) < 1e-9))
    return mesh


@meshing()
def cylinder(gf, msh, width):
    """The cylinder's half and its regions: the arc x <= width (the
    candidate contact faces) and the axis."""
    mesh = gf.Mesh("import", "gmsh", msh)
    mesh.set_region(CONTACT, boundary_faces(
        mesh, lambda x, y: x <= width + 1e-9 and y < R
        and abs(math.hypot(x, y - R) - R) < 1e-6 * R))
    mesh.set_region(AXIS, boundary_faces(mesh, lambda x, y: abs(x) < 1e-9))
    return mesh


def level_size(level):
    """h_c of a level (the module's docstring)."""
    return (math.pi * R / 4) / 2 ** (level + 5)


def level_mesh(body, level, rho, tmp):
    """The gmsh mesh of body at a level: h_c within rho of the contact
    point, growing to 32 h_c (at most R/4) (the module's docstring)."""
    hc = level_size(level)
    return hertz_mesh(body, R, hc, min(32 * hc, R / 4), rho, tmp)


def solve(gf, msh, ratio, args):
    """Builds and solves the model; returns the body and its record."""
    mesh = cylinder(gf, msh[0], 15 if ratio is None else
                    20 if args.cavity else 16)
    E1 = E * max(1.0, ratio or 1.0)
    body = ElasticBody(mesh, E1, NU)
    body.symmetry(AXIS)
    dofs = body.mfu.nbdof()
    if ratio is None:
        body.contact(CONTACT, E, args.mu)
    else:
        if args.cavity:
            base = ElasticBody(cavity(gf, msh[1]), E1 / ratio, NU,
                               model=body.md, name="v", held=True)
            base.symmetry(F_CUT)
        else:
            base = ElasticBody(foundation(gf, msh[1]), E1 / ratio, NU,
                               model=body.md, name="v", held=True)
        base.symmetry(F_LEFT)
        base.fixed(F_BASE)
        body.contact_with(base, CONTACT, F_TOP, min(E1, E1 / ratio), args.mu)
        dofs += base.mfu.nbdof()
    pole = (0.0, 2 * R) if args.body == "circle" else (0.0, R)
    body.point_force(pole, 1, -P / 2)
    # Frictionless, a residual of 1e-8 of the load: answers and Newton
    # iterations are the same as with 1e-11 of it (checked on levels 2 and
    # 3); 1e-14 of it is below the round-off floor and does not converge.
    # With friction the contact rows are divided by r, as on the receding
    # block, where 1e-8 of the load let Newton stop on a wrong active set:
    # 1e-10 of it, times E1/E where the body is the stiffer one (the
    # residual grows with the modulus: for E1/E2 = 1e3, asked for 1e-10 of
    # the load, Newton does not converge in 100 iterations at level 0; at
    # 1e-8 and 1e-7 of it it converges in 13 iterations at levels 0 and 2,
    # to N_max equal to 3e-11).
    tolerance = 1e-8 if args.mu == 0 else 1e-10 * E1 / E
    nit, converged = body.solve(tolerance * P)
    return body.record(nit, converged, dofs)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--body", choices=("circle", "dshape"),
                        default="circle")
    parser.add_argument("--level", type=int, required=True)
    parser.add_argument("--ratio", type=float, default=None,
                        help="E1/E2 of an elastic foundation (default: "
                        "the rigid plane)")
    parser.add_argument("--cavity", action="store_true",
                        help="the foundation is the body with the cavity "
                        "(E1/E2 = 1)")
    parser.add_argument("--mu", type=float, default=0.0,
                        help="Coulomb friction coefficient (default 0)")
    parser.add_argument("--mesh", nargs="+", default=None,
                        help="the meshes of the body (and of the foundation "
                        "or the cavity) instead of gmsh's, e.g. dpana's "
                        "body_1.msh (body_2.msh)")
    args = parser.parse_args()
    if args.cavity:
        if args.ratio not in (None, 1.0):
            parser.error("--cavity has equal moduli: no --ratio")
        args.ratio = 1.0
    if args.mu < 0:
        parser.error("--mu must be >= 0")
    if args.mesh is not None and \
            len(args.mesh) != (1 if args.ratio is None else 2):
        parser.error("--mesh: one file on the rigid plane, two with --ratio "
                     "or --cavity")
    hc = level_size(args.level)
    rho = 14.0 if args.ratio is None else 21.0 if args.cavity else 17.0
    with tempfile.TemporaryDirectory(prefix="getfem_hertz_") as tmp:
        start = time.perf_counter()
        msh = args.mesh or [level_mesh(args.body, args.level, rho, tmp)]
        if args.ratio is not None and args.mesh is None:
            msh.append(level_mesh("cavity" if args.cavity else "block",
                                  args.level, rho, tmp))
        gmsh_time = time.perf_counter() - start
        import getfem as gf
        start = time.perf_counter()
        record = solve(gf, msh, args.ratio, args)
    record["h_c"] = hc
    # Plane Hertz: a = sqrt(4 P R* / (pi E*)), p0 = 2 P / (pi a), with
    # 1/E* = (1 - nu^2) (1/E1 + 1/E2) and 1/R* = 1/R - 1/R_cavity (the
    # cavity: R* = 60 mm) or 1/R (a plane).
    E1 = E * max(1.0, args.ratio or 1.0)
    inv = (1 - NU * NU) / E1 * (1 + (args.ratio or 0.0))
    radius = 1 / (1 / R - 1 / R_CAVITY) if args.cavity else R
    a = math.sqrt(4 * P * radius * inv / math.pi)
    record["hertz"] = {"a": a, "N_max": 2 * P / (math.pi * a)}
    record["meshing_time"] = gmsh_time
    emit(record, start)


if __name__ == "__main__":
    main()
