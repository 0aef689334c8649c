// SSNP150, structured meshes of the unit square: a regular N x N grid, of
// quadrangles (QUADS = 1: QUAD8, QUAD4 after CREA_MAILLAGE QUAD_LINE) or of
// squares each split in two triangles by the same diagonal (QUADS = 0: TRIA6,
// TRIA3 after QUAD_LINE). Edges BAS, DROITE, HAUT, GAUCHE as SEG3 groups, cells
// as SURFACE, and the rigid master MAITRE as one SEG3 on the parabola
// Y = -0.05 (X - 0.5)^2 from X = 1.5 to X = -0.5 (as ssnp150.geo).
// gmsh -2 ssnp150_structured.geo -setnumber N 8 -setnumber QUADS 0
If (!Exists(N))
  N = DefineNumber[8, Name "N"];
EndIf
If (!Exists(QUADS))
  QUADS = DefineNumber[1, Name "QUADS"];
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
If (QUADS)
  Recombine Surface {1};
EndIf

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
