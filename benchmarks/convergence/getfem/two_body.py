#!/usr/bin/env python3
"""GetFEM harness: the two-body blocks of prm/two_body_ratio_*.prm. The
receding block (half model 40 x 40 mm, E1 = 130000 MPa, nu = 0.2, plane
strain, 50 MPa on the top, 100 MPa on the right side, symmetry u_x = 0 on
x = 0) on an elastic foundation [0, 80] x [-80, 0] (E2 = E1 / ratio,
nu = 0.2, symmetry on x = 0, fixed at its base), Coulomb friction mu = 1.
Level L: the block has n = 4 * 2^L squares per side, the foundation 2n,
each square split into two P1 triangles (GetFEM's 'regular simplices',
diagonals alternating as on a checkerboard: dpana's meshes, with
`Diagonals = alternating`), so the meshes match on the interface, as
dpana's do. Contact: GetFEM's
nodal brick between non-matching meshes, the block's base the slave side
(its nodes carry the multipliers), the foundation's top x <= 40 the master.

Prints one JSON record (see hertz.py).
"""

import argparse
import time

import numpy as np

from contact_model import ElasticBody, boundary_faces, emit, meshing
from receding import BOTTOM, E, L, NU, TOP, loaded_block
F_TOP, F_LEFT, F_BASE = 20, 21, 22


@meshing()
def foundation(gf, n, tol):
    mesh = gf.Mesh("regular simplices", np.linspace(0.0, 2 * L, 2 * n + 1),
                   np.linspace(-2 * L, 0.0, 2 * n + 1))
    mesh.set_region(F_TOP, boundary_faces(
        mesh, lambda x, y: y > -tol and x < L + tol))
    mesh.set_region(F_LEFT, boundary_faces(mesh, lambda x, y: x < tol))
    mesh.set_region(F_BASE, boundary_faces(mesh, lambda x, y: y < tol - 2 * L))
    return mesh


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--level", type=int, required=True)
    parser.add_argument("--ratio", type=float, default=1.0,
                        help="E1 / E2 (two_body_ratio_1, _1e-3, _1e3)")
    args = parser.parse_args()
    n = 4 * 2 ** args.level
    import getfem as gf
    start = time.perf_counter()
    body = loaded_block(gf, n)
    base = ElasticBody(foundation(gf, n, 1e-9 * L), E / args.ratio, NU,
                       model=body.md, name="v", held=True)
    base.symmetry(F_LEFT)
    base.fixed(F_BASE)
    # Augmentation: the smaller modulus (GetFEM's advice: close to the
    # Young modulus of the bodies).
    body.contact_with(base, BOTTOM, F_TOP, min(E, E / args.ratio), 1.0)
    # A residual of 1e-10 of the load, as for the receding block with
    # friction (receding.py).
    nit, converged = body.solve(1e-10 * TOP * L)
    emit(body.record(nit, converged, body.mfu.nbdof() + base.mfu.nbdof(),
                     n=n), start)


if __name__ == "__main__":
    main()
