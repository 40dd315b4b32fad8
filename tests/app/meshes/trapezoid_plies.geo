// The trapezoid of trapezoid_quads.geo (unstructured quadrilaterals of a
// Blossom recombination: neighbouring cells start their vertex numbering
// at unrelated corners) extruded ply by ply into hexahedra, plies
// [0/45/90/-30] of 0.25, 0.15, 0.3 and 0.2 mm, two element layers each:
// the 3D file of the Gmsh patch test with a refinement region
// (tests/app/patch_test.cc), meshed as it is read.
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
thickness[] = {0.25, 0.15, 0.3, 0.2};
bottom = 1;
For p In {0 : 3}
  out[] = Extrude {0, 0, thickness[p]} {
    Surface{bottom}; Layers{2}; Recombine;
  };
  // out[0]: the top, out[1]: the volume, out[2..5]: the sides of the
  // lines 1..4.
  ply[p] = out[1];
  side_y_minus[p] = out[2];
  side_x_plus[p] = out[3];
  side_y_plus[p] = out[4];
  side_x_minus[p] = out[5];
  bottom = out[0];
EndFor
Physical Volume("ply 1") = {ply[0]};
Physical Volume("ply 2") = {ply[1]};
Physical Volume("ply 3") = {ply[2]};
Physical Volume("ply 4") = {ply[3]};
Physical Surface("y-") = {side_y_minus[]};
Physical Surface("x+") = {side_x_plus[]};
Physical Surface("y+") = {side_y_plus[]};
Physical Surface("x-") = {side_x_minus[]};
