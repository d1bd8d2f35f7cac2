#!/usr/bin/env python3
"""Writes the square plate with a central circular hole as a gmsh 2.2 mesh of quadrilaterals.

The plate [0, L]^2 with the hole |x - c| < a, c = (L/2, L/2): an O-grid of 4 n_t cells around
the hole and n_r cells from the hole to the outer square, graded geometrically so that the
cells at the hole are about square (radial size = arc length a pi / (2 n_t)). Ring k of the grid
joins the hole point at the angle -45 + 90 k / n_t degrees to the point k / n_t of the way
around the square, counterclockwise from the corner (L, 0). Boundary ids (physical lines):
1 x = 0, 2 x = L, 3 y = 0, 4 y = L, 5 the hole (vertices on the circle: give
<Finite elements/Circular boundaries> = 5: L/2, L/2 so that refinement follows it). Material id
(physical surface) 1. Used as the FE mesh and as the particle body (<Regions>, Shape = mesh).

usage: make_mesh.py L a n_t n_r output.msh   (lengths in m)
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import gmsh22  # noqa: E402


def grading(first, length, n):
    """The ratio r of a geometric progression of n cells of total length `length` whose first
    cell is `first` (r = 1 if uniform cells are already smaller)."""
    if n == 1 or first * n >= length:
        return 1.0
    lo, hi = 1.0 + 1e-12, 2.0
    while hi - lo > 1e-14:
        r = 0.5 * (lo + hi)
        if first * (r ** n - 1) / (r - 1) > length:
            hi = r
        else:
            lo = r
    return 0.5 * (lo + hi)


def write_mesh(L, a, n_t, n_r, path):
    c = 0.5 * L
    n_ring = 4 * n_t
    r = grading(a * math.pi / (2 * n_t), c - a, n_r)
    fractions = [(r ** j - 1) / (r ** n_r - 1) if r != 1.0 else j / n_r for j in range(n_r + 1)]

    def outer(s):
        side, t = int(s) % 4, s - int(s)
        return [(L, t * L), (L - t * L, L), (0.0, L - t * L), (t * L, 0.0)][side]

    nodes = []
    for k in range(n_ring):
        s = k / n_t
        theta = math.radians(-45.0 + 90.0 * s)
        inner = (c + a * math.cos(theta), c + a * math.sin(theta))
        out = outer(s)
        for f in fractions:
            nodes.append((inner[0] + f * (out[0] - inner[0]), inner[1] + f * (out[1] - inner[1])))

    def node(k, j):
        return (k % n_ring) * (n_r + 1) + j + 1

    quads = [(node(k, j), node(k, j + 1), node(k + 1, j + 1), node(k + 1, j))
             for k in range(n_ring) for j in range(n_r)]
    side_tag = [2, 4, 1, 3]  # right, top, left, bottom, counterclockwise from (L, 0)
    lines = [(5, node(k + 1, 0), node(k, 0)) for k in range(n_ring)]
    lines += [(side_tag[k // n_t], node(k, n_r), node(k + 1, n_r)) for k in range(n_ring)]
    gmsh22.write(path, nodes, lines, quads)
    return r


if __name__ == "__main__":
    if len(sys.argv) != 6:
        raise SystemExit(__doc__)
    ratio = write_mesh(float(sys.argv[1]), float(sys.argv[2]), int(sys.argv[3]),
                       int(sys.argv[4]), sys.argv[5])
    print("make_mesh.py: %s, %d cells, radial grading ratio %.4f"
          % (sys.argv[5], 4 * int(sys.argv[3]) * int(sys.argv[4]), ratio))
