// A 2D plate 0.05 m x 0.02 m split at x = 0.03 into two materials:
// physical surface 1 (left, x < 0.03) and 2 (right). Lengths in m.
// Regenerate: gmsh -2 -format msh2 two_material_plate.geo -o two_material_plate.msh
lc = 0.005;
Point(1) = {0, 0, 0, lc};
Point(2) = {0.03, 0, 0, lc};
Point(3) = {0.05, 0, 0, lc};
Point(4) = {0.05, 0.02, 0, lc};
Point(5) = {0.03, 0.02, 0, lc};
Point(6) = {0, 0.02, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 1};
Line(7) = {2, 5};
Curve Loop(1) = {1, 7, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7};
Plane Surface(2) = {2};
Transfinite Surface{1, 2};
Recombine Surface{1, 2};
Physical Surface(1) = {1};
Physical Surface(2) = {2};
Physical Curve(1) = {6};
Physical Curve(2) = {3};
