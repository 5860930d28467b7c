#!/usr/bin/env python3
"""Writes the mesh include files of the test decks (nodes, hexahedra, node sets), numbered as the
scene's box generator numbers a box (x fastest, then y, then z), in free (comma) format so every
coordinate keeps all its digits. Coordinates are computed as the box generator computes them
(origin + size * i / n, the end exactly origin + size). Run from this folder."""


def coord(origin, size, i, n):
    return origin + (size if i == n else size * i / n)


def block(origin, size, n):
    """Nodes (x fastest) and hexahedra of one structured block, 1-based ids."""
    nodes = []
    for k in range(n[2] + 1):
        for j in range(n[1] + 1):
            for i in range(n[0] + 1):
                nodes.append((coord(origin[0], size[0], i, n[0]), coord(origin[1], size[1], j, n[1]),
                              coord(origin[2], size[2], k, n[2])))

    def nid(i, j, k):
        return 1 + (k * (n[1] + 1) + j) * (n[0] + 1) + i

    hexes = []
    for k in range(n[2]):
        for j in range(n[1]):
            for i in range(n[0]):
                hexes.append((k, [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                                  nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)]))
    return nodes, hexes


def node_list(sid, ids):
    out = ["*SET_NODE_LIST", f"{sid:10d}"]
    for a in range(0, len(ids), 8):
        out.append("".join(f"{v:10d}" for v in ids[a:a + 8]))
    return out


def write(path, header, nodes, elements, sets):
    lines = [f"$ {h}" for h in header] + ["*NODE"]
    lines += [f"{i + 1},{x!r},{y!r},{z!r}" for i, (x, y, z) in enumerate(nodes)]
    lines.append("*ELEMENT_SOLID")
    lines += [",".join(map(str, [e + 1, pid] + c)) for e, (pid, c) in enumerate(elements)]
    for sid, ids in sets:
        lines += node_list(sid, ids)
    open(path, "w").write("\n".join(lines) + "\n*END\n")


# Rod: 1 x 1 x 100 elements, 1 mm square, 0.1 m long, 0.1 mm above the wall (SI).
nodes, hexes = block((0, 0, 0.0001), (0.001, 0.001, 0.1), (1, 1, 100))
write("rod_wall_mesh.k", ["Rod mesh (SI): 1 x 1 x 100 hexahedra, part 1; node set 1 = every node."],
      nodes, [(1, c) for _, c in hexes], [(1, list(range(1, len(nodes) + 1)))])

# Laminate: 10 x 10 mm, four 0.25 mm plies [0/90/90/0], 4 x 4 elements per ply, a part per ply
# (SI). The box generator stacks one box per ply (origins z = 0, 0.00025, 0.0005, 0.00075, each
# 0.00025 thick) and merges the shared faces into the lower box's top nodes (origin + size):
# node and element order are those of one 4 x 4 x 4 block, with these z values.
# Sets: 1 = x = 0 face, 2 = x = 10 mm face, 3 = top-centre node.
n = (4, 4, 4)
nodes, hexes = block((0, 0, 0), (0.01, 0.01, 0.001), n)
tops = [0.0] + [o + 0.00025 for o in (0.0, 0.00025, 0.0005, 0.00075)]
nodes = [(x, y, tops[(i // 25)]) for i, (x, y, _) in enumerate(nodes)]
elements = [(k + 1, c) for k, c in hexes]
face = lambda i: [1 + (k * 5 + j) * 5 + i for k in range(5) for j in range(5)]
write("laminate_mat054_mesh.k", ["Laminate mesh (SI): 4 x 4 x 4 hexahedra, part = ply 1..4 bottom to top."],
      nodes, elements, [(1, face(0)), (2, face(4)), (3, [1 + (4 * 5 + 2) * 5 + 2])])
