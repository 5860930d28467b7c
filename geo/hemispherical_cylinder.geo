// Rigid hemispherical-nosed cylinder (the ASTM D7136 tup) for plyimpact: the nose is the lower
// half of a cubed sphere (a bottom patch and four side patches), the body four cylindrical
// patches, the top a flat four-sided cap. Every patch is transfinite and recombined: all quads.
// Local frame: axis z, nose tip at the origin, nose centre at (0, 0, R), top face at z = L.
// Parameters, defined by plyimpact before this file is read (defaults for standalone use):
//   R radius; L overall length (> R); N elements per quarter circumference; M elements along the body.
If (!Exists(R)) R = 8; EndIf
If (!Exists(L)) L = 40; EndIf
If (!Exists(N)) N = 6; EndIf
If (!Exists(M)) M = 8; EndIf
c = R / Sqrt(3);
e = R / Sqrt(2);
Point(1) = {0, 0, R};        // nose centre
Point(2) = {0, 0, L};        // top centre
Point(3) = {-c, -c, R - c}; Point(4) = {c, -c, R - c}; Point(5) = {c, c, R - c}; Point(6) = {-c, c, R - c};
Point(7) = {-e, -e, R};     Point(8) = {e, -e, R};     Point(9) = {e, e, R};     Point(10) = {-e, e, R};
Point(11) = {-e, -e, L};    Point(12) = {e, -e, L};    Point(13) = {e, e, L};    Point(14) = {-e, e, L};
Circle(1) = {3, 1, 4};  Circle(2) = {4, 1, 5};  Circle(3) = {5, 1, 6};  Circle(4) = {6, 1, 3};     // nose patch
Circle(5) = {3, 1, 7};  Circle(6) = {4, 1, 8};  Circle(7) = {5, 1, 9};  Circle(8) = {6, 1, 10};    // meridians
Circle(9) = {7, 1, 8};  Circle(10) = {8, 1, 9}; Circle(11) = {9, 1, 10}; Circle(12) = {10, 1, 7};  // equator
Line(13) = {7, 11};     Line(14) = {8, 12};     Line(15) = {9, 13};     Line(16) = {10, 14};      // body
Circle(17) = {11, 2, 12}; Circle(18) = {12, 2, 13}; Circle(19) = {13, 2, 14}; Circle(20) = {14, 2, 11};  // top rim
Curve Loop(1) = {1, 2, 3, 4};       Surface(1) = {1} In Sphere {1};
Curve Loop(2) = {1, 6, -9, -5};     Surface(2) = {2} In Sphere {1};
Curve Loop(3) = {2, 7, -10, -6};    Surface(3) = {3} In Sphere {1};
Curve Loop(4) = {3, 8, -11, -7};    Surface(4) = {4} In Sphere {1};
Curve Loop(5) = {4, 5, -12, -8};    Surface(5) = {5} In Sphere {1};
Curve Loop(6) = {9, 14, -17, -13};  Surface(6) = {6};   // Coons patch of two arcs: the exact cylinder
Curve Loop(7) = {10, 15, -18, -14}; Surface(7) = {7};
Curve Loop(8) = {11, 16, -19, -15}; Surface(8) = {8};
Curve Loop(9) = {12, 13, -20, -16}; Surface(9) = {9};
Curve Loop(10) = {17, 18, 19, 20};  Plane Surface(10) = {10};   // top cap
Transfinite Curve {1:12, 17:20} = N + 1;
Transfinite Curve {13:16} = M + 1;
Transfinite Surface {1:10};
Recombine Surface {1:10};
Physical Surface("impactor_surface") = {1:10};
