"""The parts the GetFEM scenes share: linear elastic bodies of P1 simplices
(plane strain in 2D), GetFEM's nodal contact bricks (non-symmetric
Alart-Curnier augmented Lagrangian, frictionless or with Coulomb friction,
solved by GetFEM's Newton method) with a rigid plane or between two bodies,
and the nodal contact pressures.

A body held by contact only (in y) has its rigid translation removed as in
GetFEM's own static contact example, by a mass term of tiny weight
(eps = 1e-8 MPa/mm^2 times the displacement): over the body it carries a
force eps |Omega| |u_y|, some 1e-10 of the load here.
"""

import contextlib
import json
import resource
import sys
import time

import numpy as np
import getfem as gf


def lame(E, nu):
    """Lame constants (GetFEM's elasticity brick: plane strain in 2D)."""
    return E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))


def boundary_faces(mesh, keep):
    """Outer faces (2 x n array: convex, face) whose vertices all satisfy
    keep(x, y) (2D) or keep(x, y, z) (3D)."""
    faces = mesh.outer_faces()
    chosen = []
    for j in range(faces.shape[1]):
        xyz = mesh.pts(mesh.pid_in_faces(faces[:, j:j + 1]))
        if all(keep(*xyz[:, k]) for k in range(xyz.shape[1])):
            chosen.append(j)
    return faces[:, chosen]


def region_faces(mesh, region):
    """The vertex coordinates (dim x dim) of every face of region."""
    faces = mesh.region(region)
    return [mesh.pts(mesh.pid_in_faces(faces[:, j:j + 1]))
            for j in range(faces.shape[1])]


def nearest_faces(points, faces):
    """For each point (column of points), the vertex columns of the face
    of faces (a list of dim x dim arrays: segments in 2D, triangles in 3D)
    nearest to it."""
    xyz = np.array(faces)                      # faces x dim x vertices
    chosen = []
    for p in points.T:
        if xyz.shape[2] == 2:
            dist = point_segment_distances(p, xyz[:, :, 0], xyz[:, :, 1])
        else:
            dist = point_triangle_distances(p, xyz)
        chosen.append(faces[int(np.argmin(dist))])
    return chosen


def point_segment_distances(p, a, b):
    """Distances of the point p from the segments a[k]-b[k] (rows)."""
    d = b - a
    t = np.clip(((p - a) * d).sum(1) / (d * d).sum(1), 0.0, 1.0)
    return np.linalg.norm(p - a - t[:, None] * d, axis=1)


def point_triangle_distances(p, xyz):
    """Distances of the point p from the triangles of vertex columns
    xyz[k] (3 x 3): the distance to the plane where p projects inside the
    triangle, otherwise to the nearest edge."""
    a, b, c = xyz[:, :, 0], xyz[:, :, 1], xyz[:, :, 2]
    n = np.cross(b - a, c - a)
    n /= np.linalg.norm(n, axis=1)[:, None]
    height = ((p - a) * n).sum(1)
    q = p - height[:, None] * n
    inside = np.ones(len(a), dtype=bool)
    for u, v in ((a, b), (b, c), (c, a)):
        inside &= (np.cross(v - u, q - u) * n).sum(1) >= 0
    edges = np.min([point_segment_distances(p, u, v)
                    for u, v in ((a, b), (b, c), (c, a))], axis=0)
    return np.where(inside, np.abs(height), edges)


def face_measure(xyz):
    """Length (2D) or area (3D) of a face given by its vertex columns."""
    if xyz.shape[0] == 2:
        return float(np.hypot(*(xyz[:, 1] - xyz[:, 0])))
    return 0.5 * float(np.linalg.norm(
        np.cross(xyz[:, 1] - xyz[:, 0], xyz[:, 2] - xyz[:, 0])))


