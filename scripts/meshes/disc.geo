// The circular body of dpana's 2D Hertz scenes, graded: the right half
// x >= 0 of the disc of radius R and centre (0, R), which touches the plane
// y = 0 at its lowest point (0, 0) and carries its load at the far end of
// its vertical diameter, (0, 2R). Linear triangles, written in the ASCII
// format 2.2 that dpana's `gmsh` geometry reads.
//
// The arc near the contact point is divided exactly as dpana's `right half
// disc` divides it at the same level (boundary vertices on the circle at
// equal angles, 45 deg / 2^(Level + 5) apart), so that the candidate contact
// surface keeps its faces; the element size grows with the distance from
// the contact point elsewhere, as in the gmsh meshes of the GetFEM harness
// of benchmarks/convergence (a Distance field feeding a Threshold field).
//
// Parameters (gmsh -setnumber NAME VALUE; lengths in mm):
//   R        radius of the disc
//   Level    refinement level: the chords of the arc near the contact point
//            span 45 deg / 2^(Level + 5) (Level = g, an integer >= -4, is
//            the level of `right half disc` with g global and 5 contact
//            refinements; Level = -2 and -1 match 0 global and 3 and 4
//            contact refinements)
//   Arc      angle (deg) from the lowest point over which the arc is so
//            divided: a multiple of 45 / 2^(Level + 5)
//   Rho      element size h_c = (pi R / 4) / 2^(Level + 5) within this
//            distance of the contact point ...
//   Growth   ... growing linearly to Growth h_c (at most R / 4) at 2 Rho
//
// Named boundaries (physical curves): curved (the arc), axis (the symmetry
// line x = 0); physical surface: body.
//
// Run through scripts/meshes/make_disc.py, e.g.
//   gmsh -2 -setnumber Level 2 disc.geo -o disc.msh

DefineConstant[ R = 40, Level = 0, Arc = 22.5, Rho = 14, Growth = 32 ];

hc   = (Pi * R / 4) / 2^(Level + 5);
hfar = Min(Growth * hc, R / 4);
nArc = Round(Arc / (45 / 2^(Level + 5)));
phi  = Arc * Pi / 180;

Point(1) = {0, 0, 0};
Point(2) = {0, R, 0};
Point(3) = {R * Sin(phi), R - R * Cos(phi), 0};
Point(4) = {R, R, 0};
Point(5) = {0, 2 * R, 0};

Circle(1) = {1, 2, 3};  // the arc near the contact point
Circle(2) = {3, 2, 4};
Circle(3) = {4, 2, 5};
Line(4)   = {5, 2};     // the axis, from the load point down
Line(5)   = {2, 1};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
Transfinite Curve{1} = nArc + 1;

Physical Curve("curved", 1) = {1, 2, 3};
Physical Curve("axis", 2)   = {4, 5};
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
