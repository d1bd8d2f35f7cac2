#!/usr/bin/env python3
"""The plate of anisotropic_crack_path.prm turned by BETA degrees about its centre against the
particle lattice, for the lattice study of run.sh: writes the gmsh 2.2 mesh OUT.msh (three
quadrilaterals: material id 1 the plate between the grips, 2 the top grip strip, 3 the bottom
grip strip, 1 mm deep as in the file) and OUT.prm, the parameter lines that turn the rest
(the pre-crack, the grips' velocities, which then hold the component along the edges too: the
conditions name global components) and include anisotropic_crack_path.prm.

usage: rotated_plate.py BETA OUT   (OUT without extension; paths relative to the benchmark's
                                    directory, where perideal-solid runs)
"""
import math
import sys


def main():
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    beta = float(sys.argv[1])
    out = sys.argv[2]
    c, s = math.cos(math.radians(beta)), math.sin(math.radians(beta))
    centre = (0.030, 0.0)

    def turn(x, y):
        dx, dy = x - centre[0], y - centre[1]
        return (centre[0] + c * dx - s * dy, centre[1] + s * dx + c * dy)

    ys = [-0.030, -0.029, 0.029, 0.030]
    nodes = []
    for y in ys:
        for x in (0.0, 0.060):
            nodes.append(turn(x, y))
    # Node k (1-based) of row r, column j: 2 r + j + 1; counterclockwise quads.
    def quad(r):
        return (2 * r + 1, 2 * r + 2, 2 * r + 4, 2 * r + 3)
    cells = [(3, quad(0)), (1, quad(1)), (2, quad(2))]
    with open(out + ".msh", "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes))
        for k, (x, y) in enumerate(nodes, 1):
            f.write("%d %.17g %.17g 0\n" % (k, x, y))
        f.write("$EndNodes\n$Elements\n%d\n" % len(cells))
        for k, (tag, q) in enumerate(cells, 1):
            f.write("%d 3 2 %d %d %d %d %d %d\n" % ((k, tag, tag) + q))
        f.write("$EndElements\n")

    start, tip = turn(-0.001, 0.0), turn(0.0199999, 0.0)
    ramp = "min(1, t / 2e-5)"
    with open(out + ".prm", "w") as f:
        f.write(f"""# The plate of anisotropic_crack_path.prm turned by {beta:g} deg about (30, 0) mm
# (rotated_plate.py {beta:g}): regions from {out}.msh, the notch and the grips' motion turned
# with it; the grips move normal to the edges and hold the component along them (clamped).
include anisotropic_crack_path.prm
subsection Discretization
  set Body = plate, top grip, bottom grip
end
subsection Regions
  subsection plate
    set Shape       = mesh
    set Mesh file   = {out}.msh
    set Material id = 1
  end
  subsection top grip
    set Shape       = mesh
    set Mesh file   = {out}.msh
    set Material id = 2
  end
  subsection bottom grip
    set Shape       = mesh
    set Mesh file   = {out}.msh
    set Material id = 3
  end
end
subsection Pre-cracks
  set Cracks = {start[0]:.9g}, {start[1]:.9g} : {tip[0]:.9g}, {tip[1]:.9g}
end
# The bottom grip's x through the anchor condition (the file's names stay).
subsection Boundary conditions
  subsection top
    set Components = x, y
    set Function   = {-0.1 * s:.9g} * {ramp}; {0.1 * c:.9g} * {ramp}
  end
  subsection bottom
    set Function   = {-0.1 * c:.9g} * {ramp}
  end
  subsection anchor
    set Region     = bottom grip
    set Function   = {0.1 * s:.9g} * {ramp}
  end
end
""")


if __name__ == "__main__":
    main()
