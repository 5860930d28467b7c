// Rigid sphere surface for plyimpact: a cubed sphere, six four-sided patches on the sphere (each a
// transfinite, recombined quad grid), so the surface is all quads with no pole singularity.
// Local frame: axis z, lowest point (the nose) at the origin, centre at (0, 0, R).
// Parameters, defined by plyimpact before this file is read (defaults for standalone use):
//   R  radius; N  elements along each patch edge (a quarter of the equator).
If (!Exists(R)) R = 8; EndIf
If (!Exists(N)) N = 6; EndIf
c = R / Sqrt(3);
Point(1) = {0, 0, R};
Point(2) = {-c, -c, R - c}; Point(3) = {c, -c, R - c}; Point(4) = {c, c, R - c}; Point(5) = {-c, c, R - c};
Point(6) = {-c, -c, R + c}; Point(7) = {c, -c, R + c}; Point(8) = {c, c, R + c}; Point(9) = {-c, c, R + c};
// Patch edges are great-circle arcs about the centre.
Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 4}; Circle(3) = {4, 1, 5}; Circle(4) = {5, 1, 2};
Circle(5) = {6, 1, 7}; Circle(6) = {7, 1, 8}; Circle(7) = {8, 1, 9}; Circle(8) = {9, 1, 6};
Circle(9) = {2, 1, 6}; Circle(10) = {3, 1, 7}; Circle(11) = {4, 1, 8}; Circle(12) = {5, 1, 9};
Curve Loop(1) = {1, 2, 3, 4};      Surface(1) = {1} In Sphere {1};   // bottom (nose)
Curve Loop(2) = {5, 6, 7, 8};      Surface(2) = {2} In Sphere {1};   // top
Curve Loop(3) = {1, 10, -5, -9};   Surface(3) = {3} In Sphere {1};
Curve Loop(4) = {2, 11, -6, -10};  Surface(4) = {4} In Sphere {1};
Curve Loop(5) = {3, 12, -7, -11};  Surface(5) = {5} In Sphere {1};
Curve Loop(6) = {4, 9, -8, -12};   Surface(6) = {6} In Sphere {1};
Transfinite Curve {1:12} = N + 1;
Transfinite Surface {1:6};
Recombine Surface {1:6};
Physical Surface("impactor_surface") = {1:6};
