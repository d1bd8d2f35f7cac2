// Kalthoff-Winkler plate with its two notches as slits: 0 <= x <= 0.1 m (x = impact direction),
// -0.1 <= y <= 0.1 m, notches along y = +-0.025 m from the impacted edge x = 0 to the tips at
// x = 0.05 m (zero width: the faces above and below a notch have their own nodes). The same
// coordinates as doc/benchmarks/kalthoff_winkler. Lengths in m.
// Six structured blocks of quadrilaterals, 2 mm: 25 + 25 cells in x, 38 + 25 + 38 in y
// (the outer blocks' cells are 75/38 mm tall): 5050 elements.
//
// Regenerate:  gmsh -2 -format msh22 kalthoff_winkler_2d.geo -o kalthoff_winkler_2d.msh
// Finer (nested) sibling, every element split into k x k, here k = 2 (1 mm):
//              gmsh -2 -format msh22 -clscale 0.5 kalthoff_winkler_2d.geo -o kalthoff_winkler_2d_k2.msh
// (-clscale must be 1/k with integer k; it sets Mesh.MeshSizeFactor, read below.)
//
// Material id 1 (physical surface 1).
// Boundary ids (physical curves):
//   1: x = 0, |y| <= 0.025 (the impacted segment between the notches)
//   2: x = 0, |y| >= 0.025 (free)
//   3: the four notch faces (free)
//   4: x = 0.1 and y = +-0.1 (free)
Mesh.MshFileVersion = 2.2;
Geometry.AutoCoherence = 0;  // keep the coincident notch-face points apart (the slits)

k = Round(1 / Mesh.MeshSizeFactor);
If (k < 1)
  k = 1;
EndIf
nx = 25 * k;  // per half of the width (50 mm)
nm = 25 * k;  // between the notches (50 mm)
no = 38 * k;  // outer blocks (75 mm)

a = 0.025; L = 0.1; t = 0.05;

// Corners of the blocks. Points on a notch (x < t) exist twice: "u" above, "d" below.
Point(1)  = {0, -L, 0};  Point(2)  = {t, -L, 0};  Point(3)  = {L, -L, 0};
Point(4)  = {0, -a, 0};  Point(5)  = {0, -a, 0};  // bottom notch: 4 below, 5 above
Point(6)  = {t, -a, 0};  Point(7)  = {L, -a, 0};
Point(8)  = {0, a, 0};   Point(9)  = {0, a, 0};   // top notch: 8 below, 9 above
Point(10) = {t, a, 0};   Point(11) = {L, a, 0};
Point(12) = {0, L, 0};   Point(13) = {t, L, 0};   Point(14) = {L, L, 0};

// Horizontal lines.
Line(1)  = {1, 2};   Line(2)  = {2, 3};           // y = -L
Line(3)  = {4, 6};                                 // bottom notch, lower face
Line(4)  = {5, 6};                                 // bottom notch, upper face
Line(5)  = {6, 7};                                 // y = -a behind the tip
Line(6)  = {8, 10};                                // top notch, lower face
Line(7)  = {9, 10};                                // top notch, upper face
Line(8)  = {10, 11};                               // y = a behind the tip
Line(9)  = {12, 13}; Line(10) = {13, 14};          // y = L
// Vertical lines.
Line(11) = {1, 4};   Line(12) = {2, 6};  Line(13) = {3, 7};
Line(14) = {5, 8};   Line(15) = {6, 10}; Line(16) = {7, 11};
Line(17) = {9, 12};  Line(18) = {10, 13}; Line(19) = {11, 14};

Transfinite Curve{1, 2, 3, 4, 5, 6, 7, 8, 9, 10} = nx + 1;
Transfinite Curve{11, 12, 13, 17, 18, 19} = no + 1;
Transfinite Curve{14, 15, 16} = nm + 1;

Curve Loop(1) = {1, 12, -3, -11};   Plane Surface(1) = {1};  // bottom left
Curve Loop(2) = {2, 13, -5, -12};   Plane Surface(2) = {2};  // bottom right
Curve Loop(3) = {4, 15, -6, -14};   Plane Surface(3) = {3};  // between the notches
Curve Loop(4) = {5, 16, -8, -15};   Plane Surface(4) = {4};  // middle right
Curve Loop(5) = {7, 18, -9, -17};   Plane Surface(5) = {5};  // top left
Curve Loop(6) = {8, 19, -10, -18};  Plane Surface(6) = {6};  // top right
Transfinite Surface{1, 2, 3, 4, 5, 6};
Recombine Surface{1, 2, 3, 4, 5, 6};

Physical Surface(1) = {1, 2, 3, 4, 5, 6};
Physical Curve(1) = {14};
Physical Curve(2) = {11, 17};
Physical Curve(3) = {3, 4, 6, 7};
Physical Curve(4) = {1, 2, 13, 16, 19, 9, 10};
