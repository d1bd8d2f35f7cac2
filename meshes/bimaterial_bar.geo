// The bimaterial bar of seed 000, example 8.2 (doc/benchmarks/antiplane_bimaterial): the
// section |x| <= 0.1, |y| <= 0.5 split at y = 0 into physical surface 1 (y < 0, mu1) and 2
// (y > 0, mu2); 2 x 10 square quadrilaterals of 0.1. Boundary ids: 1 the bottom face y = -0.5
// (clamped), 2 the top face y = 0.5 (loaded); the sides carry none (id 0, free).
// Regenerate: gmsh -2 -format msh22 bimaterial_bar.geo -o bimaterial_bar.msh
Point(1) = {-0.1, -0.5, 0};
Point(2) = {0.1, -0.5, 0};
Point(3) = {0.1, 0, 0};
Point(4) = {0.1, 0.5, 0};
Point(5) = {-0.1, 0.5, 0};
Point(6) = {-0.1, 0, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 1};
Line(7) = {6, 3};
Curve Loop(1) = {1, 2, -7, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {7, 3, 4, 5};
Plane Surface(2) = {2};
Transfinite Curve{1, 4, 7} = 3;
Transfinite Curve{2, 3, 5, 6} = 6;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};
Physical Surface(1) = {1};
Physical Surface(2) = {2};
Physical Curve(1) = {1};
Physical Curve(2) = {4};
