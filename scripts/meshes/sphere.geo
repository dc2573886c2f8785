// Quarter of an elastic sphere of radius R (x >= 0, z >= 0) touching the
// plane y = 0 at the origin, for the 3D Hertz scenes of dpana. Meshed with
// linear tetrahedra, finest on the contact cap and coarser with the distance
// from it (a gmsh Distance field feeding a Threshold field), written in the
// ASCII format 2.2 that dpana's `gmsh` geometry reads.
//
// Parameters (gmsh -setnumber NAME VALUE; lengths in mm):
//   R           radius of the sphere
//   Side        +1: the sphere above the plane, centre (0, R, 0);
//               -1: its mirror image below it, centre (0, -R, 0)
//   CapRadius   radius (measured from the axis) of the contact cap, the
//               candidate contact surface: choose it about 1.5 times the
//               expected contact radius
//   PoleRadius  radius of the cap around the far pole (0, 2 Side R, 0)
//   SizeContact element size on the contact cap
//   SizeFar     element size far from it
//   Growth      growth of the element size per unit distance from the cap
//   SizeFactor  multiplies every size: one knob for a refinement series
//               (the unknowns grow like SizeFactor^-2 while the cap's
//               layer dominates, like SizeFactor^-3 once the volume does)
//   Algorithm3D gmsh's 3D algorithm: 1 Delaunay (the default: the same mesh
//               at every run), 10 HXT (parallel and faster on big meshes,
//               but not reproducible from run to run)
//   Refinements 0: the mesh is made by the command line (gmsh -3 ... -o);
//               k > 0: this file meshes, splits every tetrahedron into 8
//               k times (gmsh's RefineMesh, which puts the new boundary
//               nodes on the sphere) and saves the mesh to the string
//               Output (gmsh -setstring Output FILE -parse_and_exit):
//               meshes nested in the mesh of Refinements = 0, h halved
//               per refinement
//
// Named boundaries (physical surfaces): symmetry_x (the plane x = 0),
// symmetry_z (z = 0), contact (the cap around the contact point), pole (the
// cap around the far pole), sphere (the rest of the spherical surface);
// physical volume: body.
//
// Run through scripts/meshes/make_sphere.sh, e.g.
//   gmsh -3 -setnumber SizeContact 0.25 sphere.geo -o sphere.msh

SetFactory("OpenCASCADE");
Geometry.OCCBoundsUseStl = 1; // tight bounding boxes for the selections below

DefineConstant[
  Output = "sphere.msh",
  R = 40, Side = 1, CapRadius = 6, PoleRadius = 4,
  SizeContact = 0.4, SizeFar = 6, Growth = 0.25, SizeFactor = 1,
  Algorithm3D = 1, Refinements = 0
];

e  = 1e-6 * R;
hc = R - Sqrt(R * R - CapRadius * CapRadius);   // height of the contact cap
hp = R - Sqrt(R * R - PoleRadius * PoleRadius); // height of the pole cap

// The quarter sphere in three slices: contact cap, middle, pole cap.
Sphere(1) = {0, R, 0, R};
Box(2)    = {0, 0, 0, R, hc, R};
Box(3)    = {0, hc, 0, R, 2 * R - hc - hp, R};
Box(4)    = {0, 2 * R - hp, 0, R, hp, R};
BooleanIntersection(11) = {Volume{1};}{Volume{2}; Delete;};
BooleanIntersection(12) = {Volume{1};}{Volume{3}; Delete;};
BooleanIntersection(13) = {Volume{1}; Delete;}{Volume{4}; Delete;};
BooleanFragments{Volume{11, 12, 13}; Delete;}{}
If (Side < 0)
  Symmetry {0, 1, 0, 0} { Volume{:}; }
EndIf

// Bounding boxes in y of a slice [y0, y1] of the upper sphere, mirrored for
// the lower one.
Macro SliceBox
  ya = (Side > 0) ? y0 : -y1;
  yb = (Side > 0) ? y1 : -y0;
Return

y0 = -e; y1 = 2 * R + e; Call SliceBox;
sym_x() = Surface In BoundingBox{-e, ya, -e, e, yb, R + e};
sym_z() = Surface In BoundingBox{-e, ya, -e, R + e, yb, e};
outer() = CombinedBoundary{ Volume{:}; };
outer() = Abs(outer());

y0 = -e; y1 = hc + e; Call SliceBox;
contact() = Surface In BoundingBox{-e, ya, -e, R + e, yb, R + e};
y0 = hc - e; y1 = hc + e; Call SliceBox;
cut() = Surface In BoundingBox{-e, ya, -e, R + e, yb, R + e};
contact() -= {sym_x(), sym_z(), cut()};

y0 = 2 * R - hp - e; y1 = 2 * R + e; Call SliceBox;
pole() = Surface In BoundingBox{-e, ya, -e, R + e, yb, R + e};
y0 = 2 * R - hp - e; y1 = 2 * R - hp + e; Call SliceBox;
cut() = Surface In BoundingBox{-e, ya, -e, R + e, yb, R + e};
pole() -= {sym_x(), sym_z(), cut()};

sphere() = outer();
sphere() -= {sym_x(), sym_z(), contact(), pole()};

Physical Surface("symmetry_x", 1) = {sym_x()};
Physical Surface("symmetry_z", 2) = {sym_z()};
Physical Surface("contact", 3)    = {contact()};
Physical Surface("pole", 4)       = {pole()};
Physical Surface("sphere", 5)     = {sphere()};
Physical Volume("body", 10)       = {Volume{:}};

// Sizes: SizeContact on the contact cap, growing by Growth per unit distance
// from it, up to SizeFar. The cap is sampled finer than its elements, so that
// the distance is known to a fraction of SizeContact.
lc  = SizeFactor * SizeContact;
lcf = SizeFactor * SizeFar;
Field[1] = Distance;
Field[1].SurfacesList = {contact()};
Field[1].NumPointsPerCurve = Ceil(4 * CapRadius / lc) + 10;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = lc;
Field[2].SizeMax = lcf;
Field[2].DistMin = 0.5 * lc;
Field[2].DistMax = 0.5 * lc + (lcf - lc) / Growth;
Background Field = 2;

Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.ElementOrder = 1;
Mesh.Algorithm3D = Algorithm3D;
Mesh.Optimize = 1;
Mesh.MshFileVersion = 2.2;
Mesh.Binary = 0;
Mesh.SaveAll = 0;            // only the physical groups

// A nested family: the mesh above, refined uniformly. gmsh's command line
// (-3) would mesh the volume again after this file, so the file saves the
// refined mesh itself and is run with -parse_and_exit.
If (Refinements > 0)
  Mesh 3;
  For i In {1:Refinements}
    RefineMesh;
  EndFor
  Save Str(Output);
EndIf
