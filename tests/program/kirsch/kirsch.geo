// Kirsch's problem on a quarter of a square plate with a hole (radius a, half-width L):
// two structured blocks of QUAD8 joined along the diagonal. `level` (gmsh -setnumber
// level K) halves the cells K - 1 times; the grading is nested, so each mesh refines
// the last one.
DefineConstant[ level = 1 ];
a = 1;
L = 5;
k = 2^(level - 1);
nt = 4 * k;              // cells along each eighth of the hole
nr = 8 * k;              // cells from the hole to the outer edge
q = 1.25^(1 / k);        // growth of the radial cells

Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0};
Point(3) = {a / Sqrt(2), a / Sqrt(2), 0};
Point(4) = {0, a, 0};
Point(5) = {L, 0, 0};
Point(6) = {L, L, 0};
Point(7) = {0, L, 0};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Line(3) = {2, 5};
Line(4) = {3, 6};
Line(5) = {4, 7};
Line(6) = {5, 6};
Line(7) = {6, 7};
Curve Loop(1) = {3, 6, -4, -1};
Plane Surface(1) = {1};
Curve Loop(2) = {4, 7, -5, -2};
Plane Surface(2) = {2};
Transfinite Curve {1, 2, 6, 7} = nt + 1;
Transfinite Curve {3, 4, 5} = nr + 1 Using Progression q;
Transfinite Surface {1, 2};
Recombine Surface {1, 2};
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 1;

Physical Surface("PLAQUE") = {1, 2};
Physical Curve("BAS") = {3};
Physical Curve("GAUCHE") = {5};
Physical Curve("DROITE") = {6};
Physical Curve("HAUT") = {7};
Physical Curve("TROU") = {1, 2};
Physical Point("A") = {4};   // (0, a): SIXX = 3 S
Physical Point("B") = {2};   // (a, 0): SIYY = -S
