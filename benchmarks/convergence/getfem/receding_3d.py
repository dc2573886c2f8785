#!/usr/bin/env python3
"""GetFEM harness: the 3D receding block of prm/receding_3d_L80.prm. The
quarter block 40 x 40 x 40 mm (symmetry planes x = 0 and z = 0),
E = 130000 MPa, nu = 0, 50 MPa on the top y = 40, 100 MPa on the side
x = 40, the end z = 40 free, on the rigid plane y = 0 with Coulomb friction
mu = 1 (GetFEM's nodal brick: the isotropic disc cone, dpana's
`Cone model = disc`). Level L: k x k/2 x k bricks (k = 4, 8, 12, 16, 24 for
L = 0 ... 4, as dpana's sweep), each cut into six P1 tetrahedra (GetFEM's
'regular simplices'; dpana cuts each brick into five, so the meshes differ
in the cut, not in the grid).

Prints one JSON record (see hertz.py).
"""

import argparse
import time

import numpy as np

from contact_model import ElasticBody, boundary_faces, emit, meshing

L, E, NU, TOP, SIDE = 40.0, 130000.0, 0.0, 50.0, 100.0
BOTTOM, LEFT, FRONT, UPPER, RIGHT = 10, 11, 12, 13, 14
K = [4, 8, 12, 16, 24, 32, 48]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--level", type=int, required=True)
    args = parser.parse_args()
    k = K[args.level]
    import getfem as gf
    start = time.perf_counter()
    with meshing():
        mesh = gf.Mesh("regular simplices", np.linspace(0.0, L, k + 1),
                       np.linspace(0.0, L, k // 2 + 1),
                       np.linspace(0.0, L, k + 1))
        tol = 1e-9 * L
        mesh.set_region(BOTTOM, boundary_faces(mesh, lambda x, y, z: y < tol))
        mesh.set_region(LEFT, boundary_faces(mesh, lambda x, y, z: x < tol))
        mesh.set_region(FRONT, boundary_faces(mesh, lambda x, y, z: z < tol))
        mesh.set_region(UPPER, boundary_faces(
            mesh, lambda x, y, z: y > L - tol))
        mesh.set_region(RIGHT, boundary_faces(
            mesh, lambda x, y, z: x > L - tol))
    body = ElasticBody(mesh, E, NU)
    body.symmetry(LEFT)
    body.symmetry(FRONT)
    body.traction(UPPER, [0.0, -TOP, 0.0])
    body.traction(RIGHT, [-SIDE, 0.0, 0.0])
    body.contact(BOTTOM, E, 1.0)
    # 1e-14 of the load: with 1e-10 (the 2D tolerance) Newton stops after
    # one iteration on the frictionless answer (GetFEM divides the rows of
    # the friction conditions by r), with 1e-12 before the answer settles
    # (N_max 97.435 against 97.377 MPa at k = 4).
    nit, converged = body.solve(1e-14 * TOP * L * L)
    emit(body.record(nit, converged, k=k), start)


if __name__ == "__main__":
    main()
