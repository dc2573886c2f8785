"""The scene families of the convergence sweeps: one entry per family.

A family is a scene file of prm/ and its refinement levels. A level is a
mesh size h (any length proportional to the element size on the contact
surface: only ratios of h enter the extrapolation) and the entries of the
scene file it changes. `levels` is the default sweep (its finest level takes
about a minute of dpana time or less on a 2-core machine); `full` adds finer
levels for `--full`.

`quantities` are the answers that are tabulated and extrapolated (see
quantities.py); `plot` the ones drawn in the speed-against-error plots,
the first in the plot of all families (the pressure centroid for the two
bodies, whose N_max sits on a singular edge).
`exact` gives the exact value of a quantity where the problem has one; the
others are measured against their Richardson-extrapolated value. `hertz`
marks the scenes whose summary carries the Hertz formulas, shown next to
the extrapolated a, a_m and N_max: the plane ones of the cylinder (Hertz
assumes a << R; here a/R is 0.2-0.4, so the converged answer need not
equal it), the 3D ones of the spheres (a/R = 0.10; N_max against p0).
`uniform` is the exact uniform normal traction of a scene that has one.

Adding a family (the circular Hertz body, the 3D sphere, ...) is one more
entry below.
"""

import os
import subprocess
import tempfile
from dataclasses import dataclass, field


@dataclass
class Family:
    name: str
    prm: str
    dim: int
    levels: list          # [(h, {entry path: value})], coarse to fine
    full: list = field(default_factory=list)
    quantities: tuple = ("N_max", "N_first", "resultant")
    plot: tuple = ("N_max",)
    exact: dict = field(default_factory=dict)
    hertz: bool = False
    uniform: float = None
    note: str = ""
    # how the tables name a value of exact that is not exact (default
    # "exact"), e.g. a limit computed apart
    exact_label: dict = field(default_factory=dict)
    # The Hertz values {"a": ..., "N_max": ...} of a family with hertz set
    # whose records do not carry them (sweeps from before the records
    # kept the 3D Hertz reference of the spheres).
    hertz_values: dict = None


def rectangle(n, body="Body 1"):
    return {f"{body}/Geometry/Rectangle/Subdivisions": f"{n}, {n}"}


def receding_2d(ns):
    """The half block 40 x 40: n x n squares, 2 triangles each (along the
    alternating diagonals that the scene files set); h = 40/n."""
    return [(40.0 / n, rectangle(n)) for n in ns]


def receding_3d(ks):
    """The quarter block 40 x 40 x 40: k x k/2 x k bricks of 5 tetrahedra."""
    return [(40.0 / k, {"Body 1/Geometry/Box/Subdivisions":
                        f"{k}, {k // 2}, {k}"}) for k in ks]


def two_body(ns):
    """Block n x n on the foundation 2n x 2n: equal element sizes on the
    contact surface, h = 40/n."""
    return [(40.0 / n, {**rectangle(n), **rectangle(2 * n, "Body 2")})
            for n in ns]


class SphereMesh:
    """The gmsh mesh of the quarter sphere of the 3D Hertz scenes at one
    level (scripts/meshes/make_sphere.py --level L: element sizes
    2^(-L/2) times those of sphere.geo). path() writes it, once, into a
    cache directory and returns its absolute path; its making is not
    timed (dpana reads it in its assembly phase)."""

    script, stem = "make_sphere.py", "sphere"

    def __init__(self, level, *options):
        self.level, self.options = level, list(options)

    def path(self, prm_dir):
        cache = os.path.join(tempfile.gettempdir(), "dpana_convergence_meshes")
        os.makedirs(cache, exist_ok=True)
        name = "_".join([self.stem, f"L{self.level}"] + [
            o.replace("=", "").replace("-", "") for o in self.options])
        out = os.path.join(cache, name + ".msh")
        script = os.path.join(prm_dir, "..", "scripts", "meshes",
                              self.script)
        subprocess.run(["python3", script, out, "--level", str(self.level)]
                       + self.options, check=True, stdout=subprocess.DEVNULL)
        return out


