"""Meshes of the Hertz cylinder for the GetFEM harness, made by gmsh.

Two bodies, both the half x >= 0 of a cylinder of radius R whose lowest
point (0, 0) touches the plane y = 0 (centre (0, R)):
  circle  the half of the full circular body, the body of the reference
          formulation; its edge on the axis runs from (0, 0) to (0, 2R);
  dshape  the lower half of that half, the quarter disc below the centre
          (the body of dpana's hertz_rigid_mu0_d_shaped scene); its edges
          are the axis (0, 0)-(0, R) and the flat side y = R.
And the elastic foundations of the two-body Hertz scenes:
  block   the square [0, 2R] x [-2R, 0] below the contact point (the half
          of the 4R x 2R foundation);
  cavity  the body with the cylindrical cavity of prm/hertz_cavity_*: the
          lower right quarter of the ring 3R <= r <= 9R around (0, 3R),
          whose inner circle touches the cylinder at (0, 0); its edges are
          the axis x = 0 below the contact point and the cut y = 3R.
Element size h_c within the distance rho of the contact point, growing
linearly to h_far at the distance 2 rho (gmsh Distance and Threshold
fields), P1 triangles.
"""

import os
import subprocess

GEO = """// {body}: half cylinder x >= 0 of radius {R} touching y = 0 at (0, 0)
R = {R};
Point(1) = {{0, 0, 0}};
Point(2) = {{0, R, 0}};
Point(3) = {{R, R, 0}};
Point(4) = {{0, 2 * R, 0}};
Circle(1) = {{1, 2, 3}};
{outline}
Field[1] = Distance;
Field[1].PointsList = {{1}};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = {hc};
Field[2].SizeMax = {hfar};
Field[2].DistMin = {rho};
Field[2].DistMax = {rho2};
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.Algorithm = 6;
Mesh.MshFileVersion = 2.2;
"""

OUTLINES = {
    # arc (0,0)-(R,R), arc (R,R)-(0,2R), axis (0,2R)-(0,R)-(0,0)
    "circle": """Circle(2) = {3, 2, 4};
Line(3) = {4, 2};
Line(4) = {2, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface(1) = {1};""",
    # arc (0,0)-(R,R), flat side (R,R)-(0,R), axis (0,R)-(0,0)
    "block": """Point(5) = {2 * R, 0, 0};
Point(6) = {2 * R, -2 * R, 0};
Point(7) = {0, -2 * R, 0};
Line(2) = {1, 5};
Line(3) = {5, 6};
Line(4) = {6, 7};
Line(5) = {7, 1};
Curve Loop(1) = {2, 3, 4, 5};
Plane Surface(1) = {1};
Physical Surface(1) = {1};""",
    # inner arc (0,0)-(3R,3R), cut (3R,3R)-(9R,3R), outer arc (9R,3R)-
    # (0,-6R), axis (0,-6R)-(0,0); all around the centre (0, 3R)
    "cavity": """Point(5) = {0, 3 * R, 0};
Point(6) = {3 * R, 3 * R, 0};
Point(7) = {9 * R, 3 * R, 0};
Point(8) = {0, -6 * R, 0};
Circle(2) = {1, 5, 6};
Line(3) = {6, 7};
Circle(4) = {7, 5, 8};
Line(5) = {8, 1};
Curve Loop(1) = {2, 3, 4, 5};
Plane Surface(1) = {1};
Physical Surface(1) = {1};""",
    "dshape": """Line(2) = {3, 2};
Line(4) = {2, 1};
Curve Loop(1) = {1, 2, 4};
Plane Surface(1) = {1};
Physical Surface(1) = {1};""",
}


def hertz_mesh(body, radius, hc, hfar, rho, directory):
    """Writes and meshes the .geo of body; returns the path of the .msh."""
    if body not in OUTLINES:
        raise ValueError(f"unknown body '{body}' "
                         f"({', '.join(OUTLINES)})")
    geo = os.path.join(directory, f"{body}.geo")
    msh = os.path.join(directory, f"{body}.msh")
    with open(geo, "w") as f:
        f.write(GEO.format(body=body, R=radius, outline=OUTLINES[body],
                           hc=hc, hfar=hfar, rho=rho, rho2=2 * rho))
    subprocess.run(["gmsh", "-2", "-v", "1", geo, "-o", msh], check=True,
                   stdout=subprocess.DEVNULL)
    return msh
