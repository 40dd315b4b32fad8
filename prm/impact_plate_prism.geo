// The in-plane mesh of prm/impact_plate_prism.prm: the quarter of a
// 60 x 60 mm plate (its corner (0, 0) is the plate's centre, where the
// pulse lands) in unstructured triangles, 0.5 mm (the element size of
// prm/impact_plate.prm) within 10 mm of the impact, growing to 2.5 mm from
// 25 mm on: the seed's fine prisms in the impact zone and coarser ones
// outside. Its four sides are the faces x-, x+, y-, y+ of the boundary
// conditions.
L = 30;
Point(1) = {0, 0, 0};
Point(2) = {L, 0, 0};
Point(3) = {L, L, 0};
Point(4) = {0, L, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Field[1] = Distance;
Field[1].PointsList = {1};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = 0.5;
Field[2].SizeMax = 2.5;
Field[2].DistMin = 10;
Field[2].DistMax = 25;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Physical Curve("y-") = {1};
Physical Curve("x+") = {2};
Physical Curve("y+") = {3};
Physical Curve("x-") = {4};
Physical Surface("laminate") = {1};
