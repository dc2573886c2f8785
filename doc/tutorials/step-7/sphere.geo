// Tutorial step 7: a quarter of the lower half of an elastic sphere of
// radius R = 10 mm centred at (0, R, 0), x >= 0, z >= 0, y <= R, for the
// 3D Hertz problem on a rigid plane y = 0. The mesh is fine (size
// h_contact) near the first contact point, the origin, and coarsens away
// from it. Physical surfaces: curved (the spherical surface, candidate
// contact surface), top (the plane y = R, loaded), x0 and z0 (the planes
// of symmetry). Run by step-7:  gmsh -3 sphere.geo -format msh22 -o ...
SetFactory("OpenCASCADE");
R         = 10;
h_contact = 0.1;
h_far     = 2.5;
Sphere(1) = {0, R, 0, R};
Box(2)    = {0, 0, 0, R, R, R};
BooleanIntersection(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Physical Volume("body") = {3};

// The faces of the quarter sphere, sorted by their bounding boxes.
s() = Boundary{ Volume{3}; };
Physical Surface("curved") = {};
Physical Surface("top")    = {};
Physical Surface("x0")     = {};
Physical Surface("z0")     = {};
For i In {0 : #s() - 1}
  b() = BoundingBox Surface{ s(i) };
  If (b(4) - b(1) < 1e-6 && b(1) > R - 1e-6)
    Physical Surface("top") += {s(i)};
  ElseIf (b(3) - b(0) < 1e-6)
    Physical Surface("x0") += {s(i)};
  ElseIf (b(5) - b(2) < 1e-6)
    Physical Surface("z0") += {s(i)};
  Else
    Physical Surface("curved") += {s(i)};
  EndIf
EndFor

// Mesh size: h_contact within 2 mm of the origin, growing by 0.3 mm per mm.
Field[1]   = MathEval;
Field[1].F = Sprintf("min(%g, %g + 0.3 * max(0, sqrt(x*x + y*y + z*z) - 2))",
                     h_far, h_contact);
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints         = 0;
Mesh.MeshSizeFromCurvature      = 0;