class DiscMesh(SphereMesh):
    """The graded gmsh mesh of the 2D circular body at one level
    (scripts/meshes/make_disc.py --level L: the arc near the contact point
    divided as the right half disc with L global and 5 contact refinements
    divides it, the size growing away from it as in the GetFEM harness's
    meshes), cached and untimed as the sphere's."""

    script, stem = "make_disc.py", "disc"


def graded_pair(disc, other, first=0):
    """Both bodies of a 2D Hertz pair on graded gmsh meshes (make_disc.py),
    the disc with the options disc, the other body with other: levels
    g = first ... 4 and the --full level 5, h = 2^(-g). Returns (levels,
    full)."""
    def level(g):
        return (2.0 ** -g, {"Body 1/Geometry/Gmsh/Mesh file":
                            DiscMesh(g, *disc),
                            "Body 2/Geometry/Gmsh/Mesh file":
                            DiscMesh(g, *other)})
    return [level(g) for g in range(first, 5)], [level(5)]


# How a family's note names its friction.
FRICTION = {"mu0": "", "mu1": ", mu = 1"}


def sphere(levels, bodies=(("Body 1", ()),)):
    """Quarter spheres at make_sphere.py levels L: h = 2^(-L/2)."""
    return [(2.0 ** (-level / 2), {
        f"{body}/Geometry/Gmsh/Mesh file": SphereMesh(level, *options)
        for body, options in bodies}) for level in levels]


def nested_sphere(refinements, bodies=(("Body 1", ()),), entries=(),
                  base=-2):
    """The quarter spheres' meshes of make_sphere.py level `base`, split k
    times into 8 (--refine k): one nested mesh family, in which every
    region of the body is refined with the contact cap. h = 2^(-base/2 - k),
    the h of the level family at the same element size on the cap.
    `entries`: more (path, value) entries of every level."""
    return [(2.0 ** (-base / 2 - k), {
        **{f"{body}/Geometry/Gmsh/Mesh file":
           SphereMesh(base, *options, "--refine", str(k))
           for body, options in bodies},
        **dict(entries)}) for k in refinements]


def contact_refinements(ms, body="Body 1", shape="Right half disc"):
    """Coarser levels: no global refinement, m < 5 contact refinements;
    h = 2^(5 - m) in the units of global_refinements()."""
    return [(2.0 ** (5 - m), {f"{body}/Geometry/Global refinements": "0",
                              f"{body}/Geometry/{shape}/Contact refinements":
                              str(m)}) for m in ms]


def disc_meshes(levels, body="Body 1"):
    """The graded disc at make_disc.py levels L: h = 2^-L, the h of the
    right half disc with the same chords on the candidate surface."""
    return [(2.0 ** -level, {f"{body}/Geometry/Gmsh/Mesh file":
                             DiscMesh(level)}) for level in levels]


def global_refinements(gs, bodies=("Body 1",)):
    """Every cell of the graded meshes halved once per level: h = 2^-g."""
    return [(2.0 ** -g, {f"{b}/Geometry/Global refinements": str(g)
                         for b in bodies}) for g in gs]


HERTZ_Q = ("N_max", "a_m", "a", "resultant")
BLOCK_Q = ("N_max", "N_first", "x_p", "a", "resultant")
TWO = ("Body 1", "Body 2")

