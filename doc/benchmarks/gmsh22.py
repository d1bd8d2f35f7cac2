"""What the benchmarks' mesh scripts share: gmsh 2.2 files of quadrilaterals (2D) and hexahedra
(3D).

write(path, nodes, lines, quads): nodes [(x, y)] numbered from 1; lines [(tag, v0, v1)], the
boundary faces with their physical tag (deal.II's boundary id); quads [(v0, v1, v2, v3)]
counterclockwise, material id 1.
read(path): the same lists (nodes as {tag: (x, y)}) from a 2D file of lines and quadrilaterals.
write_hexes(path, nodes, faces, hexes): 3D: nodes [(x, y, z)] numbered from 1; faces [(tag, v0,
v1, v2, v3)], the boundary quadrilaterals with their physical tag; hexes [(v0, ..., v7)] in
gmsh's order (the bottom quadrilateral counterclockwise seen from above, then the top one),
material id 1.
"""


def write(path, nodes, lines, quads):
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes))
        for k, (x, y) in enumerate(nodes, 1):
            f.write("%d %.17g %.17g 0\n" % (k, x, y))
        f.write("$EndNodes\n$Elements\n%d\n" % (len(lines) + len(quads)))
        k = 0
        for tag, v0, v1 in lines:
            k += 1
            f.write("%d 1 2 %d %d %d %d\n" % (k, tag, tag, v0, v1))
        for q in quads:
            k += 1
            f.write("%d 3 2 1 1 %d %d %d %d\n" % ((k,) + q))
        f.write("$EndElements\n")


def read(path):
    """nodes {tag: (x, y)}, lines [(physical, v0, v1)], quads [(v0, v1, v2, v3)] of a gmsh 2.2
    file with lines (type 1) and quadrilaterals (type 3)."""
    nodes, lines, quads = {}, [], []
    with open(path) as f:
        text = f.read().split("\n")
    k = text.index("$Nodes") + 2
    while text[k] != "$EndNodes":
        tag, x, y, _ = text[k].split()
        nodes[int(tag)] = (float(x), float(y))
        k += 1
    k = text.index("$Elements") + 2
    while text[k] != "$EndElements":
        item = [int(v) for v in text[k].split()]
        kind, n_tags = item[1], item[2]
        vertices = item[3 + n_tags:]
        if kind == 1:
            lines.append((item[3], vertices[0], vertices[1]))
        elif kind == 3:
            quads.append(tuple(vertices))
        k += 1
    return nodes, lines, quads


def write_hexes(path, nodes, faces, hexes):
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes))
        for k, (x, y, z) in enumerate(nodes, 1):
            f.write("%d %.17g %.17g %.17g\n" % (k, x, y, z))
        f.write("$EndNodes\n$Elements\n%d\n" % (len(faces) + len(hexes)))
        k = 0
        for tag, *v in faces:
            k += 1
            f.write("%d 3 2 %d %d %d %d %d %d\n" % ((k, tag, tag) + tuple(v)))
        for h in hexes:
            k += 1
            f.write("%d 5 2 1 1 %d %d %d %d %d %d %d %d\n" % ((k,) + tuple(h)))
        f.write("$EndElements\n")
