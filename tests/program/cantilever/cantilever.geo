// A cantilever beam x in [0, L], y in [-D/2, D/2]: nx x ny QUAD8, `level` (gmsh
// -setnumber level K) halving the cells K - 1 times.
DefineConstant[ level = 1 ];
Lb = 10;
D = 1;
k = 2^(level - 1);
Point(1) = {0, -D / 2, 0};
Point(2) = {Lb, -D / 2, 0};
Point(3) = {Lb, D / 2, 0};
Point(4) = {0, D / 2, 0};
Point(5) = {0, 0, 0};
Point(6) = {Lb, 0, 0};
Line(1) = {1, 2};
Line(2) = {2, 6};
Line(6) = {6, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 1};
Curve Loop(1) = {1, 2, 6, 3, 4, 5};
Plane Surface(1) = {1};
Transfinite Curve {1, 3} = 20 * k + 1;
Transfinite Curve {2, 6, 4, 5} = 2 * k + 1;
Transfinite Surface {1} = {1, 2, 3, 4};
Recombine Surface {1};
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 1;

Physical Surface("POUTRE") = {1};
Physical Curve("ENCAS") = {4, 5};   // the clamped end x = 0
Physical Curve("BOUT") = {2, 6};    // the loaded end x = L
Physical Point("O") = {5};          // (0, 0)
Physical Point("HAUT_ENC") = {4};   // (0, D/2): the largest bending stress
Physical Point("P") = {6};          // (L, 0): the tip deflection