class ElasticBody:
    """P1 displacement `u` (or another name) on mesh, Lame data, and, for a
    body held by contact only, the rigid-motion mass term. Several bodies
    share one GetFEM model when `model` is given."""

    def __init__(self, mesh, E, nu, model=None, name="u", held=False):
        self.mesh, self.name = mesh, name
        self.dim = mesh.dim()
        self.mfu = gf.MeshFem(mesh, self.dim)
        self.mfu.set_classical_fem(1)
        self.mim = gf.MeshIm(mesh, 2)
        self.md = model if model is not None else gf.Model("real")
        self.md.add_fem_variable(name, self.mfu)
        lam, mu = lame(E, nu)
        self.md.add_initialized_data(f"lambda_{name}", [lam])
        self.md.add_initialized_data(f"mu_{name}", [mu])
        self.md.add_isotropic_linearized_elasticity_brick(
            self.mim, name, f"lambda_{name}", f"mu_{name}")
        if not held:
            self.md.add_initialized_data(f"eps_{name}", [1e-8])
            self.md.add_mass_brick(self.mim, name, f"eps_{name}")

    def symmetry(self, region):
        """Normal displacement zero on region (a symmetry plane), by
        multipliers."""
        self.md.add_normal_Dirichlet_condition_with_multipliers(
            self.mim, self.name, 1, region)

    def fixed(self, region):
        """u = 0 on region, by multipliers."""
        self.md.add_Dirichlet_condition_with_multipliers(
            self.mim, self.name, 1, region)

    def traction(self, region, vector):
        """A constant traction (MPa) on region."""
        data = f"t_{self.name}_{region}"
        self.md.add_initialized_data(data, list(vector))
        self.md.add_source_term_brick(self.mim, self.name, data, region)

    def point_force(self, point, component, value):
        """A force on the component of the node nearest to point."""
        nodes = self.mfu.basic_dof_nodes()
        dist = sum((nodes[k] - point[k]) ** 2 for k in range(self.dim))
        dofs = range(component, self.mfu.nbdof(), self.dim)
        load = np.zeros(self.mfu.nbdof())
        load[min(dofs, key=lambda d: dist[d])] = value
        self.md.add_explicit_rhs(self.name, load)

    def _multipliers(self, region, r, mu):
        cdof = self.mfu.dof_on_region(region)
        self.contact_dofs = cdof[1::self.dim]
        self.contact_region = region
        n = len(self.contact_dofs)
        self.md.add_variable("lambda_n", n)
        self.md.add_initialized_data("r", [r])
        if mu > 0:
            self.md.add_variable("lambda_t", n * (self.dim - 1))
            self.md.add_initialized_data("friction", [mu])
            return ["lambda_n", "lambda_t", "r", "friction"]
        return ["lambda_n", "r"]

    def contact(self, region, r, mu=0.0):
        """Nodal Signorini contact on region with the plane y = 0 (signed
        distance y), augmentation r (MPa); with mu > 0, Coulomb friction
        (static: the tangential multipliers against the total tangential
        displacement, the one-step problem dpana solves)."""
        names = self._multipliers(region, r, mu)
        self.md.add_nodal_contact_with_rigid_obstacle_brick(
            self.mim, self.name, *names, region, "y", 1)

    def contact_with(self, other, region, other_region, r, mu=0.0):
        """Nodal contact of this body's nodes on region (the slave side)
        with the faces of other on other_region (the master side), by
        GetFEM's brick for non-matching meshes (the slave nodes are
        projected on the master faces), which makes its multipliers itself.
        With friction, GetFEM 5.4's interface reads the name of the
        tangential multiplier twice for two displacement variables (given
        once, it takes the next names one place off and Newton fails);
        checked: with E2 = 1000 E1 it reproduces the rigid plane."""
        cdof = self.mfu.dof_on_region(region)
        self.contact_dofs = cdof[1::self.dim]
        self.contact_region = region
        self.md.add_initialized_data("r", [r])
        names = ["lambda_n", "r"]
        if mu > 0:
            self.md.add_initialized_data("friction", [mu])
            names = ["lambda_n", "lambda_t", "lambda_t", "r", "friction"]
        self.md.add_nodal_contact_between_nonmatching_meshes_brick(
            self.mim, other.mim, self.name, other.name, *names, region,
            other_region)
        self.master_directions(other, other_region, mu > 0)

    def master_directions(self, other, other_region, friction):
        """The multipliers of the brick between non-matching meshes act
        along the normal (and in 2D the tangent) of the master face onto
        which the slave node projects, in the reference configuration. For
        the force along the contact direction y, which dpana's N measures,
        keep per slave node |n_y| of that face and, in 2D with friction,
        t_y of its tangent t (oriented with t_x > 0): F_y = |lambda_n| |n_y|
        - lambda_t t_y. Both are checked by the resultant: on the curved
        cavity (|n_y| down to 0.99) the F_y carry the load to 1e-9, the
        |lambda_n| 2e-3 more. On a flat master n_y = 1 and t_y = 0 exactly.
        In 3D the tangential multipliers' part is left out (their basis is
        GetFEM's); the resultant then shows its size."""
        nodes = self.mfu.basic_dof_nodes(self.contact_dofs)
        faces = nearest_faces(nodes, region_faces(other.mesh, other_region))
        normal_y, tangent_y = [], []
        for xyz in faces:
            if xyz.shape[1] == 2:
                t = xyz[:, 1] - xyz[:, 0]
                t = t / np.linalg.norm(t) * (1 if t[0] > 0 else -1)
                normal_y.append(abs(t[0]))
                tangent_y.append(t[1])
            else:
                n = np.cross(xyz[:, 1] - xyz[:, 0], xyz[:, 2] - xyz[:, 0])
                normal_y.append(abs(n[1]) / np.linalg.norm(n))
        self.normal_y = np.array(normal_y)
        self.tangent_y = (np.array(tangent_y)
                          if friction and self.dim == 2 else None)

    def solve(self, residual, max_iter=100):
        # MUMPS, GetFEM's direct solver, on every level, as dpana factors
        # on every level: GetFEM's default is MUMPS below 250 000 unknowns
        # in 3D (300 000 in 2D) and GMRES with an ILU preconditioner
        # above, which would change the method within a sweep.
        nit, converged = self.md.solve("max_res", residual, "max_iter",
                                       max_iter, "lsearch", "default",
                                       "lsolver", "mumps")
        return int(nit), bool(converged)

    def record(self, nit, converged, dofs=None, **extra):
        """The record of a solved level: sizes, Newton iterations, extra
        entries and the quantities of pressure_quantities()."""
        record = {"dofs": int(self.mfu.nbdof() if dofs is None else dofs),
                  "contact_unknowns": len(self.contact_dofs),
                  "iterations": nit, "converged": converged, **extra}
        record.update(pressure_quantities(*self.nodal_pressures()))
        return record

    def nodal_pressures(self):
        """Contact nodes (coordinates, dim x n), the nodal force F >= 0 (N/mm
        in 2D, N in 3D; between two bodies its part along y, see
        master_directions()) and the pressure p = F / (the tributary length or
        area: half of each adjacent contact face in 2D, a third in 3D)."""
        lam = np.asarray(self.md.variable("lambda_n")).ravel()
        force = np.abs(lam)
        if getattr(self, "normal_y", None) is not None:
            force = force * self.normal_y
            if self.tangent_y is not None:
                force -= (np.asarray(self.md.variable("lambda_t")).ravel()
                          * self.tangent_y)
        nodes = self.mfu.basic_dof_nodes(self.contact_dofs)
        faces = self.mesh.region(self.contact_region)
        tributary = {}
        for j in range(faces.shape[1]):
            xyz = self.mesh.pts(self.mesh.pid_in_faces(faces[:, j:j + 1]))
            share = face_measure(xyz) / xyz.shape[1]
            for k in range(xyz.shape[1]):
                key = tuple(round(c, 9) for c in xyz[:, k])
                tributary[key] = tributary.get(key, 0.0) + share
        trib = np.array([tributary[tuple(round(c, 9) for c in node)]
                         for node in nodes.T])
        return nodes, force, force / trib


