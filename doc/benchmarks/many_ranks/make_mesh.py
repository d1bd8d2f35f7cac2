#!/usr/bin/env python3
"""Write meshes/kalthoff_plate_coarse_3d.msh: the Kalthoff-Winkler plate as a thin 3D body for
the many-rank checks (issue #41, part 3), 0 <= x <= 0.1 (x = impact direction),
-0.1 <= y <= 0.1, 0 <= z <= T [m], hexahedra of H x H x T/NZ, the two notches y = +-0.025,
0 <= x <= 0.05 through the thickness as slits (the nodes on a notch plane in front of the tip
line exist twice: one copy for the cells below, one for the cells above). Boundary ids (physical
surfaces): 1 x = 0 between the notches (impacted), 2 x = 0 outside them, 3 the four notch faces,
4 x = 0.1, y = +-0.1 and the faces z = 0, z = T (all but 1 free). Material id 1.

usage: make_mesh.py [H [T [NZ [OUTPUT]]]]   (defaults 5e-3, 7.5e-3, 2, <top>/meshes/
kalthoff_plate_coarse_3d.msh; H must divide 25 mm)
"""
import os
import sys

LX, LY, A, NOTCH = 0.1, 0.2, 0.025, 0.05


def write_mesh(h, thickness, nz, path):
    nx, ny = round(LX / h), round(LY / h)
    n_notch = round(NOTCH / h)
    j_notch = (round((LY / 2 - A) / h), round((LY / 2 + A) / h))
    if abs(round(A / h) * h - A) > 1e-12 or abs(nx * h - LX) > 1e-12:
        raise SystemExit("make_mesh.py: H = %g must divide 25 mm" % h)
    dz = thickness / nz
    nodes, index = [], {}

    def node(i, j, k, above):
        # Nodes on a notch plane strictly in front of the tip line: the cells above use copy 1.
        key = (i, j, k, 1 if (j in j_notch and i < n_notch and above) else 0)
        if key not in index:
            nodes.append((i * h, -LY / 2 + j * h, k * dz))
            index[key] = len(nodes)
        return index[key]

    hexes, quads = [], []
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                # The cell row j lies above a notch plane at node row j, below one at j + 1.
                lo = lambda ii, kk: node(ii, j, kk, True)  # noqa: E731
                hi = lambda ii, kk: node(ii, j + 1, kk, False)  # noqa: E731
                hexes.append((lo(i, k), lo(i + 1, k), hi(i + 1, k), hi(i, k),
                              lo(i, k + 1), lo(i + 1, k + 1), hi(i + 1, k + 1), hi(i, k + 1)))
                if k == 0:
                    quads.append((4, lo(i, 0), hi(i, 0), hi(i + 1, 0), lo(i + 1, 0)))
                if k == nz - 1:
                    quads.append((4, lo(i, nz), lo(i + 1, nz), hi(i + 1, nz), hi(i, nz)))
                if i == 0:
                    tag = 1 if j_notch[0] <= j < j_notch[1] else 2
                    quads.append((tag, lo(0, k), lo(0, k + 1), hi(0, k + 1), hi(0, k)))
                if i == nx - 1:
                    quads.append((4, lo(nx, k), hi(nx, k), hi(nx, k + 1), lo(nx, k + 1)))
                if j == 0:
                    quads.append((4, lo(i, k), lo(i + 1, k), lo(i + 1, k + 1), lo(i, k + 1)))
                if j == ny - 1:
                    quads.append((4, hi(i, k), hi(i, k + 1), hi(i + 1, k + 1), hi(i + 1, k)))
                if i < n_notch and j in j_notch:  # the notch face below this cell
                    quads.append((3, lo(i, k), lo(i + 1, k), lo(i + 1, k + 1), lo(i, k + 1)))
                if i < n_notch and j + 1 in j_notch:  # the notch face above this cell
                    quads.append((3, hi(i, k), hi(i, k + 1), hi(i + 1, k + 1), hi(i + 1, k)))
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes))
        for n, (x, y, z) in enumerate(nodes, 1):
            f.write("%d %.17g %.17g %.17g\n" % (n, x, y, z))
        f.write("$EndNodes\n$Elements\n%d\n" % (len(quads) + len(hexes)))
        n = 0
        for q in quads:
            n += 1
            f.write("%d 3 2 %d %d %d %d %d %d\n" % ((n, q[0]) + q))
        for e in hexes:
            n += 1
            f.write("%d 5 2 1 1 %d %d %d %d %d %d %d %d\n" % ((n,) + e))
        f.write("$EndElements\n")
    print("%s: %d hexes, %d nodes, %d boundary quads" % (path, len(hexes), len(nodes), len(quads)))


if __name__ == "__main__":
    top = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..")
    args = sys.argv[1:]
    write_mesh(float(args[0]) if len(args) > 0 else 5e-3,
               float(args[1]) if len(args) > 1 else 7.5e-3,
               int(args[2]) if len(args) > 2 else 2,
               args[3] if len(args) > 3 else os.path.join(top, "meshes",
                                                          "kalthoff_plate_coarse_3d.msh"))
