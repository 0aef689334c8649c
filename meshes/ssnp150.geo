// SSNP150 geometry: the unit square meshed by a regular N x N grid of QUAD8,
// its edges as SEG3 groups, and the rigid master MAITRE as one SEG3 on the
// parabola Y = -0.05 (X - 0.5)^2 from X = 1.5 to X = -0.5.
// N can be overridden: gmsh -2 ssnp150.geo -setnumber N 4 (or through ONELAB "N").
If (!Exists(N))
  N = DefineNumber[16, Name "N"];
EndIf

Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};  // y = 0
Line(2) = {2, 3};  // x = 1
Line(3) = {3, 4};  // y = 1
Line(4) = {4, 1};  // x = 0
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve {1, 2, 3, 4} = N + 1;
Transfinite Surface {1} = {1, 2, 3, 4};
Recombine Surface {1};

// The parabola is exactly the quadratic Bezier curve with these control points;
// its parametric middle is the apex (0.5, 0).
Point(5) = {1.5, -0.05, 0};
Point(6) = {0.5, 0.05, 0};
Point(7) = {-0.5, -0.05, 0};
Bezier(5) = {5, 6, 7};
Transfinite Curve {5} = 2;

Physical Surface("SURFACE") = {1};
Physical Curve("BAS") = {1};
Physical Curve("DROITE") = {2};
Physical Curve("HAUT") = {3};
Physical Curve("GAUCHE") = {4};
Physical Curve("MAITRE") = {5};

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 1;
