// The disk of disk.geo (radius 2 at (2, 2), unstructured triangles)
// extruded ply by ply into wedges: the 3D .msh of the Gmsh patch test
// (tests/app/patch_test.cc), plies [0/45/90/-30] of 0.25, 0.15, 0.3 and
// 0.2 mm, two element layers each.
//   gmsh -3 disk_plies.geo -format msh41 -o disk_plies.msh
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
thickness[] = {0.25, 0.15, 0.3, 0.2};
bottom = 1;
For p In {0 : 3}
  out[] = Extrude {0, 0, thickness[p]} {
    Surface{bottom}; Layers{2}; Recombine;
  };
  // out[0]: the top, out[1]: the volume, out[2..5]: the sides of the
  // arcs 1..4.
  ply[p] = out[1];
  side_x_plus[p] = out[2];
  side_y_plus[p] = out[3];
  side_x_minus[p] = out[4];
  side_y_minus[p] = out[5];
  bottom = out[0];
EndFor
// Named out of order: the ply comes from the name, not the tag.
Physical Volume("ply 3") = {ply[2]};
Physical Volume("ply 1") = {ply[0]};
Physical Volume("ply 4") = {ply[3]};
Physical Volume("ply 2") = {ply[1]};
Physical Surface("x+") = {side_x_plus[]};
Physical Surface("y+") = {side_y_plus[]};
Physical Surface("x-") = {side_x_minus[]};
Physical Surface("y-") = {side_y_minus[]};
Physical Surface("z-") = {1};
Physical Surface("z+") = {bottom};
