// Two blocks for the two-body contact patch test (contact_patch.lua): BLOC_BAS
// [0,1] x [0,0.5] and BLOC_HAUT [0,1] x [0.5,1], each with its own nodes on
// y = 0.5, structured. `level` (gmsh -setnumber level L) chooses the cells:
// L = 1..4 TRIA3, QUAD4, TRIA6, QUAD8 with 5 cells across BLOC_BAS and 7
// across BLOC_HAUT (the interfaces' nodes coincide only at x = 0 and x = 1);
// L = 5..8 the same cells with 5 across both (matching interfaces: the control).
// Groups: BAS (y = 0), HAUT (y = 1), GAUCHE (x = 0, both blocks), INTER_BAS
// (the top of BLOC_BAS), INTER_HAUT (the bottom of BLOC_HAUT).
Geometry.AutoCoherence = 0;  // the blocks keep their own points on y = 0.5
DefineConstant[ level = 1 ];
cell = (level - 1) % 4 + 1;  // 1 TRIA3, 2 QUAD4, 3 TRIA6, 4 QUAD8
nBas = 5;
nHaut = level > 4 ? 5 : 7;

Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 0.5, 0};
Point(4) = {0, 0.5, 0};
Point(5) = {0, 0.5, 0};
Point(6) = {1, 0.5, 0};
Point(7) = {1, 1, 0};
Point(8) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};  // INTER_BAS
Line(4) = {4, 1};
Line(5) = {5, 6};  // INTER_HAUT
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};
Transfinite Curve {1, 3} = nBas + 1;
Transfinite Curve {5, 7} = nHaut + 1;
Transfinite Curve {2, 4} = 4;
Transfinite Curve {6, 8} = 5;
Transfinite Surface {1, 2};
If (cell == 2 || cell == 4)
  Recombine Surface {1, 2};
EndIf
If (cell >= 3)
  Mesh.ElementOrder = 2;
  Mesh.SecondOrderIncomplete = 1;
EndIf

Physical Surface("BLOC_BAS") = {1};
Physical Surface("BLOC_HAUT") = {2};
Physical Curve("BAS") = {1};
Physical Curve("HAUT") = {7};
Physical Curve("GAUCHE") = {4, 8};
Physical Curve("INTER_BAS") = {3};
Physical Curve("INTER_HAUT") = {5};
