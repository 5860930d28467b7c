// Cube (a fragment) for plyimpact, all hexahedra: a structured N x N x N block. The rigid impactor
// uses the boundary of this mesh, the deformable one all of it.
// Local frame: axis z, the impacting face at z = 0 (centred on the axis), edges along x, y, z.
// Parameters, defined by plyimpact before this file is read (defaults for standalone use):
//   D edge length; N elements along an edge.
If (!Exists(D)) D = 10; EndIf
If (!Exists(N)) N = 5; EndIf
Point(1) = {-D / 2, -D / 2, 0};
edge[] = Extrude {D, 0, 0} { Point{1}; Layers{N}; };
face[] = Extrude {0, D, 0} { Curve{edge[1]}; Layers{N}; Recombine; };
body[] = Extrude {0, 0, D} { Surface{face[1]}; Layers{N}; Recombine; };
Physical Volume("impactor") = {body[1]};
