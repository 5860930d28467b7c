// Flat-ended cylinder (a flat punch) for plyimpact, all hexahedra: an O-grid disc (a square core
// of half-width A and four ring blocks) extruded along the axis in M layers. The rigid impactor
// uses the boundary of this mesh, the deformable one all of it.
// Local frame: axis z, flat impacting face at z = 0 (centred on the axis), top face at z = L.
// Parameters, defined by plyimpact before this file is read (defaults for standalone use):
//   R radius; L length; N elements per quarter circumference; M elements along the axis; K elements
//   through the ring (core to surface); A core half-width (default R / (2 Sqrt(2)): the core corners
//   sit at R / 2).
If (!Exists(R)) R = 8; EndIf
If (!Exists(L)) L = 16; EndIf
If (!Exists(N)) N = 6; EndIf
If (!Exists(M)) M = 8; EndIf
If (!Exists(K)) K = 4; EndIf
If (!Exists(A)) A = R / (2 * Sqrt(2)); EndIf
e = R / Sqrt(2);
Point(1) = {0, 0, 0};
Point(2) = {-e, -e, 0}; Point(3) = {e, -e, 0}; Point(4) = {e, e, 0}; Point(5) = {-e, e, 0};
Point(22) = {-A, -A, 0}; Point(23) = {A, -A, 0}; Point(24) = {A, A, 0}; Point(25) = {-A, A, 0};
Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 4}; Circle(3) = {4, 1, 5}; Circle(4) = {5, 1, 2};   // rim
Line(21) = {22, 23}; Line(22) = {23, 24}; Line(23) = {24, 25}; Line(24) = {25, 22};           // core
For p In {2:5}
  Line(50 + p) = {p + 20, p};   // radial
EndFor
Curve Loop(1) = {21, 22, 23, 24};    Plane Surface(1) = {1};
Curve Loop(2) = {21, 53, -1, -52};   Plane Surface(2) = {2};
Curve Loop(3) = {22, 54, -2, -53};   Plane Surface(3) = {3};
Curve Loop(4) = {23, 55, -3, -54};   Plane Surface(4) = {4};
Curve Loop(5) = {24, 52, -4, -55};   Plane Surface(5) = {5};
Transfinite Curve {1:4, 21:24} = N + 1;
Transfinite Curve {52:55} = K + 1;
Transfinite Surface {1:5};
Recombine Surface {1:5};
out[] = Extrude {0, 0, L} { Surface{1:5}; Layers{M}; Recombine; };
Physical Volume("impactor") = {out[1], out[7], out[13], out[19], out[25]};
