#!/usr/bin/env python3
"""Write meshes/polycrystal_2d.msh: the 60 x 60 mm plate of the polycrystal benchmark (x from 0
to 60 mm, y from -30 to 30 mm) in 1 mm quadrilaterals, for the FE far field of coupled.prm (the
notch lies in the PD band, where the FE cells are inactive). Boundary ids: 1 bottom, 2 top,
3 the bottom between x = 30 and 31 mm (the anchor that holds x), 4 the sides (free).

Usage: make_mesh.py [TARGET]   (default: the repository's meshes/polycrystal_2d.msh)
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from gmsh22 import write  # noqa: E402

SIZE, CELLS = 0.06, 60


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    target = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        here, "..", "..", "..", "meshes", "polycrystal_2d.msh")
    h = SIZE / CELLS
    node = lambda i, j: 1 + i + j * (CELLS + 1)  # noqa: E731
    nodes = [(i * h, j * h - 0.5 * SIZE) for j in range(CELLS + 1) for i in range(CELLS + 1)]
    quads = [(node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1))
             for j in range(CELLS) for i in range(CELLS)]
    lines = []
    for i in range(CELLS):
        lines.append((3 if i == CELLS // 2 else 1, node(i, 0), node(i + 1, 0)))
        lines.append((2, node(i + 1, CELLS), node(i, CELLS)))
    for j in range(CELLS):
        lines.append((4, node(0, j + 1), node(0, j)))
        lines.append((4, node(CELLS, j), node(CELLS, j + 1)))
    write(target, nodes, lines, quads)
    print("wrote", target, len(quads), "cells")


if __name__ == "__main__":
    main()