FAMILIES = [
    Family("receding_2d_mu0", "receding_2d_mu0.prm", 2,
           receding_2d([4, 8, 16, 32, 64, 128]), receding_2d([256, 512]),
           quantities=("N_max", "uniform_error", "resultant"),
           exact={"N_max": 50.0, "uniform_error": 0.0, "resultant": 2000.0},
           uniform=-50.0,
           note="exact uniform state N = -50 MPa: P1 elements reproduce it"),
    Family("receding_2d_mu1", "receding_2d_mu1.prm", 2,
           receding_2d([4, 8, 16, 32, 64, 128]), receding_2d([256, 512]),
           quantities=BLOCK_Q, plot=("N_max", "x_p"),
           exact={"resultant": 2000.0}),
    Family("receding_3d_L80", "receding_3d_L80.prm", 3,
           receding_3d([4, 8, 12, 16, 24, 32]), receding_3d([48]),
           quantities=("N_max", "N_first", "x_p", "resultant"),
           plot=("x_p", "N_max", "N_first"),
           # With nu = 0 the plane solution solves the 3D problem: its
           # pressure at the axis, 83.31 MPa, from fine plane meshes of both
           # codes (dpana n = 128 ... 512, GetFEM n = 32 ... 128, each
           # extrapolated; README.md), within about 1e-4; its pressure
           # centroid, 13.7429 mm (prm/receding_2d_nu0_mu1.prm: dpana
           # 13.742974, 13.743025, 13.742963 at n = 128, 256, 512; GetFEM
           # 13.743115, 13.742903 at n = 64, 128), within about 1e-5.
           exact={"N_max": 83.31, "N_first": 83.31, "x_p": 13.7429,
                  "resultant": 80000.0},
           exact_label={"N_max": "plane limit", "N_first": "plane limit",
                        "x_p": "plane limit"},
           note="N_max, N_first and x_p against the plane limits 83.31 MPa "
                "and 13.7429 mm (nu = 0: the plane solution is the 3D one), "
                "computed apart"),
    Family("two_body_ratio_1", "two_body_ratio_1.prm", 2,
           two_body([4, 8, 16, 32, 64, 128]), two_body([256]),
           quantities=BLOCK_Q, plot=("x_p", "N_max"),
           exact={"resultant": 2000.0}),
    Family("two_body_ratio_1e-3", "two_body_ratio_1e-3.prm", 2,
           two_body([4, 8, 16, 32, 64, 128]), two_body([256]),
           quantities=BLOCK_Q, plot=("x_p", "N_max"),
           exact={"resultant": 2000.0}),
    Family("two_body_ratio_1e3", "two_body_ratio_1e3.prm", 2,
           two_body([4, 8, 16, 32, 64, 128]), two_body([256]),
           quantities=BLOCK_Q, plot=("x_p", "N_max"),
           exact={"resultant": 2000.0}),
]

for mu in ("mu0", "mu1"):
    FAMILIES.append(Family(
        f"hertz_rigid_{mu}", f"hertz_rigid_{mu}.prm", 2,
        contact_refinements([3, 4]) + global_refinements(range(0, 6)),
        global_refinements([6]),
        quantities=HERTZ_Q, plot=("N_max", "a_m"),
        exact={"resultant": 100000.0}, hertz=True,
        note="Circular body (right half disc), force at the far pole"))
# The same scenes on the graded gmsh mesh of the disc (scripts/meshes/
# make_disc.py): the same faces on the candidate surface at each h, the
# element size growing from 14 mm on as in GetFEM's meshes, so that both
# codes solve about the same number of unknowns.
for mu in ("mu0", "mu1"):
    FAMILIES.append(Family(
        f"hertz_rigid_{mu}_graded", f"hertz_rigid_{mu}_graded.prm", 2,
        disc_meshes(range(-2, 6)), disc_meshes([6]),
        quantities=HERTZ_Q, plot=("N_max", "a_m"),
        exact={"resultant": 100000.0}, hertz=True,
        note="Circular body (right half disc), force at the far pole; "
             "graded gmsh mesh"))
# The same scene on a leaner mesh: contact refinements within 10 mm of the
# contact point instead of 14 (a = 8.6 mm), the same contact elements in
# the contact zone with half the dofs (GetFEM's meshes are refined within
# 14 mm, but grade away from it, where dpana's disc stays uniform).
R10 = {"Body 1/Geometry/Right half disc/Contact refinement radius": "10"}
FAMILIES.append(Family(
    "hertz_rigid_mu0_r10", "hertz_rigid_mu0.prm", 2,
    [(h, {**e, **R10}) for h, e in
     contact_refinements([3, 4]) + global_refinements(range(0, 6))],
    [(h, {**e, **R10}) for h, e in global_refinements([6])],
    quantities=HERTZ_Q, plot=("N_max", "a_m"),
    exact={"resultant": 100000.0}, hertz=True,
    note="Circular body (right half disc), force at the far pole; contact "
         "refinement radius 10 mm instead of 14"))
