// A 2 x 1 plate meshed with linear triangles (CPS3); physical curves become
// T3D2 line elements, and Mesh.SaveGroupsOfNodes = 1 adds a node set per group.
h = 0.5;
Point(1) = {0, 0, 0, h}; Point(2) = {2, 0, 0, h}; Point(3) = {2, 1, 0, h}; Point(4) = {0, 1, 0, h};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("LEFT") = {4};
Physical Curve("RIGHT") = {2};
Physical Curve("BOTTOM") = {1};
Physical Surface("PLATE") = {1};
Mesh.SaveGroupsOfNodes = 1;
