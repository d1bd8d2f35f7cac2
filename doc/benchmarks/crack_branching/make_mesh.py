#!/usr/bin/env python3
"""Write meshes/crack_branching_2d.msh: the glass plate of the crack-branching benchmark,
0 <= x <= 0.1, -0.02 <= y <= 0.02 [m], in squares of h = 1 mm, with the notch on y = 0 from the
left edge to the centre x = 0.05 as a slit (the nodes on y = 0 left of the tip exist twice, one
copy for the cells below, one for the cells above). Boundary ids (physical lines): 1 the top
edge y = 0.02, 2 the bottom edge y = -0.02 (both loaded by the traction), 3 the left and right
edges, 4 the notch faces (all free). Material id 1.

usage: make_mesh.py [H [OUTPUT]]   (cell size H [m], default 1e-3; OUTPUT default
<top>/meshes/crack_branching_2d.msh)
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import gmsh22  # noqa: E402

LX, LY, NOTCH = 0.1, 0.04, 0.05


def write_mesh(h, path):
    nx, ny = round(LX / h), round(LY / h)
    n_notch, j_notch = round(NOTCH / h), ny // 2
    if abs(nx * h - LX) > 1e-12 or abs(ny * h - LY) > 1e-12 or ny % 2:
        raise SystemExit("make_mesh.py: h = %g must divide 0.1 and 0.02" % h)
    nodes, index = [], {}

    def node(i, j, above):
        # Nodes on the notch line strictly left of the tip: the cells above use copy 1.
        key = (i, j, 1 if (j == j_notch and i < n_notch and above) else 0)
        if key not in index:
            nodes.append((i * h, -LY / 2 + j * h))
            index[key] = len(nodes)
        return index[key]

    quads = []
    for j in range(ny):
        above = j >= j_notch
        for i in range(nx):
            quads.append((node(i, j, above), node(i + 1, j, above),
                          node(i + 1, j + 1, above), node(i, j + 1, above)))
    lines = []
    for i in range(nx):
        lines.append((2, node(i, 0, False), node(i + 1, 0, False)))
        lines.append((1, node(i, ny, True), node(i + 1, ny, True)))
    for j in range(ny):
        above = j >= j_notch
        lines.append((3, node(0, j, above), node(0, j + 1, above)))
        lines.append((3, node(nx, j, above), node(nx, j + 1, above)))
    for i in range(n_notch):
        lines.append((4, node(i, j_notch, False), node(i + 1, j_notch, False)))
        lines.append((4, node(i, j_notch, True), node(i + 1, j_notch, True)))
    gmsh22.write(path, nodes, lines, quads)
    print("%s: %d quads, %d nodes, %d boundary lines" % (path, len(quads), len(nodes), len(lines)))


if __name__ == "__main__":
    top = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..")
    h = float(sys.argv[1]) if len(sys.argv) > 1 else 1e-3
    write_mesh(h, sys.argv[2] if len(sys.argv) > 2
               else os.path.join(top, "meshes", "crack_branching_2d.msh"))
