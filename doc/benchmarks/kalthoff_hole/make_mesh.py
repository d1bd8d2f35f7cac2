#!/usr/bin/env python3
"""Write meshes/kalthoff_winkler_hole_2d.msh: the Kalthoff-Winkler mesh (meshes/
kalthoff_winkler_2d.msh, 2 mm quadrilaterals, notches as slits) with a square hole off the
upper crack's path: the cells whose centre lies in HOLE (x0, x1, y0, y1) [m] are removed, the
faces between removed and kept cells get boundary id 5 (free). Material id 1 and boundary ids
1-4 as in the source mesh.

Usage: make_mesh.py [SOURCE [TARGET]]   (defaults: the repository's meshes/)
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from gmsh22 import read, write  # noqa: E402

HOLE = (0.070, 0.082, 0.044, 0.056)


def main():
    top = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "meshes")
    source = sys.argv[1] if len(sys.argv) > 1 else os.path.join(top, "kalthoff_winkler_2d.msh")
    target = (sys.argv[2] if len(sys.argv) > 2
              else os.path.join(top, "kalthoff_winkler_hole_2d.msh"))
    nodes, lines, quads = read(source)

    def in_hole(q):
        x = sum(nodes[v][0] for v in q) / 4
        y = sum(nodes[v][1] for v in q) / 4
        return HOLE[0] < x < HOLE[1] and HOLE[2] < y < HOLE[3]

    kept = [q for q in quads if not in_hole(q)]
    removed = [q for q in quads if in_hole(q)]
    edges = lambda q: [tuple(sorted((q[i], q[(i + 1) % 4]))) for i in range(4)]  # noqa: E731
    kept_edges = {e for q in kept for e in edges(q)}
    hole_faces = [(5,) + e for q in removed for e in edges(q) if e in kept_edges]
    used = sorted({v for q in kept for v in q})
    number = {tag: k + 1 for k, tag in enumerate(used)}
    write(target, [nodes[t] for t in used],
          [(tag, number[a], number[b]) for tag, a, b in lines + hole_faces
           if a in number and b in number],
          [tuple(number[v] for v in q) for q in kept])
    print("%s: %d quads (%d removed for the hole), %d hole faces"
          % (target, len(kept), len(removed), len(hole_faces)))


if __name__ == "__main__":
    main()