def pressure_quantities(nodes, force, p):
    """From the contact nodes: N_max, N_first (the node nearest the origin,
    on the symmetry axis), the resultant, the half width at node
    resolution (the farthest node that carries a force, in x in 2D, in
    r = (x^2 + z^2)^1/2 in 3D), the moment estimate (2D: a_m = 2 (sum F x^2
    / sum F)^1/2; 3D: a_m = (5/2 sum F r^2 / sum F)^1/2), each exact for
    the elliptic Hertz law, and the pressure centroid in x, x_p = sum F x /
    sum F."""
    total = force.sum()
    r = np.abs(nodes[0]) if len(nodes) == 2 else np.hypot(nodes[0], nodes[2])
    active = force > 1e-12 * total
    q = {"N_max": float(p.max()),
         "N_first": float(p[np.argmin(np.hypot(r, nodes[1]))]),
         "resultant": float(total),
         "a": float(r[active].max())}
    moment = (force * r * r).sum() / total
    if len(nodes) == 2:
        q["a_m"] = float(2 * np.sqrt(moment))
    else:
        q["a_m"] = float(np.sqrt(2.5 * moment))
    q["x_p"] = float((force * np.abs(nodes[0])).sum() / total)
    return q


_MESH_TIME = [0.0]


@contextlib.contextmanager
def meshing():
    """Times what it encloses, the making of a mesh and of its regions
    (gmsh import or GetFEM's own grid, boundary regions), as mesh time: the
    solve time of both codes runs from a mesh in memory to the answers
    (dpana's mesh phase, generation or reading and refinement with its
    boundary ids, is left out of its solve time too)."""
    start = time.perf_counter()
    try:
        yield
    finally:
        _MESH_TIME[0] += time.perf_counter() - start


def emit(record, start):
    """Adds the time since start without the mesh time (the GetFEM work:
    assembly, solve and post-processing), the mesh time and the peak
    memory, and prints the record as one JSON line. The peak memory is the
    process's peak resident set (getrusage's ru_maxrss, KiB on Linux) in MB
    of 2^20 bytes, the measure of dpana's summary.json: for both codes with
    the interpreter or the libraries loaded."""
    record["mesh_time"] = _MESH_TIME[0]
    record["solve_time"] = time.perf_counter() - start - _MESH_TIME[0]
    record["peak_memory_mb"] = \
        resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    json.dump(record, sys.stdout)
    print()
