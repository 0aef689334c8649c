// SSNP150, trapezoidal meshes of the unit square (as Arnold, Boffi and Falk's,
// Math. Comp. 71, 2002): N x N cells, every one a trapezoid at every N, made
// for each N (not by splitting a coarser one, which tends to parallelograms).
// Columns of width h = 1/N; the nodes inside the square are moved up and down
// by h/6 alternately, +h/6 where i + j is even, so that the top and bottom of
// each cell slope opposite ways: the cells are trapezoids with vertical
// parallel sides of 2h/3 and 4h/3 (those of the first and last row, whose
// bottom or top is the straight edge, 5h/6 and 7h/6). QUADS = 1: QUAD8 (QUAD4
// after CREA_MAILLAGE QUAD_LINE); QUADS = 0: each trapezoid split in two
// triangles, TRIA6 (TRIA3 after QUAD_LINE). Groups as ssnp150.geo: BAS, DROITE,
// HAUT, GAUCHE (SEG3), SURFACE, and MAITRE, one SEG3 on the parabola
// Y = -0.05 (X - 0.5)^2 from X = 1.5 to X = -0.5; and INTERIEUR (below).
// gmsh -2 ssnp150_trapezoidal.geo -setnumber N 8 -setnumber QUADS 1
If (!Exists(N))
  N = DefineNumber[8, Name "N"];
EndIf
If (!Exists(QUADS))
  QUADS = DefineNumber[1, Name "QUADS"];
EndIf

h = 1.0 / N;
shift = h / 6;
// Node (i, j), 0 <= i, j <= N: point 100 + i (N + 1) + j. Curves: the one from
// node (i, j) to (i + 1, j) is 100000 + i (N + 1) + j, from (i, j) to (i, j + 1)
// is 200000 + i (N + 1) + j; cell (i, j) is surface 300000 + i N + j.
For i In {0 : N}
  For j In {0 : N}
    y = j * h;
    If (j > 0 && j < N)
      y = y + shift * (1 - 2 * ((i + j) % 2));
    EndIf
    Point(100 + i * (N + 1) + j) = {i * h, y, 0};
  EndFor
EndFor
For i In {0 : N}
  For j In {0 : N}
    If (i < N)
      Line(100000 + i * (N + 1) + j) = {100 + i * (N + 1) + j, 100 + (i + 1) * (N + 1) + j};
    EndIf
    If (j < N)
      Line(200000 + i * (N + 1) + j) = {100 + i * (N + 1) + j, 100 + i * (N + 1) + j + 1};
    EndIf
  EndFor
EndFor
cells[] = {};
For i In {0 : N - 1}
  For j In {0 : N - 1}
    c = 300000 + i * N + j;
    Curve Loop(c) = {100000 + i * (N + 1) + j, 200000 + (i + 1) * (N + 1) + j,
                     -(100000 + i * (N + 1) + j + 1), -(200000 + i * (N + 1) + j)};
    Plane Surface(c) = {c};
    cells[] += {c};
  EndFor
EndFor
Transfinite Curve {:} = 2;
Transfinite Surface {cells[]};
If (QUADS)
  Recombine Surface {cells[]};
EndIf

bas[] = {};
haut[] = {};
gauche[] = {};
droite[] = {};
inside[] = {};
For k In {0 : N - 1}
  bas[] += {100000 + k * (N + 1)};
  haut[] += {100000 + k * (N + 1) + N};
  gauche[] += {200000 + k};
  droite[] += {200000 + N * (N + 1) + k};
  For j In {1 : N - 1}
    inside[] += {100000 + k * (N + 1) + j, 200000 + j * (N + 1) + k};
  EndFor
EndFor

// The parabola is exactly the quadratic Bezier curve with these control points;
// its parametric middle is the apex (0.5, 0).
Point(1) = {1.5, -0.05, 0};
Point(2) = {0.5, 0.05, 0};
Point(3) = {-0.5, -0.05, 0};
Bezier(1) = {1, 2, 3};
Transfinite Curve {1} = 2;

Physical Surface("SURFACE") = {cells[]};
Physical Curve("BAS") = {bas[]};
Physical Curve("DROITE") = {droite[]};
Physical Curve("HAUT") = {haut[]};
Physical Curve("GAUCHE") = {gauche[]};
Physical Curve("MAITRE") = {1};
// The edges between cells are curves of this geometry, so gmsh meshes them
// (SEG3) and aster-lite keeps every cell of the file: named, they are not left
// as cells in no group (CREA_MAILLAGE QUAD_LINE must reach them, or their
// middle nodes would stay as nodes of no cell of SURFACE).
If (N > 1)
  Physical Curve("INTERIEUR") = {inside[]};
EndIf

Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 1;
