// Quarter of a thick cylinder, inner radius a = 10, outer radius b = 20,
// meshed by Gmsh into second-order quadrilaterals without centre node (CPS8).
// Export:  gmsh -2 -format inp lame_quarter.geo -o lame_quarter_mesh.inp
// Physical curves become T3D3 line elements (no stiffness in tether) whose
// sets name the loaded faces; Mesh.SaveGroupsOfNodes = 1 adds node sets.
a = 10; b = 20;
Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0}; Point(3) = {b, 0, 0};
Point(4) = {0, b, 0}; Point(5) = {0, a, 0};
Line(1) = {2, 3};          // y = 0
Circle(2) = {3, 1, 4};     // outer arc
Line(3) = {4, 5};          // x = 0
Circle(4) = {5, 1, 2};     // inner arc
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 9;
Transfinite Curve{2, 4} = 17;
Transfinite Surface{1};
Recombine Surface{1};
Physical Curve("INNER") = {4};
Physical Curve("OUTER") = {2};
Physical Curve("YSYM") = {1};   // the x axis: u_y = 0
Physical Curve("XSYM") = {3};   // the y axis: u_x = 0
Physical Surface("CYLINDER") = {1};
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 1;
Mesh.SaveGroupsOfNodes = 1;
