"""What the benchmarks' mesh scripts share: writing a 2D mesh of quadrilaterals as gmsh 2.2.

write(path, nodes, lines, quads): nodes [(x, y)] numbered from 1; lines [(tag, v0, v1)], the
boundary faces with their physical tag (deal.II's boundary id); quads [(v0, v1, v2, v3)]
counterclockwise, material id 1.
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
