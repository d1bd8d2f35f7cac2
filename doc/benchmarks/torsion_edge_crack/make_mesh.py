#!/usr/bin/env python3
"""Writes the cracked torsion section as a gmsh 2.2 mesh of quadrilaterals with a slit.

The section |x| <= 1/2, |y| <= 1 with an edge crack on y = 0 from the face x = -1/2 to the tip
x = -1/2 + a: nodes on the crack line left of the tip exist twice (one copy for the cells
below, one for the cells above), so the crack faces are free faces of the mesh. Boundary ids
(physical lines): 1 the outer faces, 2 the crack faces. Material id (physical surface) 1.

usage: make_mesh.py a n output.msh   (crack length a, n cells across the short side; a n must
be an integer so that the tip is a vertex)
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import gmsh22  # noqa: E402


def write_mesh(a, n, path):
    nx, ny = n, 2 * n
    h = 1.0 / n
    n_crack = round(a * n)
    if abs(n_crack - a * n) > 1e-9:
        raise SystemExit("make_mesh.py: a * n = %g is not an integer; the tip must be a vertex"
                         % (a * n))
    nodes = []
    index = {}

    def node(i, j, side=0):
        key = (i, j, side)
        if key not in index:
            nodes.append((-0.5 + i * h, -1.0 + j * h))
            index[key] = len(nodes)
        return index[key]

    def vertex(i, j, above):
        # Nodes on the crack line strictly left of the tip: the cells above use copy 1.
        on_crack = (j == n and i < n_crack)
        return node(i, j, 1 if (on_crack and above) else 0)

    quads = []
    for j in range(ny):
        above = j >= n
        for i in range(nx):
            quads.append((vertex(i, j, above), vertex(i + 1, j, above),
                          vertex(i + 1, j + 1, above), vertex(i, j + 1, above)))
    lines = []
    for i in range(nx):
        lines.append((1, node(i, 0), node(i + 1, 0)))
        lines.append((1, node(i, ny), node(i + 1, ny)))
    for j in range(ny):
        above = j >= n
        lines.append((1, vertex(0, j, above), vertex(0, j + 1, above)))
        lines.append((1, vertex(nx, j, above), vertex(nx, j + 1, above)))
    for i in range(n_crack):
        lines.append((2, vertex(i, n, False), vertex(i + 1, n, False)))
        lines.append((2, vertex(i, n, True), vertex(i + 1, n, True)))
    gmsh22.write(path, nodes, lines, quads)

if __name__ == "__main__":
    if len(sys.argv) != 4:
        raise SystemExit(__doc__)
    write_mesh(float(sys.argv[1]), int(sys.argv[2]), sys.argv[3])
