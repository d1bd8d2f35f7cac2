#!/usr/bin/env python3
"""Benchmark compact_tension: does ASTM E399's LEFM formula apply to this specimen and its pins?

An FE elastic solution of the benchmark's CT geometry and loading (issue #40 part 2): the upper
half x in [-10, 40] mm, y in [0, 24] mm by symmetry (u_y = 0 on the ligament y = 0, x >= a; the
notch face x < a free), bilinear squares of side h, plane stress, E = 200 GPa, nu = 1/3,
B = 1 mm; the pin is the node column x = dx/2, 6 mm <= y <= 18 mm with u_y prescribed and u_x
free (the particle column of the .prm files), the anchor holds u_x of the node at
(dx/2, 18 mm + dx/2). The tip is at x = 20 mm (the end of the pre-crack).

G from the compliance method, G = P^2 / (2 B) dC/da with C = (2 u_pin) / P (the load-line
opening over the pin load), dC/da by central differences of the tip position over +-h, against
ASTM's G = (P f(a/W) / (B sqrt(W)))^2 / E for W = 40 mm - dx/2, a = 20 mm - dx/2: their ratio
is 1 where the formula applies. The K-dominance of the notch-tip field: sigma_yy on the ligament
(the symmetry reactions over h B) against K / sqrt(2 pi r), K = sqrt(E G), at distances r ahead
of the tip.

The solve is a block-tridiagonal elimination, node column by node column, with numpy only.
usage: fe_check.py [--dx DX_MM] [--h H_MM]   (defaults 1 and 0.25)
"""
import argparse
import math

import numpy as np

E, NU, B = 200e9, 1.0 / 3.0, 1e-3
X0, X1, Y1 = -0.010, 0.040, 0.024


def astm_f(alpha):
    return ((2 + alpha) * (0.886 + 4.64 * alpha - 13.32 * alpha**2 + 14.72 * alpha**3
                           - 5.6 * alpha**4) / (1 - alpha)**1.5)


def element_stiffness(h):
    """Bilinear square of side h, plane stress, thickness B; nodes (0,0), (1,0), (1,1), (0,1)."""
    D = E / (1 - NU**2) * np.array([[1, NU, 0], [NU, 1, 0], [0, 0, (1 - NU) / 2]])
    K = np.zeros((8, 8))
    corners = [(-1, -1), (1, -1), (1, 1), (-1, 1)]
    g = 1 / math.sqrt(3)
    for xi in (-g, g):
        for eta in (-g, g):
            Bm = np.zeros((3, 8))
            for n, (a, b) in enumerate(corners):
                dx = a * (1 + b * eta) / 4 * 2 / h
                dy = b * (1 + a * xi) / 4 * 2 / h
                Bm[0, 2 * n], Bm[1, 2 * n + 1] = dx, dy
                Bm[2, 2 * n], Bm[2, 2 * n + 1] = dy, dx
            K += Bm.T @ D @ Bm * (h / 2)**2 * B
    return K


