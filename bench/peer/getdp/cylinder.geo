// Gmsh geometry of bench/peer/eddy_cylinder_step.fem: a conducting cylinder (radius 10 mm) inside
// a 10-turn winding (10 to 10.5 mm), a 2 mm high axisymmetric strip (no boundary condition but the
// axis: the long-solenoid limit). Lengths in metres.
//   lc: element size away from the cylinder's surface; ls: size at the surface (r = 10 mm) and in
//   the winding, growing to lc over `grade` (ls = lc: a uniform mesh).
DefineConstant[ lc = 0.5e-3, ls = 0.5e-3, grade = 2e-3 ];
a = 10e-3; b = 10.5e-3; h = 2e-3;
Point(1) = {0, 0, 0, lc}; Point(2) = {a, 0, 0, ls}; Point(3) = {b, 0, 0, ls};
Point(4) = {b, h, 0, ls}; Point(5) = {a, h, 0, ls}; Point(6) = {0, h, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5};
Line(5) = {5, 6}; Line(6) = {6, 1}; Line(7) = {2, 5};
Curve Loop(1) = {1, 7, 5, 6}; Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7}; Plane Surface(2) = {2};
Field[1] = Distance; Field[1].CurvesList = {7}; Field[1].NumPointsPerCurve = 200;
Field[2] = Threshold; Field[2].InField = 1; Field[2].SizeMin = ls; Field[2].SizeMax = lc;
Field[2].DistMin = 0; Field[2].DistMax = grade;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0; Mesh.MeshSizeFromPoints = 0;
Physical Surface("iron", 100) = {1};
Physical Surface("winding", 101) = {2};
Physical Curve("axis", 200) = {6};
