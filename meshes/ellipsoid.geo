// All-quadrilateral surface mesh of the ellipsoid x²/a² + y²/b² + z²/c² = 1 (default: the seed's
// prolate [0.61, 0.61, 2.02]): the six faces of a cube projected onto the unit sphere as
// structured (transfinite) quadrilateral patches, then stretched by the semi-axes.
//   gmsh -2 ellipsoid.geo -o ellipsoid.msh        (ASCII msh 2.2, 6 n² quadrilaterals)
// Change n (cells per cube edge) or a, b, c with -setnumber, e.g. gmsh -2 -setnumber n 8 ellipsoid.geo
If (!Exists(n)) n = 6; EndIf
If (!Exists(a)) a = 0.61; EndIf
If (!Exists(b)) b = 0.61; EndIf
If (!Exists(c)) c = 2.02; EndIf
s = 1 / Sqrt(3);
Point(1) = {0, 0, 0};
Point(2) = {-s, -s, -s}; Point(3) = { s, -s, -s}; Point(4) = { s,  s, -s}; Point(5) = {-s,  s, -s};
Point(6) = {-s, -s,  s}; Point(7) = { s, -s,  s}; Point(8) = { s,  s,  s}; Point(9) = {-s,  s,  s};
// Great-circle arcs along the twelve cube edges.
Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 4}; Circle(3) = {4, 1, 5}; Circle(4) = {5, 1, 2};
Circle(5) = {6, 1, 7}; Circle(6) = {7, 1, 8}; Circle(7) = {8, 1, 9}; Circle(8) = {9, 1, 6};
Circle(9) = {2, 1, 6}; Circle(10) = {3, 1, 7}; Circle(11) = {4, 1, 8}; Circle(12) = {5, 1, 9};
// Faces oriented with outward normals.
Curve Loop(1) = {-1, -4, -3, -2}; Surface(1) = {1} In Sphere {1};  // z = -1
Curve Loop(2) = {5, 6, 7, 8};     Surface(2) = {2} In Sphere {1};  // z = +1
Curve Loop(3) = {1, 10, -5, -9};  Surface(3) = {3} In Sphere {1};  // y = -1
Curve Loop(4) = {3, 12, -7, -11}; Surface(4) = {4} In Sphere {1};  // y = +1
Curve Loop(5) = {2, 11, -6, -10}; Surface(5) = {5} In Sphere {1};  // x = +1
Curve Loop(6) = {4, 9, -8, -12};  Surface(6) = {6} In Sphere {1};  // x = -1
Transfinite Curve {1:12} = n + 1;
Transfinite Surface {1:6};
Recombine Surface {1:6};
Dilate {{0, 0, 0}, {a, b, c}} { Surface{1:6}; }
Physical Surface("surface") = {1:6};
Mesh.MshFileVersion = 2.2;
Mesh.Binary = 0;
