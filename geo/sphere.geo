// Sphere for plyimpact, all hexahedra: a cubed-sphere O-grid. A cubic core (half-width A) is
// surrounded by six shell blocks, one under each cubed-sphere patch of the surface (no pole
// singularity); every block is a transfinite, recombined volume. The rigid impactor uses the
// boundary of this mesh (6 N^2 quads), the deformable one all of it (N^3 + 6 N^2 K hexahedra).
// Local frame: axis z, lowest point (the nose) at the origin, centre at (0, 0, R).
// Parameters, defined by plyimpact before this file is read (defaults for standalone use):
//   R radius; N elements along each patch edge (a quarter of the equator); K elements through the
//   shell (core to surface); A core half-width (default R / (2 Sqrt(3)): the core corners sit at
//   R / 2, halfway out along the diagonals, keeping the diagonal shell elements well shaped).
// Numbering: outer point p (2-9), its core twin p + 20, the radial line from twin to p is 50 + p;
// outer curve i (1-12), its core twin 20 + i, the radial face through both is surface 40 + i;
// outer patch f (1-6), its core twin 20 + f; the core is volume 1, the shell under patch f is 1 + f.
If (!Exists(R)) R = 8; EndIf
If (!Exists(N)) N = 6; EndIf
If (!Exists(K)) K = 4; EndIf
If (!Exists(A)) A = R / (2 * Sqrt(3)); EndIf
c = R / Sqrt(3);
Point(1) = {0, 0, R};
Point(2) = {-c, -c, R - c}; Point(3) = {c, -c, R - c}; Point(4) = {c, c, R - c}; Point(5) = {-c, c, R - c};
Point(6) = {-c, -c, R + c}; Point(7) = {c, -c, R + c}; Point(8) = {c, c, R + c}; Point(9) = {-c, c, R + c};
Point(22) = {-A, -A, R - A}; Point(23) = {A, -A, R - A}; Point(24) = {A, A, R - A}; Point(25) = {-A, A, R - A};
Point(26) = {-A, -A, R + A}; Point(27) = {A, -A, R + A}; Point(28) = {A, A, R + A}; Point(29) = {-A, A, R + A};
// Patch edges are great-circle arcs about the centre; the core's edges are straight.
Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 4}; Circle(3) = {4, 1, 5}; Circle(4) = {5, 1, 2};
Circle(5) = {6, 1, 7}; Circle(6) = {7, 1, 8}; Circle(7) = {8, 1, 9}; Circle(8) = {9, 1, 6};
Circle(9) = {2, 1, 6}; Circle(10) = {3, 1, 7}; Circle(11) = {4, 1, 8}; Circle(12) = {5, 1, 9};
Line(21) = {22, 23}; Line(22) = {23, 24}; Line(23) = {24, 25}; Line(24) = {25, 22};
Line(25) = {26, 27}; Line(26) = {27, 28}; Line(27) = {28, 29}; Line(28) = {29, 26};
Line(29) = {22, 26}; Line(30) = {23, 27}; Line(31) = {24, 28}; Line(32) = {25, 29};
For p In {2:9}
  Line(50 + p) = {p + 20, p};
EndFor
// Outer patches (on the sphere) and their flat core twins.
Curve Loop(1) = {1, 2, 3, 4};      Surface(1) = {1} In Sphere {1};   // bottom (nose)
Curve Loop(2) = {5, 6, 7, 8};      Surface(2) = {2} In Sphere {1};   // top
Curve Loop(3) = {1, 10, -5, -9};   Surface(3) = {3} In Sphere {1};
Curve Loop(4) = {2, 11, -6, -10};  Surface(4) = {4} In Sphere {1};
Curve Loop(5) = {3, 12, -7, -11};  Surface(5) = {5} In Sphere {1};
Curve Loop(6) = {4, 9, -8, -12};   Surface(6) = {6} In Sphere {1};
Curve Loop(21) = {21, 22, 23, 24};     Plane Surface(21) = {21};
Curve Loop(22) = {25, 26, 27, 28};     Plane Surface(22) = {22};
Curve Loop(23) = {21, 30, -25, -29};   Plane Surface(23) = {23};
Curve Loop(24) = {22, 31, -26, -30};   Plane Surface(24) = {24};
Curve Loop(25) = {23, 32, -27, -31};   Plane Surface(25) = {25};
Curve Loop(26) = {24, 29, -28, -32};   Plane Surface(26) = {26};
// Radial faces: outer curve i from point s to point e -> {core twin, radial at e, -i, -radial at s}.
S[] = {2, 3, 4, 5, 6, 7, 8, 9, 2, 3, 4, 5};   // start point of curve i (1-based: S[i - 1])
E[] = {3, 4, 5, 2, 7, 8, 9, 6, 6, 7, 8, 9};   // end point of curve i
For i In {1:12}
  Curve Loop(40 + i) = {20 + i, 50 + E[i - 1], -i, -(50 + S[i - 1])};
  Surface(40 + i) = {40 + i};   // planar (a great-circle plane), filled as a Coons patch
EndFor
Surface Loop(1) = {21, 22, 23, 24, 25, 26};  Volume(1) = {1};
Surface Loop(2) = {1, 21, 41, 42, 43, 44};   Volume(2) = {2};
Surface Loop(3) = {2, 22, 45, 46, 47, 48};   Volume(3) = {3};
Surface Loop(4) = {3, 23, 41, 50, 45, 49};   Volume(4) = {4};
Surface Loop(5) = {4, 24, 42, 51, 46, 50};   Volume(5) = {5};
Surface Loop(6) = {5, 25, 43, 52, 47, 51};   Volume(6) = {6};
Surface Loop(7) = {6, 26, 44, 49, 48, 52};   Volume(7) = {7};
Transfinite Curve {1:12, 21:32} = N + 1;
Transfinite Curve {52:59} = K + 1;
Transfinite Surface {1:6, 21:26, 41:52};
Recombine Surface {1:6, 21:26, 41:52};
Transfinite Volume {1:7};
Recombine Volume {1:7};
Physical Volume("impactor") = {1:7};
