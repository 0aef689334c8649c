// SSNP150, unstructured meshes of the unit square made by gmsh itself: N
// equal segments on each edge (h = 1/N along BAS, as the structured meshes),
// the inside by Frontal-Delaunay triangles of size 1/N (QUADS = 0: TRIA6, TRIA3
// after CREA_MAILLAGE QUAD_LINE) or the same recombined into quadrangles by
// Blossom (QUADS = 1: QUAD8, QUAD4 after QUAD_LINE; no triangle is left for
// N = 2 to 64 with gmsh 4.8; its "Frontal-Delaunay for quads" and full-quad
// recombination crash on this geometry). Groups as
// ssnp150.geo: BAS, DROITE, HAUT, GAUCHE (SEG3), SURFACE, and MAITRE, one SEG3
// on the parabola Y = -0.05 (X - 0.5)^2 from X = 1.5 to X = -0.5.
// gmsh -2 ssnp150_unstructured.geo -setnumber N 8 -setnumber QUADS 1
If (!Exists(N))
  N = DefineNumber[8, Name "N"];
EndIf
If (!Exists(QUADS))
  QUADS = DefineNumber[1, Name "QUADS"];
EndIf

Point(1) = {0, 0, 0, 1.0 / N};
Point(2) = {1, 0, 0, 1.0 / N};
Point(3) = {1, 1, 0, 1.0 / N};
Point(4) = {0, 1, 0, 1.0 / N};
Line(1) = {1, 2};  // y = 0
Line(2) = {2, 3};  // x = 1
Line(3) = {3, 4};  // y = 1
Line(4) = {4, 1};  // x = 0
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve {1, 2, 3, 4} = N + 1;
Mesh.Algorithm = 6;                 // Frontal-Delaunay
If (QUADS)
  Mesh.RecombinationAlgorithm = 1;  // Blossom
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
