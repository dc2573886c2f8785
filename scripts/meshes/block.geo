// The elastic foundation of dpana's 2D Hertz scenes on a block, graded:
// the square [0, 2R] x [-2R, 0] below the contact point (0, 0) of the
// circular body (the half x >= 0 of the 4R x 2R foundation), the companion
// of disc.geo. Linear triangles, written in the ASCII format 2.2 that
// dpana's `gmsh` geometry reads.
//
// Its top face near the contact point is divided at the projections of the
// vertices of disc.geo's arc at the same level, x = R sin(k dphi) with
// dphi = 45 deg / 2^(Level + 5), k = 0 ... Arc / dphi: below every chord of
// the disc lies one face of the block, so that the mortar projection of
// the two-body scenes pairs each face of the candidate surface with one
// face of the foundation. (gmsh places the vertices of disc.geo's arc by
// its numerically integrated length, up to 3e-8 mm away from the exact
// angles: the projection also cuts slivers of that length from the
// neighbouring faces, with weights of 1e-8 of a face.) Elsewhere the element size grows with the
// distance from the contact point as in disc.geo and in the gmsh meshes of
// the GetFEM harness of benchmarks/convergence (a Distance field feeding a
// Threshold field).
//
// Parameters (gmsh -setnumber NAME VALUE; lengths in mm), those of
// disc.geo:
//   R        radius of the circular body (the block is 2R wide and deep)
//   Level    refinement level, as in disc.geo
//   Arc      the top face is divided as the disc's arc is within this
//            angle (deg) from the lowest point: up to x = R sin(Arc)
//   Rho      element size h_c = (pi R / 4) / 2^(Level + 5) within this
//            distance of the contact point ...
//   Growth   ... growing linearly to Growth h_c (at most R / 4) at 2 Rho
//
// Named boundaries (physical curves): top (y = 0, the contact face), right
// (x = 2R), bottom (y = -2R), left (the symmetry line x = 0), the names of
// dpana's `rectangle`; physical surface: body.
//
// Run through scripts/meshes/make_disc.py --body block, e.g.
//   gmsh -2 -setnumber Level 2 block.geo -o block.msh

DefineConstant[ R = 40, Level = 0, Arc = 22.5, Rho = 14, Growth = 32 ];

hc   = (Pi * R / 4) / 2^(Level + 5);
hfar = Min(Growth * hc, R / 4);
nArc = Round(Arc / (45 / 2^(Level + 5)));
dphi = (45 / 2^(Level + 5)) * Pi / 180;

// The corners, and the top face's vertices below the arc's: point 100 + k
// at x = R sin(k dphi), k = 1 ... nArc (k = 0 is the contact point).
Point(1) = {0, 0, 0};
Point(2) = {2 * R, 0, 0};
Point(3) = {2 * R, -2 * R, 0};
Point(4) = {0, -2 * R, 0};
For k In {1 : nArc}
  Point(100 + k) = {R * Sin(k * dphi), 0, 0};
EndFor

// The top face: one line per chord of the arc (one element each), then the
// rest of the face to the corner; the other sides.
Line(101) = {1, 101};
For k In {2 : nArc}
  Line(100 + k) = {99 + k, 100 + k};
EndFor
Transfinite Curve{101 : 100 + nArc} = 2;
Line(1) = {100 + nArc, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {101 : 100 + nArc, 1, 2, 3, 4};
Plane Surface(1) = {1};

Physical Curve("top", 1)    = {101 : 100 + nArc, 1};
Physical Curve("right", 2)  = {2};
Physical Curve("bottom", 3) = {3};
Physical Curve("left", 4)   = {4};
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