def solve(h, dx, tip):
    """Pin load P [N] for u_pin = 1 (upper pin up by 1 m) and the ligament reactions."""
    nx, ny = int(round((X1 - X0) / h)), int(round(Y1 / h))
    nc = 2 * (ny + 1)
    x = X0 + h * np.arange(nx + 1)
    y = h * np.arange(ny + 1)
    Ke = element_stiffness(h)
    Dg = [np.zeros((nc, nc)) for _ in range(nx + 1)]
    Ug = [np.zeros((nc, nc)) for _ in range(nx)]
    # Element nodes 0, 3 lie in column i, nodes 1, 2 in column i + 1.
    left, right = [0, 1, 6, 7], [2, 3, 4, 5]
    for i in range(nx):
        for j in range(ny):
            ll = [2 * j, 2 * j + 1, 2 * j + 2, 2 * j + 3]       # nodes (i, j), (i, j+1)
            rr = [2 * j, 2 * j + 1, 2 * j + 2, 2 * j + 3]       # nodes (i+1, j), (i+1, j+1)
            Dg[i][np.ix_(ll, ll)] += Ke[np.ix_(left, left)]
            Dg[i + 1][np.ix_(rr, rr)] += Ke[np.ix_(right, right)]
            Ug[i][np.ix_(ll, rr)] += Ke[np.ix_(left, right)]
    iL = int(round((dx / 2 - X0) / h))
    assert abs(x[iL] - dx / 2) < 1e-9, "the mesh must have a node column at the load line"
    pin = [j for j in range(ny + 1) if 0.006 - 1e-9 <= y[j] <= 0.018 + 1e-9]
    anchor = int(np.argmin(abs(y - (0.018 + dx / 2))))
    prescribed = {}                                            # (column, local dof) -> value
    for j in pin:
        prescribed[(iL, 2 * j + 1)] = 1.0
    prescribed[(iL, 2 * anchor)] = 0.0
    itip = int(round((tip - X0) / h))
    for i in range(itip, nx + 1):
        prescribed[(i, 1)] = 0.0
    # Keep the rows of the reactions before eliminating the prescribed dofs.
    rows_L = (Ug[iL - 1].T.copy(), Dg[iL].copy(), Ug[iL].copy())
    lig = [(Ug[i - 1].T[1].copy() if i > 0 else None, Dg[i][1].copy(),
            Ug[i][1].copy() if i < nx else None) for i in range(itip, nx + 1)]
    rhs = [np.zeros(nc) for _ in range(nx + 1)]
    for (i, l), g in prescribed.items():
        rhs[i] -= Dg[i][:, l] * g
        if i > 0:
            rhs[i - 1] -= Ug[i - 1][:, l] * g
        if i < nx:
            rhs[i + 1] -= Ug[i][l, :] * g
    for (i, l), g in prescribed.items():
        Dg[i][:, l] = 0
        Dg[i][l, :] = 0
        Dg[i][l, l] = 1
        if i > 0:
            Ug[i - 1][:, l] = 0
        if i < nx:
            Ug[i][l, :] = 0
    for (i, l), g in prescribed.items():
        rhs[i][l] = g
    # Block elimination column by column, then back substitution.
    S, r = [Dg[0]], [rhs[0]]
    for i in range(1, nx + 1):
        X = np.linalg.solve(S[-1], np.column_stack([Ug[i - 1], r[-1]]))
        S.append(Dg[i] - Ug[i - 1].T @ X[:, :-1])
        r.append(rhs[i] - Ug[i - 1].T @ X[:, -1])
    u = [None] * (nx + 1)
    u[nx] = np.linalg.solve(S[nx], r[nx])
    for i in range(nx - 1, -1, -1):
        u[i] = np.linalg.solve(S[i], r[i] - Ug[i] @ u[i + 1])
    reaction = rows_L[0] @ u[iL - 1] + rows_L[1] @ u[iL] + rows_L[2] @ u[iL + 1]
    P = sum(reaction[2 * j + 1] for j in pin)
    # The symmetry reactions on the ligament (the force the lower half pulls with).
    sig = []
    for k, i in enumerate(range(itip, nx + 1)):
        lo, d, up = lig[k]
        f = d @ u[i] + (lo @ u[i - 1] if lo is not None else 0) + \
            (up @ u[i + 1] if up is not None else 0)
        sig.append((x[i] - tip, -f / (h * B)))
    return P, sig


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--dx", type=float, default=1.0, help="PD lattice spacing [mm]")
    parser.add_argument("--h", type=float, default=0.25, help="FE mesh size [mm]")
    args = parser.parse_args()
    dx, h = args.dx * 1e-3, args.h * 1e-3
    tip = 0.020
    W, a = 0.040 - dx / 2, 0.020 - dx / 2
    C = {}
    for s in (-1, 0, 1):
        P, sig = solve(h, dx, tip + s * h)
        C[s] = 2.0 / P
        if s == 0:
            P0, sig0 = P, sig
    dCda = (C[1] - C[-1]) / (2 * h)
    g_fe = dCda / (2 * B)                         # G / P^2
    g_astm = (astm_f(a / W) / (B * math.sqrt(W)))**2 / E
    print(f"dx = {dx * 1e3:g} mm, h = {h * 1e3:g} mm: W = {W * 1e3:.2f} mm, a/W = {a / W:.4f}")
    print(f"compliance C = {C[0]:.6e} m/N; "
          f"G/P^2: FE {g_fe:.6e}, ASTM {g_astm:.6e} 1/(N m)")
    print(f"G_FE / G_ASTM at the same load: {g_fe / g_astm:.4f}  "
          f"(P_LEFM,FE / P_LEFM,ASTM = {math.sqrt(g_astm / g_fe):.4f})")
    K = math.sqrt(E * g_fe) * P0                  # K for the pin load P0
    print("K-dominance: sigma_yy(r) sqrt(2 pi r) / K on the ligament")
    for r_mm in (0.5, 1, 2, 3, 4, 6, 8, 12):
        r, s = min(sig0, key=lambda rs: abs(rs[0] - r_mm * 1e-3))
        if r > 0:
            print(f"  r = {r * 1e3:5.2f} mm: {s * math.sqrt(2 * math.pi * r) / K:.4f}")


if __name__ == "__main__":
    main()