FAMILIES.append(Family(
    "hertz_rigid_mu0_d_shaped", "hertz_rigid_mu0_d_shaped.prm", 2,
    contact_refinements([3, 4], shape="Quarter disc")
    + global_refinements(range(0, 6)), global_refinements([6]),
    quantities=HERTZ_Q, plot=("N_max", "a_m"),
    exact={"resultant": 100000.0}, hertz=True,
    note="D-shaped body (quarter disc below the centre), force at the "
         "centre"))
# The disc on the graded block one level below global_refinements(0):
# one contact refinement fewer for the disc, half the subdivisions of the
# block (contact faces of 1.96 mm, h = 2), as GetFEM's level -1 paired with
# it. On level 0 both codes are often within 1 % already, and then neither
# time is known.
COARSER_PAIR = (2.0, {"Body 1/Geometry/Global refinements": "0",
                      "Body 1/Geometry/Right half disc/Contact refinements":
                      "4",
                      "Body 2/Geometry/Global refinements": "0",
                      "Body 2/Geometry/Rectangle/Subdivisions": "16, 16"})
for ratio in ("1", "1e-3", "1e3"):
    for mu in ("mu0", "mu1"):
        FAMILIES.append(Family(
            f"hertz_ratio_{ratio}_{mu}", f"hertz_ratio_{ratio}_{mu}.prm", 2,
            [COARSER_PAIR] + global_refinements(range(0, 5), TWO),
            global_refinements([5], TWO),
            quantities=HERTZ_Q, plot=("N_max", "a_m"),
            exact={"resultant": 100000.0}, hertz=True,
            note="Circular body on a graded elastic block"))
# The equal-moduli pair with the disc on its graded gmsh mesh (refined
# within the scene's 17 mm, the arc divided as the generator's within
# 28.125 deg, beyond the candidate surface's 16 mm); the foundation's grid
# is the scene's.
RHO17 = ("--set", "Rho=17", "--set", "Arc=28.125")
# Its first level g = -1 pairs the disc's level -1 with the foundation of
# COARSER_PAIR, as GetFEM's level -1.
COARSER_BLOCK = {k: v for k, v in COARSER_PAIR[1].items()
                 if k.startswith("Body 2/")}
FAMILIES.append(Family(
    "hertz_ratio_1_mu0_graded", "hertz_ratio_1_mu0_graded.prm", 2,
    [(2.0, {"Body 1/Geometry/Gmsh/Mesh file": DiscMesh(-1, *RHO17),
            **COARSER_BLOCK})]
    + [(2.0 ** -g, {"Body 1/Geometry/Gmsh/Mesh file": DiscMesh(g, *RHO17),
                    "Body 2/Geometry/Global refinements": str(g)})
       for g in range(0, 5)],
    [(2.0 ** -5, {"Body 1/Geometry/Gmsh/Mesh file": DiscMesh(5, *RHO17),
                  "Body 2/Geometry/Global refinements": "5"})],
    quantities=HERTZ_Q, plot=("N_max", "a_m"),
    exact={"resultant": 100000.0}, hertz=True,
    note="Circular body (graded gmsh mesh) on a graded elastic block"))
