#!/usr/bin/env python3
"""GetFEM with weak contact conditions on the Hertz cylinder of hertz.py
(the circular body on the rigid plane, frictionless, the graded mesh of
level L): GetFEM's integral contact brick with a rigid obstacle
(non-symmetric Alart-Curnier, augmentation r = E) and a multiplier field
on the candidate faces, instead of hertz.py's nodal brick:
  P0         piecewise constant, one value per face;
  P1         piecewise linear, one value per surface node;
  P1-lumped  the same, with the contact integrals taken by the vertex
             rule of each face (the trapezoidal rule: GetFEM's IM_NC(2,1)),
             which makes the weak conditions nodal ones, those of the
             nodal brick with the tributary lengths as weights.
It tells whether the small a_m error of the nodal brick on the coarse
levels comes from its nodal conditions or from the degree of its
multipliers (README.md, "What closes the remaining gaps, and what does not").

The pressure p = -lambda_n acts along the obstacle's normal y (the
resultant is the load). a_m = 2 (int p x^2 ds / int p ds)^(1/2) over the
candidate faces, with a quadrature exact for the products of the
multiplier field (also for P1-lumped, whose nodal values it interpolates
linearly); N_max is the largest multiplier value.

  weak_contact.py --level L --multiplier P0|P1|P1-lumped

Prints one JSON record (sizes, Newton iterations, a_m, N_max, resultant,
the time of the GetFEM work).
"""

import argparse
import tempfile
import time

import numpy as np

from contact_model import ElasticBody, emit
from hertz import AXIS, CONTACT, E, NU, P, R, cylinder, level_mesh


def solve(gf, msh, multiplier):
    mesh = cylinder(gf, msh, 15)
    body = ElasticBody(mesh, E, NU)
    body.symmetry(AXIS)
    md = body.md
    mf_lambda = gf.MeshFem(mesh, 1)
    if multiplier == "P0":
        mf_lambda.set_classical_discontinuous_fem(0)
    else:
        mf_lambda.set_classical_fem(1)
    md.add_filtered_fem_variable("lambda_n", mf_lambda, CONTACT)
    mf_obstacle = gf.MeshFem(mesh, 1)
    mf_obstacle.set_classical_fem(1)
    md.add_initialized_fem_data("obstacle", mf_obstacle,
                                mf_obstacle.eval("y"))
    md.add_initialized_data("r", [E])
    mim = (gf.MeshIm(mesh, gf.Integ("IM_NC(2,1)"))
           if multiplier == "P1-lumped" else body.mim)
    md.add_integral_contact_with_rigid_obstacle_brick(
        mim, "u", "lambda_n", "obstacle", "r", CONTACT, 1)
    body.point_force((0.0, 2 * R), 1, -P / 2)
    nit, converged = body.solve(1e-8 * P)
    exact = gf.MeshIm(mesh, 6)
    resultant = gf.asm_generic(exact, 0, "-lambda_n", CONTACT, md)
    moment = gf.asm_generic(exact, 0, "-lambda_n*X(1)*X(1)", CONTACT, md)
    lam = -np.asarray(md.variable("lambda_n"))
    return {"dofs": int(body.mfu.nbdof()), "contact_unknowns": len(lam),
            "iterations": nit, "converged": converged,
            "resultant": float(resultant),
            "a_m": float(2 * np.sqrt(moment / resultant)),
            "N_max": float(lam.max())}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--level", type=int, required=True)
    parser.add_argument("--multiplier", choices=("P0", "P1", "P1-lumped"),
                        required=True)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="getfem_weak_") as tmp:
        msh = level_mesh("circle", args.level, 14.0, tmp)
        import getfem as gf
        start = time.perf_counter()
        record = solve(gf, msh, args.multiplier)
    record.update({"level": args.level, "multiplier": args.multiplier})
    emit(record, start)


if __name__ == "__main__":
    main()
