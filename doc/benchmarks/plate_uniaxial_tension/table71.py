#!/usr/bin/env python3
"""Deviations of PD from plane-stress elasticity at four points of each mid-line, tabulated
like Table 7.1 of seed 002 (whose points are not defined: we take x, y = 0.1 L, 0.2 L, 0.3 L
and 0.4 L from the lower/left edge, where the elastic displacement is not zero).

Usage: table71.py DIR   (DIR holds the particles_*.h5 of a run of this benchmark)
"""
import sys

import h5py
import numpy as np

from postprocess import L, NU, U, last_particle_file, mid_line

directory = sys.argv[1] if len(sys.argv) > 1 else "."
with h5py.File(last_particle_file(directory), "r") as f:
    x = f["nodes"][:, :2]
    u = f["displacement"][:, :2]
dx = np.min(np.diff(np.unique(np.round(x[:, 0], 12))))
eps = 2 * U / L
points = [0.1 * L, 0.2 * L, 0.3 * L, 0.4 * L]

# Horizontal mid-line (y = L/2): u_x along x; vertical mid-line (x = L/2): u_y along y.
sx, ux = mid_line(x, x[:, 0], u[:, 0], x[:, 1] - L / 2, dx)
_, uy_h = mid_line(x, x[:, 0], u[:, 1], x[:, 1] - L / 2, dx)
sy, uy = mid_line(x, x[:, 1], u[:, 1], x[:, 0] - L / 2, dx)
_, ux_v = mid_line(x, x[:, 1], u[:, 0], x[:, 0] - L / 2, dx)


def at(s, values, p):
    return np.interp(p, s, values)


rows = []
for k, p in enumerate(points, 1):
    el_x = -NU * eps * (p - L / 2)
    el_y = eps * (p - L / 2)
    d1 = abs(at(sx, ux, p) / el_x - 1)
    d2 = abs(at(sy, uy, p) / el_y - 1)
    d3 = abs(np.hypot(at(sx, ux, p), at(sx, uy_h, p)) / abs(el_x) - 1)
    d4 = abs(np.hypot(at(sy, ux_v, p), at(sy, uy, p)) / abs(el_y) - 1)
    rows.append((k, p, d1, d2, d3, d4))

print("| point (x or y [mm]) | u_x1 along x1 | u_x2 along x2 | u along x1 | u along x2 |")
print("|---|---|---|---|---|")
for k, p, *d in rows:
    print(f"| {k:02d} ({p * 1e3:.0f}) | " + " | ".join(f"{100 * v:.2f} %" for v in d) + " |")
mean = np.mean([r[2:] for r in rows], axis=0)
print("| average | " + " | ".join(f"{100 * v:.2f} %" for v in mean) + " |")
