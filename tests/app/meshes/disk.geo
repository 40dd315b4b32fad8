// A disk of radius 2 centred at (2, 2), unstructured triangles: the
// in-plane outline of the Gmsh patch test (tests/app/patch_test.cc). Its
// four arcs are the faces x+, y+, x-, y- of the Boundary conditions.
h = 0.7;
Point(1) = {2, 2, 0, h};
Point(2) = {4, 2, 0, h};
Point(3) = {2, 4, 0, h};
Point(4) = {0, 2, 0, h};
Point(5) = {2, 0, 0, h};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("x+") = {1};
Physical Curve("y+") = {2};
Physical Curve("x-") = {3};
Physical Curve("y-") = {4};
Physical Surface("laminate") = {1};
