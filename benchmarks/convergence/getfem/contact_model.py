"""The parts the GetFEM scenes share: a plane-strain linear elastic body of
P1 triangles on a rigid plane y = 0, with GetFEM's nodal contact brick
(frictionless, non-symmetric Alart-Curnier augmented Lagrangian, solved by
GetFEM's Newton method), and the nodal contact pressures.

The body is held in y by contact only. Its rigid translation is removed as
in GetFEM's own static contact example, by a mass term of tiny weight
(eps = 1e-8 MPa/mm^2 times the displacement): over the body's area it
carries a force eps |Omega| |u_y|, some 1e-10 of the load here.
"""

import numpy as np
import getfem as gf


def lame(E, nu):
    """Lame constants of plane strain (GetFEM's 2D elasticity brick)."""
    return E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))


def boundary_faces(mesh, keep):
    """Outer faces (2 x n array: convex, face) whose two vertices satisfy
    keep(x, y)."""
    faces = mesh.outer_faces()
    chosen = []
    for j in range(faces.shape[1]):
        pts = mesh.pid_in_faces(faces[:, j:j + 1])
        xy = mesh.pts(pts)
        if all(keep(xy[0, k], xy[1, k]) for k in range(xy.shape[1])):
            chosen.append(j)
    return faces[:, chosen]


class ElasticBody:
    """P1 displacement u on mesh, Lame data, the rigid-motion mass term."""

    def __init__(self, mesh, E, nu):
        self.mesh = mesh
        self.mfu = gf.MeshFem(mesh, 2)
        self.mfu.set_classical_fem(1)
        self.mim = gf.MeshIm(mesh, 2)
        self.md = gf.Model("real")
        self.md.add_fem_variable("u", self.mfu)
        lam, mu = lame(E, nu)
        self.md.add_initialized_data("lambda", [lam])
        self.md.add_initialized_data("mu", [mu])
        self.md.add_isotropic_linearized_elasticity_brick(
            self.mim, "u", "lambda", "mu")
        self.md.add_initialized_data("eps", [1e-8])
        self.md.add_mass_brick(self.mim, "u", "eps")

    def symmetry(self, region):
        """u_x = 0 on region (the symmetry axis x = 0), by multipliers."""
        self.md.add_normal_Dirichlet_condition_with_multipliers(
            self.mim, "u", 1, region)

    def contact(self, region, r, mu=0.0):
        """Nodal Signorini contact on region with the plane y = 0 (signed
        distance y), augmentation r (MPa); with mu > 0, Coulomb friction
        (static: the tangential multipliers against the total tangential
        displacement, the one-step problem dpana solves)."""
        cdof = self.mfu.dof_on_region(region)
        self.contact_dofs = cdof[1::2]
        self.md.add_variable("lambda_n", len(self.contact_dofs))
        self.md.add_initialized_data("r", [r])
        if mu > 0:
            self.md.add_variable("lambda_t", len(self.contact_dofs))
            self.md.add_initialized_data("friction", [mu])
            self.md.add_nodal_contact_with_rigid_obstacle_brick(
                self.mim, "u", "lambda_n", "lambda_t", "r", "friction",
                region, "y", 1)
        else:
            self.md.add_nodal_contact_with_rigid_obstacle_brick(
                self.mim, "u", "lambda_n", "r", region, "y", 1)
        self.contact_region = region

    def solve(self, residual, max_iter=100):
        nit, converged = self.md.solve("max_res", residual, "max_iter",
                                       max_iter, "lsearch", "default")
        return int(nit), bool(converged)

    def nodal_pressures(self):
        """Contact nodes sorted by x: x, nodal force F >= 0 (N/mm) and the
        pressure p = F / (half the length of the adjacent contact faces)."""
        lam = np.asarray(self.md.variable("lambda_n")).ravel()
        nodes = self.mfu.basic_dof_nodes(self.contact_dofs)
        faces = self.mesh.region(self.contact_region)
        tributary = {}
        for j in range(faces.shape[1]):
            pts = self.mesh.pid_in_faces(faces[:, j:j + 1])
            xy = self.mesh.pts(pts)
            half = 0.5 * np.hypot(*(xy[:, 1] - xy[:, 0]))
            for k in range(2):
                key = (round(xy[0, k], 9), round(xy[1, k], 9))
                tributary[key] = tributary.get(key, 0.0) + half
        trib = np.array([tributary[(round(x, 9), round(y, 9))]
                         for x, y in nodes.T])
        force = np.abs(lam)
        order = np.argsort(nodes[0])
        return nodes[0][order], force[order], (force / trib)[order]


def pressure_quantities(x, force, p):
    """N_max, N_first (the node on the axis), the resultant, the half width
    at node resolution (last node that carries a force) and the moment
    estimate a_m = 2 sqrt(sum F x^2 / sum F)."""
    total = force.sum()
    active = np.nonzero(force > 1e-12 * total)[0]
    return {
        "N_max": float(p.max()),
        "N_first": float(p[0]),
        "resultant": float(total),
        "a": float(x[active[-1]]),
        "a_m": float(2 * np.sqrt((force * x * x).sum() / total)),
        "x_p": float((force * x).sum() / total),
    }
