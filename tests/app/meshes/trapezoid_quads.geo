// A trapezoid meshed with quadrilaterals (Blossom full-quad recombination of an
// unstructured triangulation): the source of trapezoid_quads.msh, the
// .msh of the Gmsh patch test on hexahedra (tests/app/patch_test.cc).
//   gmsh -2 trapezoid_quads.geo -format msh41 -o trapezoid_quads.msh
h = 0.9;
Point(1) = {0, 0, 0, h};
Point(2) = {4, 0, 0, h};
Point(3) = {3.2, 3, 0, h};
Point(4) = {0.5, 2.6, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Recombine Surface {1};
Mesh.RecombinationAlgorithm = 2;
Physical Curve("y-") = {1};
Physical Curve("x+") = {2};
Physical Curve("y+") = {3};
Physical Curve("x-") = {4};
Physical Surface("laminate") = {1};
