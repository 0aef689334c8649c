// A square plate with a circular hole under tension: the quarter x >= 0, y >= 0
// (lengths in mm). The groups the study uses are physical groups.
a = 10;    // radius of the hole
L = 200;   // half-width of the plate
h = 1;     // mesh size at the hole
H = 25;    // mesh size at the outer edges

Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0, h};
Point(3) = {L, 0, 0, H};
Point(4) = {L, L, 0, H};
Point(5) = {0, L, 0, H};
Point(6) = {0, a, 0, h};
Line(1) = {2, 3};
Line(2) = {3, 4};
Line(3) = {4, 5};
Line(4) = {5, 6};
Circle(5) = {6, 1, 2};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};

// Quadrangles with 8 nodes (QUAD8): recombined triangles, second order, no centre node.
Recombine Surface {1};
Mesh.Algorithm = 6;
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 1;

Physical Surface("PLAQUE") = {1};
Physical Curve("BAS") = {1};
Physical Curve("DROITE") = {2};
Physical Curve("HAUT") = {3};
Physical Curve("GAUCHE") = {4};
Physical Curve("TROU") = {5};
Physical Point("A") = {6};   // (0, a): the top of the hole, where SIXX is largest
Physical Point("B") = {2};   // (a, 0)
