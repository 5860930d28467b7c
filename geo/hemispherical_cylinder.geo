// Hemispherical-nosed cylinder (the ASTM D7136 tup) for plyimpact, all hexahedra: an O-grid.
// The nose is the lower half of a cubed sphere: a half-cube core (half-width A) under five shell
// blocks (one under the bottom patch, four under the side patches, which end at the equator). The
// body continues the equator's cross-section (a square core and four ring blocks) up to the flat
// top. Every block is a transfinite, recombined volume. The rigid impactor uses the boundary of
// this mesh, the deformable one all of it.
// Local frame: axis z, nose tip at the origin, nose centre at (0, 0, R), top face at z = L.
// Parameters, defined by plyimpact before this file is read (defaults for standalone use):
//   R radius; L overall length (> R); N elements per quarter circumference; M elements along the
//   body; K elements through the shell; A core half-width (default R / (2 Sqrt(3)), as sphere.geo).
// Numbering: outer point p (3-14), its core twin p + 20, the radial line from twin to p is 50 + p;
// outer curve i (1-20), its core twin 20 + i, the radial face through both is surface 40 + i;
// outer patch f (1-9), its core twin 20 + f.
If (!Exists(R)) R = 8; EndIf
If (!Exists(L)) L = 40; EndIf
If (!Exists(N)) N = 6; EndIf
If (!Exists(M)) M = 8; EndIf
If (!Exists(K)) K = 4; EndIf
If (!Exists(A)) A = R / (2 * Sqrt(3)); EndIf
c = R / Sqrt(3);
e = R / Sqrt(2);
Point(1) = {0, 0, R};        // nose centre
Point(2) = {0, 0, L};        // top centre
Point(3) = {-c, -c, R - c}; Point(4) = {c, -c, R - c}; Point(5) = {c, c, R - c}; Point(6) = {-c, c, R - c};
Point(7) = {-e, -e, R};     Point(8) = {e, -e, R};     Point(9) = {e, e, R};     Point(10) = {-e, e, R};
Point(11) = {-e, -e, L};    Point(12) = {e, -e, L};    Point(13) = {e, e, L};    Point(14) = {-e, e, L};
Point(23) = {-A, -A, R - A}; Point(24) = {A, -A, R - A}; Point(25) = {A, A, R - A}; Point(26) = {-A, A, R - A};
Point(27) = {-A, -A, R};     Point(28) = {A, -A, R};     Point(29) = {A, A, R};     Point(30) = {-A, A, R};
Point(31) = {-A, -A, L};     Point(32) = {A, -A, L};     Point(33) = {A, A, L};     Point(34) = {-A, A, L};
Circle(1) = {3, 1, 4};  Circle(2) = {4, 1, 5};  Circle(3) = {5, 1, 6};  Circle(4) = {6, 1, 3};     // nose patch
Circle(5) = {3, 1, 7};  Circle(6) = {4, 1, 8};  Circle(7) = {5, 1, 9};  Circle(8) = {6, 1, 10};    // meridians
Circle(9) = {7, 1, 8};  Circle(10) = {8, 1, 9}; Circle(11) = {9, 1, 10}; Circle(12) = {10, 1, 7};  // equator
Line(13) = {7, 11};     Line(14) = {8, 12};     Line(15) = {9, 13};     Line(16) = {10, 14};      // body
Circle(17) = {11, 2, 12}; Circle(18) = {12, 2, 13}; Circle(19) = {13, 2, 14}; Circle(20) = {14, 2, 11};  // top rim
S[] = {3, 4, 5, 6, 3, 4, 5, 6, 7, 8, 9, 10, 7, 8, 9, 10, 11, 12, 13, 14};    // start point of curve i: S[i - 1]
E[] = {4, 5, 6, 3, 7, 8, 9, 10, 8, 9, 10, 7, 11, 12, 13, 14, 12, 13, 14, 11}; // end point of curve i
For i In {1:20}
  Line(20 + i) = {S[i - 1] + 20, E[i - 1] + 20};   // the core's edges are straight
EndFor
For p In {3:14}
  Line(50 + p) = {p + 20, p};
