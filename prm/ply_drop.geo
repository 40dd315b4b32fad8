// A symmetric external ply drop, the upper half: ply 1 (0.5 mm, the
// half of the continuous plies) runs the whole length 0 < x < 16 mm,
// ply 2 (0.5 mm, a terminated outer ply) stops at x = 10 mm. The width
// is 1 mm. Meshed by extruding the (x, y) rectangles ply by ply into
// hexahedra: 0.2 mm along x where ply 2 can delaminate, 0.5 mm beyond,
// two element layers per ply. The scene prm/ply_drop.prm.
drop = 10;
length = 16;
width = 1;
t = 0.5;
Point(1) = {0, 0, 0};
Point(2) = {drop, 0, 0};
Point(3) = {drop, width, 0};
Point(4) = {0, width, 0};
Point(5) = {length, 0, 0};
Point(6) = {length, width, 0};
Line(1) = {1, 2};
Line(2) = {2, 3}; // x = drop, shared by both rectangles
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {2, 5};
Line(6) = {5, 6};
Line(7) = {6, 3};
Transfinite Curve{1, 3} = 51;
Transfinite Curve{5, 7} = 13;
Transfinite Curve{2, 4, 6} = 2;
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, -2};
Plane Surface(1) = {1}; // under the dropped ply
Plane Surface(2) = {2}; // beyond the drop
Transfinite Surface{1, 2};
Recombine Surface{1, 2};
// out[0]: the top, out[1]: the volume, out[2..]: the sides of the loop's
// curves in order.
a[] = Extrude {0, 0, t} { Surface{1}; Layers{2}; Recombine; };
b[] = Extrude {0, 0, t} { Surface{2}; Layers{2}; Recombine; };
c[] = Extrude {0, 0, t} { Surface{a[0]}; Layers{2}; Recombine; };
Physical Volume("ply 1") = {a[1], b[1]};
Physical Volume("ply 2") = {c[1]};
Physical Surface("x-") = {a[5], c[5]};
Physical Surface("x+") = {b[3]};
Physical Surface("z-") = {1, 2};
