// Two deformable bodies for the ironing test (ironing.lua), plane strain:
// DALLE, the slab [-3, 3] x [0, 1], and FER, the iron: a block whose bottom
// is the arc of radius 1 centred at (0, 2) from x = -0.5 to x = 0.5 (touching
// the slab at the origin's vertical, (0, 1)), with vertical sides up to its
// top y = 1.5. Both structured (transfinite) and symmetric about x = 0; the
// slab's top has cells of length h = 0.1, the iron's arc 15 cells of 0.0698
// (arc length pi / 3 / 15): the contact surfaces' nodes do not coincide (on
// level 3 both have one at x = 0).
// `level` (gmsh -setnumber level L): 1 QUAD4, 2 QUAD8, 3 QUAD4 with cells
// half as long (h = 0.05, 30 cells on the arc).
// Groups: DALLE, FER (the surfaces), BAS (the slab's bottom y = 0), DESSUS
// (the slab's top y = 1), ARC (the iron's bottom), HAUT_FER (the iron's top).
Geometry.AutoCoherence = 0;  // the bodies keep their own points
DefineConstant[ level = 1 ];
r = level == 3 ? 2 : 1;  // cells per cell of levels 1 and 2

Point(1) = {-3, 0, 0};
Point(2) = {3, 0, 0};
Point(3) = {3, 1, 0};
Point(4) = {-3, 1, 0};
Line(1) = {1, 2};  // BAS
Line(2) = {2, 3};
Line(3) = {3, 4};  // DESSUS
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve {1, 3} = 60 * r + 1;
Transfinite Curve {2, 4} = 10 * r + 1;

yArc = 2 - Sqrt(0.75);  // the arc's ends, at x = -0.5 and x = 0.5
Point(10) = {0, 2, 0};  // the arc's centre
Point(11) = {-0.5, yArc, 0};
Point(12) = {0.5, yArc, 0};
Point(13) = {0.5, 1.5, 0};
Point(14) = {-0.5, 1.5, 0};
Circle(11) = {11, 10, 12};  // ARC
Line(12) = {12, 13};
Line(13) = {13, 14};  // HAUT_FER
Line(14) = {14, 11};
Curve Loop(2) = {11, 12, 13, 14};
Plane Surface(2) = {2};
Transfinite Curve {11, 13} = 15 * r + 1;
Transfinite Curve {12, 14} = 4 * r + 1;

Transfinite Surface {1, 2};
Recombine Surface {1, 2};
If (level == 2)
  Mesh.ElementOrder = 2;
  Mesh.SecondOrderIncomplete = 1;
EndIf

Physical Surface("DALLE") = {1};
Physical Surface("FER") = {2};
Physical Curve("BAS") = {1};
Physical Curve("DESSUS") = {3};
Physical Curve("ARC") = {11};
Physical Curve("HAUT_FER") = {13};