# The same pair with the foundation on a graded gmsh mesh too
# (make_disc.py --body block: its top face divided at the projections of
# the disc's vertices, the size field of the disc elsewhere), both bodies
# meshed as GetFEM's.
BLOCK17 = ("--body", "block") + RHO17
# The same meshes for the rigid punch (E1/E2 = 1e3) and the stiff
# foundation (E1/E2 = 1e-3), frictionless and with mu = 1. They start one
# level coarser (g = -1), as GetFEM's sweeps paired with them: on level 0
# both codes are often within 1 % already, and then neither time is known.
for ratio, mu, what in (
        (r, m, w) for r, w in (("1", "an elastic block"),
                               ("1e3", "a soft block"),
                               ("1e-3", "a stiff block"))
        for m in ("mu0", "mu1")):
    FAMILIES.append(Family(
        f"hertz_ratio_{ratio}_{mu}_graded_block",
        f"hertz_ratio_{ratio}_{mu}_graded_block.prm", 2,
        *graded_pair(RHO17, BLOCK17, first=-1),
        quantities=HERTZ_Q, plot=("N_max", "a_m"),
        exact={"resultant": 100000.0}, hertz=True,
        note=f"Circular body on {what}, both on graded gmsh meshes"
             + FRICTION[mu]))
for mu in ("mu0", "mu1"):
    FAMILIES.append(Family(
        f"hertz_cavity_{mu}", f"hertz_cavity_{mu}.prm", 2,
        global_refinements(range(0, 5), TWO), global_refinements([5], TWO),
        quantities=HERTZ_Q, plot=("N_max", "a_m"),
        exact={"resultant": 100000.0}, hertz=True,
        note="Circular body in a cavity R = 120"))
# The cavity scene with both bodies on graded gmsh meshes (make_disc.py
# --body cavity: the inner circle divided at the vertical projections of
# the disc's vertices), refined within the scene's 21 mm, the disc's arc
# divided as the generator's within 33.75 deg (the candidate surface's
# 20 mm lie within 30 deg).
RHO21 = ("--set", "Rho=21", "--set", "Arc=33.75")
CAVITY21 = ("--body", "cavity") + RHO21
for mu in ("mu0", "mu1"):
    FAMILIES.append(Family(
        f"hertz_cavity_{mu}_graded", f"hertz_cavity_{mu}_graded.prm", 2,
        *graded_pair(RHO21, CAVITY21),
        quantities=HERTZ_Q, plot=("N_max", "a_m"),
        exact={"resultant": 100000.0}, hertz=True,
        note="Circular body in a cavity R = 120, both on graded gmsh meshes"
             + FRICTION[mu]))
# The quantities of every sphere family; the contact carries the quarter
# sphere's P/4 = 75 kN exactly. 3D Hertz, shown next to the converged a_m
# and N_max: a = (3 P R (1 - nu^2) / (4 E))^(1/3), p0 = 3 P / (2 pi a^2),
# P = 300 kN (for two equal spheres the same a and p0).
SPHERE_Q = {"quantities": ("N_max", "a_m", "resultant"),
            "plot": ("N_max", "a_m"), "exact": {"resultant": 75000.0},
            "hertz": True,
            "hertz_values": {"a": 4.050638287, "N_max": 8730.02956}}
# The level families start at level -2, as GetFEM's sweeps paired with them:
# on level 0, and for the one sphere on level -1, both codes are within 1 %
# in a_m already, and then neither time to 1 % is known.
FAMILIES.append(Family(
    "hertz_sphere_rigid", "hertz_sphere_rigid.prm", 3,
    sphere(range(-2, 5)), sphere([5]),
    **SPHERE_Q,
    note="Quarter sphere R = 40 on a rigid plane, P = 300 kN (3D Hertz: "
         "a = 4.050 mm, p0 = 8730 MPa)"))
# The same sphere on nested meshes: the level-(-2) mesh split k times. The
# level family refines the cap but keeps the growth of the element size
# away from it (sphere.geo's Growth), so that the mesh a contact radius
# away hardly changes; the nested family refines it everywhere.
FAMILIES.append(Family(
    "hertz_sphere_rigid_nested", "hertz_sphere_rigid.prm", 3,
    nested_sphere(range(0, 3)),
    # 641 547 dofs: the blocked solves need 14 GB, the Schur route more.
    nested_sphere([3], entries=[("Contact/Condensation method",
                                 "blocked solves")]),
    **SPHERE_Q,
    note="Quarter sphere R = 40 on a rigid plane, P = 300 kN, on nested "
         "meshes (make_sphere.py --level -2 --refine k)"))
