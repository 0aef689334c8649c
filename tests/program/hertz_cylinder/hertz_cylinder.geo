// A cylinder of radius R = 1 on a rigid flat, plane strain, for
// hertz_cylinder.lua: the quarter x >= 0, y <= R of the disc centred at
// (0, R), touching the flat y = 0 at the origin. Groups: CYLINDRE (the quarter
// disc), HAUT (y = R, the cut through the centre, loaded), SYME (x = 0, the
// symmetry line), ESCLAVE (the arc from the origin to x = XS, the slave),
// LIBRE (the rest of the arc), MAITRE (the rigid flat, one SEG2 from x = 0.6 to
// x = -0.1, walked so that its normal (dy, -dx) points up, to the cylinder).
// `level` (gmsh -setnumber level L): TRIA3 for L = 1..4, TRIA6 for L = 5..7,
// of size H = A / 5, A / 10, A / 20 (and A / 40 for TRIA3) within 2 A of the
// origin (A = 0.05, the Hertz half-width of the study's load), growing to
// R / 10 beyond 0.5 R.
Geometry.AutoCoherence = 0;
DefineConstant[ level = 1 ];
R = 1.0;
A = 0.05;
refinement = level > 4 ? level - 5 : level - 1;
H = A / (5 * 2^refinement);
XS = 0.3;  // the slave arc ends at x = XS = 6 A

Point(1) = {0, R, 0};                      // the centre
Point(2) = {0, 0, 0};                      // the contact point
Point(3) = {XS, R - Sqrt(R^2 - XS^2), 0};  // the end of the slave arc
Point(4) = {R, R, 0};
Circle(1) = {2, 1, 3};  // ESCLAVE
Circle(2) = {3, 1, 4};  // LIBRE
Line(3) = {4, 1};       // HAUT
Line(4) = {1, 2};       // SYME
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Point(5) = {0.6, 0, 0};
Point(6) = {-0.1, 0, 0};
Line(5) = {5, 6};       // MAITRE
Transfinite Curve {5} = 2;

Field[1] = Distance;
Field[1].PointsList = {2};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = H;
Field[2].SizeMax = R / 10;
Field[2].DistMin = 2 * A;
Field[2].DistMax = 0.5 * R;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

If (level > 4)
  Mesh.ElementOrder = 2;
EndIf

Physical Surface("CYLINDRE") = {1};
Physical Curve("ESCLAVE") = {1};
Physical Curve("LIBRE") = {2};
Physical Curve("HAUT") = {3};
Physical Curve("SYME") = {4};
Physical Curve("MAITRE") = {5};