EndFor
Curve Loop(1) = {1, 2, 3, 4};       Surface(1) = {1} In Sphere {1};
Curve Loop(2) = {1, 6, -9, -5};     Surface(2) = {2} In Sphere {1};
Curve Loop(3) = {2, 7, -10, -6};    Surface(3) = {3} In Sphere {1};
Curve Loop(4) = {3, 8, -11, -7};    Surface(4) = {4} In Sphere {1};
Curve Loop(5) = {4, 5, -12, -8};    Surface(5) = {5} In Sphere {1};
Curve Loop(6) = {9, 14, -17, -13};  Surface(6) = {6};   // Coons patch of two arcs: the exact cylinder
Curve Loop(7) = {10, 15, -18, -14}; Surface(7) = {7};
Curve Loop(8) = {11, 16, -19, -15}; Surface(8) = {8};
Curve Loop(9) = {12, 13, -20, -16}; Surface(9) = {9};
// Core twins of patches 1-9 (flat), the core's top square (10) and its equator section (30).
Curve Loop(21) = {21, 22, 23, 24};      Plane Surface(21) = {21};
Curve Loop(22) = {21, 26, -29, -25};    Plane Surface(22) = {22};
Curve Loop(23) = {22, 27, -30, -26};    Plane Surface(23) = {23};
Curve Loop(24) = {23, 28, -31, -27};    Plane Surface(24) = {24};
Curve Loop(25) = {24, 25, -32, -28};    Plane Surface(25) = {25};
Curve Loop(26) = {29, 34, -37, -33};    Plane Surface(26) = {26};
Curve Loop(27) = {30, 35, -38, -34};    Plane Surface(27) = {27};
Curve Loop(28) = {31, 36, -39, -35};    Plane Surface(28) = {28};
Curve Loop(29) = {32, 33, -40, -36};    Plane Surface(29) = {29};
Curve Loop(10) = {37, 38, 39, 40};      Plane Surface(10) = {10};
Curve Loop(30) = {29, 30, 31, 32};      Plane Surface(30) = {30};
// Radial faces: outer curve i from point s to point e -> {core twin, radial at e, -i, -radial at s}.
// Those of the top rim (57-60) are the top face's ring, those of the equator (49-52) the section.
For i In {1:20}
  Curve Loop(40 + i) = {20 + i, 50 + E[i - 1], -i, -(50 + S[i - 1])};
  Surface(40 + i) = {40 + i};
EndFor
Surface Loop(1) = {21, 22, 23, 24, 25, 30};  Volume(1) = {1};    // nose core
Surface Loop(2) = {1, 21, 41, 42, 43, 44};   Volume(2) = {2};    // nose shell, bottom
Surface Loop(3) = {2, 22, 41, 46, 49, 45};   Volume(3) = {3};    // nose shell, sides
Surface Loop(4) = {3, 23, 42, 47, 50, 46};   Volume(4) = {4};
Surface Loop(5) = {4, 24, 43, 48, 51, 47};   Volume(5) = {5};
Surface Loop(6) = {5, 25, 44, 45, 52, 48};   Volume(6) = {6};
Surface Loop(7) = {30, 10, 26, 27, 28, 29};  Volume(7) = {7};    // body core
Surface Loop(8) = {6, 26, 49, 54, 57, 53};   Volume(8) = {8};    // body ring
Surface Loop(9) = {7, 27, 50, 55, 58, 54};   Volume(9) = {9};
Surface Loop(10) = {8, 28, 51, 56, 59, 55};  Volume(10) = {10};
Surface Loop(11) = {9, 29, 52, 53, 60, 56};  Volume(11) = {11};
Transfinite Curve {1:12, 17:32, 37:40} = N + 1;
Transfinite Curve {13:16, 33:36} = M + 1;
Transfinite Curve {53:64} = K + 1;
Transfinite Surface {1:10, 21:30, 41:60};
Recombine Surface {1:10, 21:30, 41:60};
Transfinite Volume {1:11};
Recombine Volume {1:11};
Physical Volume("impactor") = {1:11};
