// A block 4 x 3 x 0.9 mm of the plies [0/45/90/-30] (0.25, 0.15, 0.3,
// 0.2 mm) meshed by extruding its x = 0 face along x: Gmsh's hexahedra
// then have their third axis along x, and the reader must turn them so
// that refinement in the plies' plane cuts the right axes (the .msh of
// tests/unit/volume_mesh.cc and of the Gmsh patch test on hexahedra).
//   gmsh -3 block_plies_x.geo -format msh41 -o block_plies_x.msh
z[] = {0, 0.25, 0.4, 0.7, 0.9};
For k In {0 : 4}
  Point(2 * k + 1) = {0, 0, z[k]};
  Point(2 * k + 2) = {0, 3, z[k]};
  Line(k + 1) = {2 * k + 1, 2 * k + 2}; // along y at z[k]
EndFor
For p In {0 : 3}
  Line(10 + p) = {2 * p + 1, 2 * p + 3}; // y = 0, through ply p
  Line(20 + p) = {2 * p + 2, 2 * p + 4}; // y = 3
  Curve Loop(p + 1) = {p + 1, 20 + p, -(p + 2), -(10 + p)};
  Plane Surface(p + 1) = {p + 1};
  Transfinite Curve{10 + p, 20 + p} = 3;
EndFor
Transfinite Curve{1 : 5} = 4;
Transfinite Surface{1 : 4};
Recombine Surface{1 : 4};
For p In {0 : 3}
  out[] = Extrude {4, 0, 0} {
    Surface{p + 1}; Layers{4}; Recombine;
  };
  // out[0]: the x = 4 face, out[1]: the volume, out[2..5]: the sides of
  // the curve loop's lines (z[p], y = 3, z[p+1], y = 0).
  ply[p] = out[1];
  x_plus[p] = out[0];
  lower[p] = out[2];
  y_plus[p] = out[3];
  upper[p] = out[4];
  y_minus[p] = out[5];
EndFor
Physical Volume("ply 1") = {ply[0]};
Physical Volume("ply 2") = {ply[1]};
Physical Volume("ply 3") = {ply[2]};
Physical Volume("ply 4") = {ply[3]};
Physical Surface("x-") = {1 : 4};
Physical Surface("x+") = {x_plus[]};
Physical Surface("y-") = {y_minus[]};
Physical Surface("y+") = {y_plus[]};
Physical Surface("z-") = {lower[0]};
Physical Surface("z+") = {upper[3]};
