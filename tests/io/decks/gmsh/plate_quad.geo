// The 2 x 1 plate of plate_tri.geo, recombined into quadrilaterals (CPS4, or
// CPS8 when make_fixtures.sh asks for order 2 without centre node).
h = 0.5;
Point(1) = {0, 0, 0, h}; Point(2) = {2, 0, 0, h}; Point(3) = {2, 1, 0, h}; Point(4) = {0, 1, 0, h};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 5; Transfinite Curve{2, 4} = 3;
Transfinite Surface{1};
Recombine Surface{1};
Physical Curve("LEFT") = {4};
Physical Curve("RIGHT") = {2};
Physical Surface("PLATE") = {1};
Mesh.SaveGroupsOfNodes = 1;
