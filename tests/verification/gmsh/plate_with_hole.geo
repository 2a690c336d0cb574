// Quarter of a square plate 2L x 2L with a central hole of radius a, for the
// Kirsch stress concentration (tests/verification/gmsh_plate_test.cpp).
//
// Recipe for a mesh tether reads (gmsh 4.8):
//   gmsh -2 plate_with_hole.geo -format inp -o plate_with_hole_mesh.inp
// and a deck that *INCLUDEs it (plate_with_hole.inp beside this file).
//  - Only the surface is a physical group, and Mesh.SaveAll = 0 (the default):
//    gmsh then writes only the 2D elements (here CPS8), no T3D2/T3D3 line
//    elements, which tether (like any 2D solver) refuses.
//  - Mesh.SaveGroupsOfNodes = -1 writes one *NSET per curve, named LINE<tag>
//    after the curve's tag below; the deck uses them for boundary conditions.
//  - Node lines carry x, y, z (z = 0); tether ignores a zero z.
//  - Quadrilaterals come from recombination. Algorithm 8 (Frontal-Delaunay for
//    quads) crashes gmsh 4.8.4 on this geometry; 6 (Frontal-Delaunay) + recombine works.
//  - ElementOrder 2 with SecondOrderIncomplete = 1 gives 8-node quads (CPS8).
//    gmsh always names 2D elements CPS* (plane stress); for plane strain or
//    axisymmetry rename CPS to CPE or CAX in the mesh file.
a = 1;      // hole radius
L = 20;     // half width of the plate: d/W = 0.05
h_hole = 0.08;
h_far = 2;
Point(1) = {0, 0, 0, h_hole};   // hole centre (not meshed)
Point(2) = {a, 0, 0, h_hole};
Point(3) = {L, 0, 0, h_far};
Point(4) = {L, L, 0, h_far};
Point(5) = {0, L, 0, h_far};
Point(6) = {0, a, 0, h_hole};
Line(1) = {2, 3};       // LINE1: y = 0, symmetry
Line(2) = {3, 4};       // LINE2: x = L, loaded edge
Line(3) = {4, 5};       // LINE3: y = L, free
Line(4) = {5, 6};       // LINE4: x = 0, symmetry
Circle(5) = {6, 1, 2};  // LINE5: the hole
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
Physical Surface("PLATE") = {1};
Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 1;
Mesh.SaveGroupsOfNodes = -1;
