#!/usr/bin/env python3
"""Write meshes/nooru_mohamed_2d.msh: the 200 x 200 mm Nooru-Mohamed specimen (origin at its lower
left corner) in 4 mm quadrilaterals (50 x 50), without the notches (they lie in the PD-only band
of the coupled run, where the FE cells are inactive). Boundary ids: 1 bottom, 2 top, 3 the left
side above y = 140 mm (upper lateral platen), 4 the right side below y = 60 mm (lower lateral
platen), 5 the rest of the sides (free).

Usage: make_mesh.py [TARGET]   (default: the repository's meshes/nooru_mohamed_2d.msh)
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from gmsh22 import write  # noqa: E402

SIZE, CELLS = 0.2, 50
PLATEN = 0.06  # length of the lateral platens at the outer ends of the sides [m]


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    target = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        here, "..", "..", "..", "meshes", "nooru_mohamed_2d.msh")
    h = SIZE / CELLS
    node = lambda i, j: 1 + i + j * (CELLS + 1)  # noqa: E731
    nodes = [(i * h, j * h) for j in range(CELLS + 1) for i in range(CELLS + 1)]
    quads = [(node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1))
             for j in range(CELLS) for i in range(CELLS)]
    lines = []
    for i in range(CELLS):
        lines.append((1, node(i, 0), node(i + 1, 0)))
        lines.append((2, node(i + 1, CELLS), node(i, CELLS)))
    for j in range(CELLS):
        y = (j + 0.5) * h
        lines.append((3 if y > SIZE - PLATEN else 5, node(0, j + 1), node(0, j)))
        lines.append((4 if y < PLATEN else 5, node(CELLS, j), node(CELLS, j + 1)))
    write(target, nodes, lines, quads)
    print("wrote", target, len(quads), "cells")


if __name__ == "__main__":
    main()