# The sphere's second nested family, one level coarser: level -3 split k
# times (1 320 to 420 543 dofs). Its finest level is the one on which
# GetFEM still fits this machine (about 11 GB), so that both codes have
# four nested levels.
FAMILIES.append(Family(
    "hertz_sphere_rigid_nested3", "hertz_sphere_rigid.prm", 3,
    nested_sphere(range(0, 3), base=-3),
    # 420 543 dofs: the blocked solves need 8.5 GB.
    nested_sphere([3], entries=[("Contact/Condensation method",
                                 "blocked solves")], base=-3),
    **SPHERE_Q,
    note="Quarter sphere R = 40 on a rigid plane, P = 300 kN, on nested "
         "meshes (make_sphere.py --level -3 --refine k)"))

# The two equal spheres: the upper one on dpana's sphere mesh, the lower one
# (the mirror image) on the mesh of the scene's mesh line
# (make_sphere.py --side -1 --set CapRadius=7.5), both at level L.
LOWER_SPHERE = ("--side", "-1", "--set", "CapRadius=7.5")
for name, mu in (("hertz_two_spheres", "frictionless"),
                 ("hertz_two_spheres_mu03", "mu = 0.3")):
    FAMILIES.append(Family(
        name, f"{name}.prm", 3,
        sphere(range(-2, 5), (("Body 1", ()), ("Body 2", LOWER_SPHERE))),
        sphere([5], (("Body 1", ()), ("Body 2", LOWER_SPHERE))),
        **SPHERE_Q,
        note=f"Two equal spheres R = 40, P = 300 kN, {mu} (3D Hertz as "
             "for one sphere on a rigid plane: a = 4.050 mm, "
             "p0 = 8730 MPa)"))
# The two frictionless spheres on nested meshes, both of level -2 split k
# times (k = 3: about 1.4 million dofs, two bodies the size of the one
# sphere's level 3, which alone took 14 GB).
FAMILIES.append(Family(
    "hertz_two_spheres_nested", "hertz_two_spheres.prm", 3,
    nested_sphere(range(0, 3), (("Body 1", ()), ("Body 2", LOWER_SPHERE))),
    **SPHERE_Q,
    note="Two equal spheres R = 40, P = 300 kN, frictionless, on nested "
         "meshes (make_sphere.py --level -2 --refine k)"))

# The 2D Hertz scenes on the rigid plane, the quarter sphere and the two
# spheres with patches around the vertices of the candidate surface
# (Contact / Contact elements = vertices: as many tractions as surface
# vertices) instead of groups of faces (two edges, eight triangles): the
# same scenes and meshes, one entry more at every level. GetFEM's records of a
# variant are those of its scene (getfem/sweep.py).
VERTICES = {"Contact/Contact elements": "vertices"}
VERTEX_VARIANTS = ("hertz_rigid_mu0", "hertz_rigid_mu1",
                   "hertz_rigid_mu0_graded", "hertz_rigid_mu1_graded",
                   "hertz_rigid_mu0_r10", "hertz_rigid_mu0_d_shaped",
                   "hertz_sphere_rigid", "hertz_two_spheres")


def vertex_variant(f):
    """Family f with patches around the vertices, named f.name + '_vertices'.
    """
    def patched(levels):
        return [(h, {**e, **VERTICES}) for h, e in levels]
    return Family(f.name + "_vertices", f.prm, f.dim, patched(f.levels),
                  patched(f.full), f.quantities, f.plot, dict(f.exact),
                  f.hertz, f.uniform,
                  f.note + "; patches around the vertices",
                  dict(f.exact_label), f.hertz_values)


FAMILIES += [vertex_variant(f) for f in list(FAMILIES)
             if f.name in VERTEX_VARIANTS]

BY_NAME = {f.name: f for f in FAMILIES}
