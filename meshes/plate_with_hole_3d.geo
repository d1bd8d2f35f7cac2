// Quarter of a square plate (half-width 0.1 m, thickness t = 0.01 m) with a
// central circular hole of radius a = 0.01 m on the z axis (3D Kirsch problem):
// plate_with_hole_2d extruded in z by t with 2 hexahedral layers.
// Lengths in m. All elements hexahedra.
//
// Regenerate:  gmsh -3 -format msh22 plate_with_hole_3d.geo -o plate_with_hole_3d.msh
// Finer (nested) sibling, every element split into k x k x k, here k = 2:
//              gmsh -3 -format msh22 -clscale 0.5 plate_with_hole_3d.geo -o plate_with_hole_3d_k2.msh
// (-clscale must be 1/k with integer k; it sets Mesh.MeshSizeFactor, read below.)
//
// Material id 1 (physical volume 1).
// Boundary ids (physical surfaces):
//   1: x = 0,   a <= y <= 0.1  (symmetry)
//   2: y = 0,   a <= x <= 0.1  (symmetry)
//   3: x = 0.1                  (loaded in tension)
//   4: y = 0.1                  (free)
//   5: hole surface r = a
//   6: z = 0
//   7: z = t
// In-plane mesh identical to plate_with_hole_2d.geo (keep the two in sync).
Mesh.MshFileVersion = 2.2;

a = 0.01;      // hole radius
L = 0.1;       // plate half-width
k = Round(1 / Mesh.MeshSizeFactor);  // refinement factor from -clscale 1/k
If (k < 1)
  k = 1;
EndIf
nr = 20 * k;   // radial elements
nc = 8 * k;    // circumferential elements per 45-degree block
// Geometric progressions (ratio of successive radial element sizes, hole -> out)
// chosen so that the first element at the hole is a/8 = 1.25e-3 m for nr = 20:
//   along the axes (length L - a = 0.09):                 1.1199 (last ~0.0108)
//   along the diagonal (length sqrt(2) L - a = 0.1314):    1.1522 (last ~0.0184)
// For k > 1 the ratio is r^(1/k), so the refined mesh is nested in the coarse one.
rx = 1.1199371717705349^(1 / k);
rd = 1.1521874565701897^(1 / k);

c = a / Sqrt(2);
Point(1) = {0, 0, 0};     // hole centre (only used for the arcs)
Point(2) = {a, 0, 0};
Point(3) = {L, 0, 0};
Point(4) = {L, L, 0};
Point(5) = {0, L, 0};
Point(6) = {0, a, 0};
Point(7) = {c, c, 0};

Line(1) = {2, 3};         // y = 0   (outward from the hole)
Line(2) = {3, 4};         // x = L
Line(3) = {4, 5};         // y = L
Line(4) = {6, 5};         // x = 0   (outward from the hole)
Line(5) = {7, 4};         // diagonal (outward from the hole), interior
Circle(6) = {2, 1, 7};    // hole arc, 0 .. 45 degrees
Circle(7) = {7, 1, 6};    // hole arc, 45 .. 90 degrees

Curve Loop(1) = {1, 2, -5, -6};
Plane Surface(1) = {1};
Curve Loop(2) = {5, 3, -4, -7};
Plane Surface(2) = {2};

Transfinite Curve{1, 4} = nr + 1 Using Progression rx;
Transfinite Curve{5} = nr + 1 Using Progression rd;
Transfinite Curve{2, 3, 6, 7} = nc + 1;
Transfinite Surface{1} = {2, 3, 4, 7};
Transfinite Surface{2} = {7, 4, 5, 6};
Recombine Surface{1, 2};

t = 0.01;      // thickness
nz = 2 * k;    // hexahedral layers through the thickness
ex1[] = Extrude {0, 0, t} { Surface{1}; Layers{nz}; Recombine; };
ex2[] = Extrude {0, 0, t} { Surface{2}; Layers{nz}; Recombine; };

eps = 1e-6;
Physical Volume(1) = {ex1[1], ex2[1]};
Physical Surface(1) = Surface In BoundingBox {-eps, a - eps, -eps, eps, L + eps, t + eps};
Physical Surface(2) = Surface In BoundingBox {a - eps, -eps, -eps, L + eps, eps, t + eps};
Physical Surface(3) = Surface In BoundingBox {L - eps, -eps, -eps, L + eps, L + eps, t + eps};
Physical Surface(4) = Surface In BoundingBox {-eps, L - eps, -eps, L + eps, L + eps, t + eps};
Physical Surface(5) = Surface In BoundingBox {-eps, -eps, -eps, a + eps, a + eps, t + eps};
Physical Surface(6) = {1, 2};
Physical Surface(7) = {ex1[0], ex2[0]};
