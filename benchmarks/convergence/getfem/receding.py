#!/usr/bin/env python3
"""GetFEM harness: the receding block of prm/receding_2d_mu0.prm (and, with
--mu 1, of receding_2d_mu1.prm: Coulomb friction by the same nodal brick).
Half block 40 x 40 mm (symmetry u_x = 0 on x = 0), E = 130000 MPa,
nu = 0.2, plane strain, 50 MPa on the top, 100 MPa on the right side, on
the rigid plane y = 0. Level L: n = 4 * 2^L squares per side, each split
into two P1 triangles (GetFEM's 'regular simplices', whose diagonals
alternate as on a checkerboard: the mesh of dpana's rectangle with n
subdivisions and `Diagonals = alternating`, as the scene files set it).
The exact solution is the uniform stress state sigma_yy = -50 MPa: every
nodal pressure is 50 MPa (frictionless).

Prints one JSON record (see hertz.py), with uniform_error =
max |p - 50| / 50 over the contact nodes.
"""

import argparse
import time

import numpy as np

from contact_model import ElasticBody, boundary_faces, emit, meshing

L, E, NU, TOP, SIDE = 40.0, 130000.0, 0.2, 50.0, 100.0
BOTTOM, LEFT, UPPER, RIGHT = 10, 11, 12, 13


def loaded_block(gf, n, nu=NU):
    """The half block on n x n squares of two P1 triangles, with its
    symmetry condition and loads (its base is the region BOTTOM)."""
    with meshing():
        grid = np.linspace(0.0, L, n + 1)
        mesh = gf.Mesh("regular simplices", grid, grid)
        tol = 1e-9 * L
        mesh.set_region(BOTTOM, boundary_faces(mesh, lambda x, y: y < tol))
        mesh.set_region(LEFT, boundary_faces(mesh, lambda x, y: x < tol))
        mesh.set_region(UPPER, boundary_faces(mesh, lambda x, y: y > L - tol))
        mesh.set_region(RIGHT, boundary_faces(mesh, lambda x, y: x > L - tol))
    body = ElasticBody(mesh, E, nu)
    body.symmetry(LEFT)
    body.traction(UPPER, [0.0, -TOP])
    body.traction(RIGHT, [-SIDE, 0.0])
    return body


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--level", type=int, required=True)
    parser.add_argument("--mu", type=float, default=0.0,
                        help="friction coefficient (receding_2d_mu1: 1)")
    parser.add_argument("--nu", type=float, default=NU,
                        help="Poisson's ratio (receding_2d_nu0_mu1: 0)")
    args = parser.parse_args()
    n = 4 * 2 ** args.level
    import getfem as gf
    start = time.perf_counter()
    body = loaded_block(gf, n, args.nu)
    body.contact(BOTTOM, E, args.mu)
    # GetFEM's residual divides the rows of the contact conditions by r:
    # with friction, a tolerance of 1e-8 of the load let Newton stop on a
    # wrong active set (tensile multipliers of up to 4 N at n = 64); 1e-10
    # of the load converges on the right one, above the round-off floor.
    nit, converged = body.solve(1e-10 * TOP * L)
    record = body.record(nit, converged, n=n)
    p = body.nodal_pressures()[2]
    record["uniform_error"] = float(np.abs(p - TOP).max() / TOP)
    emit(record, start)


if __name__ == "__main__":
    main()
