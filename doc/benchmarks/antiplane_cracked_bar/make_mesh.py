#!/usr/bin/env python3
"""Writes the upper half of the cracked bar of example 8.3 as a gmsh 2.2 mesh of quadrilaterals.

Under antiplane shear the solution of the bar |x|, |y| <= 1/2 with the central crack |x| < a on
y = 0 is odd in y, so w = 0 on the ligament and the upper half [-1/2, 1/2] x [0, 1/2] is the whole
problem. Boundary ids (physical lines): 1 the ligament (y = 0, |x| >= a), 2 the top (y = 1/2),
3 the sides, 4 the crack face (y = 0, |x| < a). Material id (physical surface) 1.

usage: make_mesh.py a n output.msh   (half crack length a, n cells across the width 1; a n must
be an integer so that the tips are vertices, and n even)
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import gmsh22  # noqa: E402


def write_mesh(a, n, path):
    if n % 2 or abs(round(a * n) - a * n) > 1e-9:
        raise SystemExit("make_mesh.py: n = %d must be even and a n = %g an integer (the tips "
                         "are vertices)" % (n, a * n))
    nx, ny, h = n, n // 2, 1.0 / n
    tip = round(a * n)

    def node(i, j):
        return j * (nx + 1) + i + 1

    lines = []
    for i in range(nx):
        centre = abs(i + 0.5 - nx / 2)
        lines.append((4 if centre < tip else 1, node(i, 0), node(i + 1, 0)))
        lines.append((2, node(i, ny), node(i + 1, ny)))
    for j in range(ny):
        lines.append((3, node(0, j), node(0, j + 1)))
        lines.append((3, node(nx, j), node(nx, j + 1)))
    quads = [(node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1))
             for j in range(ny) for i in range(nx)]
    nodes = [(-0.5 + i * h, j * h) for j in range(ny + 1) for i in range(nx + 1)]
    gmsh22.write(path, nodes, lines, quads)

if __name__ == "__main__":
    if len(sys.argv) != 4:
        raise SystemExit(__doc__)
    write_mesh(float(sys.argv[1]), int(sys.argv[2]), sys.argv[3])
