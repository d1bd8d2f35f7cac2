#!/usr/bin/env python3
"""Write meshes/kalthoff_winkler_3d.msh: the Kalthoff-Winkler plate as a 3D body, the 2D mesh
(meshes/kalthoff_winkler_2d.msh: 2 mm quadrilaterals, the notches as slits with separate nodes on
their faces) extruded through the thickness 0 <= z <= 9 mm in LAYERS layers of hexahedra (3 mm).
The slits stay slits (their faces keep separate nodes in every layer). Material id 1; boundary
ids 1-4 as in the 2D mesh (1: x = 0, |y| <= 25 mm, the impacted segment; 2: x = 0, |y| >= 25 mm;
3: the notch faces; 4: x = 100 mm and y = +-100 mm), 5: the faces z = 0 and z = 9 mm (free).
No gmsh needed.

Usage: make_mesh.py [SOURCE [TARGET]]   (defaults: the repository's meshes/)
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from gmsh22 import read, write_hexes  # noqa: E402

THICKNESS = 0.009
LAYERS = 3


def main():
    top = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "meshes")
    source = sys.argv[1] if len(sys.argv) > 1 else os.path.join(top, "kalthoff_winkler_2d.msh")
    target = sys.argv[2] if len(sys.argv) > 2 else os.path.join(top, "kalthoff_winkler_3d.msh")
    nodes, lines, quads = read(source)
    tags = sorted(nodes)
    number = {}  # (2D tag, layer) -> 3D node number
    points = []
    for layer in range(LAYERS + 1):
        z = THICKNESS * layer / LAYERS
        for t in tags:
            points.append(nodes[t] + (z,))
            number[(t, layer)] = len(points)
    hexes, faces = [], []
    for layer in range(LAYERS):
        for q in quads:  # counterclockwise: the hexahedron has a positive volume
            hexes.append(tuple(number[(v, layer)] for v in q)
                         + tuple(number[(v, layer + 1)] for v in q))
        for tag, a, b in lines:
            faces.append((tag, number[(a, layer)], number[(b, layer)], number[(b, layer + 1)],
                          number[(a, layer + 1)]))
    for q in quads:
        faces.append((5,) + tuple(number[(v, 0)] for v in reversed(q)))
        faces.append((5,) + tuple(number[(v, LAYERS)] for v in q))
    write_hexes(target, points, faces, hexes)
    print("%s: %d hexahedra, %d nodes, %d boundary quadrilaterals"
          % (target, len(hexes), len(points), len(faces)))


if __name__ == "__main__":
    main()
