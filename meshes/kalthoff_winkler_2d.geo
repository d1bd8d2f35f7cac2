// Kalthoff-Winkler plate, full geometry 0.2 m (x) x 0.1 m (y), origin at the
// lower-left corner; the impact edge is x = 0. No notches in the mesh (they
// are modelled in the peridynamic particle region). Lengths in m.
// Uniform structured quadrilaterals of 2 mm: 100 x 50 = 5000 elements.
//
// Regenerate:  gmsh -2 -format msh22 kalthoff_winkler_2d.geo -o kalthoff_winkler_2d.msh
// Finer (nested) sibling, every element split into k x k, here k = 2 (1 mm):
//              gmsh -2 -format msh22 -clscale 0.5 kalthoff_winkler_2d.geo -o kalthoff_winkler_2d_k2.msh
// (-clscale must be 1/k with integer k; it sets Mesh.MeshSizeFactor, read below.)
//
// Material id 1 (physical surface 1).
// Boundary ids (physical curves):
//   1: x = 0    (impact edge)
//   2: x = 0.2
//   3: y = 0
//   4: y = 0.1
Mesh.MshFileVersion = 2.2;

Lx = 0.2;
Ly = 0.1;
h = 0.002;     // element size
k = Round(1 / Mesh.MeshSizeFactor);  // refinement factor from -clscale 1/k
If (k < 1)
  k = 1;
EndIf
nx = Round(Lx / h) * k;
ny = Round(Ly / h) * k;

Point(1) = {0, 0, 0};
Point(2) = {Lx, 0, 0};
Point(3) = {Lx, Ly, 0};
Point(4) = {0, Ly, 0};
Line(1) = {1, 2};   // y = 0
Line(2) = {2, 3};   // x = Lx
Line(3) = {3, 4};   // y = Ly
Line(4) = {4, 1};   // x = 0
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Transfinite Curve{1, 3} = nx + 1;
Transfinite Curve{2, 4} = ny + 1;
Transfinite Surface{1};
Recombine Surface{1};

Physical Surface(1) = {1};
Physical Curve(1) = {4};
Physical Curve(2) = {2};
Physical Curve(3) = {1};
Physical Curve(4) = {3};
