// The body with the cylindrical cavity of dpana's 2D Hertz scenes
// (prm/hertz_cavity_*), graded: the lower right quarter of the ring
// 3R <= r <= 9R around (0, 3R), whose inner circle touches the circular
// body of disc.geo at its lowest point (0, 0); the companion of disc.geo.
// Linear triangles, written in the ASCII format 2.2 that dpana's `gmsh`
// geometry reads.
//
// Its inner circle near the contact point is divided at the projections,
// along the contact direction (0, -1), of the vertices of disc.geo's arc at
// the same level: the points of the inner circle with x = R sin(k dphi),
// dphi = 45 deg / 2^(Level + 5), k = 0 ... Arc / dphi. Below every chord of
// the disc lies one face of the cavity, so that the mortar projection of
// the two-body scenes pairs each face of the candidate surface with one
// face of the cavity (up to slivers of 3e-8 mm: gmsh places the vertices
// of disc.geo's arc by its numerically integrated length). Elsewhere the
// element size grows with the distance from the contact point as in
// disc.geo and in the gmsh meshes of the GetFEM harness of
// benchmarks/convergence.
//
// Parameters (gmsh -setnumber NAME VALUE; lengths in mm), those of
// disc.geo:
//   R        radius of the circular body (the cavity's radius is 3R, the
//            ring's outer radius 9R)
//   Level    refinement level, as in disc.geo
//   Arc      the inner circle is divided as the disc's arc is within this
//            angle (deg) of the disc's lowest point: up to x = R sin(Arc)
//   Rho      element size h_c = (pi R / 4) / 2^(Level + 5) within this
//            distance of the contact point ...
//   Growth   ... growing linearly to Growth h_c (at most R / 4) at 2 Rho
//
// Named boundaries (physical curves): inner (the cavity), outer (r = 9R),
// x_axis (the cut y = 3R), y_axis (the symmetry line x = 0), the names of
// dpana's `quarter annulus`; physical surface: body.
//
// Run through scripts/meshes/make_disc.py --body cavity, e.g.
//   gmsh -2 -setnumber Level 2 cavity.geo -o cavity.msh

DefineConstant[ R = 40, Level = 0, Arc = 22.5, Rho = 14, Growth = 32 ];

hc   = (Pi * R / 4) / 2^(Level + 5);
hfar = Min(Growth * hc, R / 4);
nArc = Round(Arc / (45 / 2^(Level + 5)));
dphi = (45 / 2^(Level + 5)) * Pi / 180;

// The contact point, the centre of the ring, the ends of the cut and of
// the axis; the inner circle's vertices below the arc's: point 100 + k at
// x = R sin(k dphi) on the circle of radius 3R, k = 1 ... nArc.
Point(1) = {0, 0, 0};
Point(2) = {0, 3 * R, 0};
Point(3) = {3 * R, 3 * R, 0};
Point(4) = {9 * R, 3 * R, 0};
Point(5) = {0, -6 * R, 0};
For k In {1 : nArc}
  x = R * Sin(k * dphi);
  Point(100 + k) = {x, 3 * R - Sqrt(9 * R * R - x * x), 0};
EndFor

// The inner circle: one arc per chord of the disc (one element each), then
// the rest of it to the cut; the cut, the outer circle, the axis.
Circle(101) = {1, 2, 101};
For k In {2 : nArc}
  Circle(100 + k) = {99 + k, 2, 100 + k};
EndFor
Transfinite Curve{101 : 100 + nArc} = 2;
Circle(1) = {100 + nArc, 2, 3};
Line(2)   = {3, 4};
Circle(3) = {4, 2, 5};
Line(4)   = {5, 1};
Curve Loop(1) = {101 : 100 + nArc, 1, 2, 3, 4};
Plane Surface(1) = {1};

Physical Curve("inner", 1)  = {101 : 100 + nArc, 1};
Physical Curve("x_axis", 2) = {2};
Physical Curve("outer", 3)  = {3};
Physical Curve("y_axis", 4) = {4};
Physical Surface("body", 10) = {1};

Field[1] = Distance;
Field[1].PointsList = {1};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hc;
Field[2].SizeMax = hfar;
Field[2].DistMin = Rho;
Field[2].DistMax = 2 * Rho;
Background Field = 2;

Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.Algorithm = 6;
Mesh.ElementOrder = 1;
Mesh.MshFileVersion = 2.2;
Mesh.Binary = 0;
Mesh.SaveAll = 0;
