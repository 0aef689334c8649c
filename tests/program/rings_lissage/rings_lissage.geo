// Two concentric rings touching along r = R2: C1 (R2 <= r <= R1) and C2
// (R3 <= r <= R2), each of four structured quarter-annuli of QUAD4, with their
// own nodes on r = R2 (the same positions: the contact surfaces are fitted).
// `level` (gmsh -setnumber level K): QUAD4 halved K - 1 times for K = 1, 2;
// K = 3: level 1's cells as QUAD8 (SEG3 contact surfaces).
DefineConstant[ level = 1 ];
R1 = 1.0;
R2 = 0.6;
R3 = 0.2;
k = level == 3 ? 1 : 2^(level - 1);
nt = 8 * k;  // cells along each quarter circle
nr = 4 * k;  // cells across each ring

Point(1) = {0, 0, 0};
// Points p(ring radius index, quarter): outer ring at R1 and R2, inner ring at R2 and R3.
radii[] = {R1, R2, R2, R3};
For r In {0:3}
  For q In {0:3}
    Point(10 * (r + 1) + q) = {radii[r] * Cos(q * Pi / 2), radii[r] * Sin(q * Pi / 2), 0};
  EndFor
EndFor
// Quarter arcs, counterclockwise: arc(r, q) from quarter q to q + 1.
For r In {0:3}
  For q In {0:3}
    Circle(10 * (r + 1) + q) = {10 * (r + 1) + q, 1, 10 * (r + 1) + (q + 1) % 4};
  EndFor
EndFor
// Radial lines of each ring at the quarter points.
For q In {0:3}
  Line(100 + q) = {20 + q, 10 + q};  // outer ring, from R2 to R1
  Line(200 + q) = {40 + q, 30 + q};  // inner ring, from R3 to R2
EndFor
For q In {0:3}
  Curve Loop(100 + q) = {100 + q, 10 + q, -(100 + (q + 1) % 4), -(20 + q)};
  Plane Surface(100 + q) = {100 + q};
  Curve Loop(200 + q) = {200 + q, 30 + q, -(200 + (q + 1) % 4), -(40 + q)};
  Plane Surface(200 + q) = {200 + q};
EndFor
Transfinite Curve {10:13, 20:23, 30:33, 40:43} = nt + 1;
Transfinite Curve {100:103, 200:203} = nr + 1;
Transfinite Surface {100:103, 200:203};
Recombine Surface {100:103, 200:203};
If (level == 3)
  Mesh.ElementOrder = 2;
  Mesh.SecondOrderIncomplete = 1;
EndIf

Physical Surface("C1") = {100:103};
Physical Surface("C2") = {200:203};
Physical Curve("S1R1") = {10:13};
Physical Curve("S1R2") = {20:23};
Physical Curve("S2R2") = {30:33};
Physical Curve("S2R3") = {40:43};
