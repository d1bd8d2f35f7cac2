#!/usr/bin/python3
"""The PD temperature of a quench run against the slab's series solution (README.md, "Critical
dT"). Usage: heat_check.py RESULTS_DIR T0 [dx] -- RESULTS_DIR of a run of the 20 x 10 mm
segment of the tests (thermal_shock_subcritical.prm.in with field output every load step), no
broken bonds. Prints, at 40, 140 and 200 ms, the mean PD temperature of particle rows 0, 1, 2,
4, 8, 19 (counted from the nearer long edge; 19: the centre line; columns within 2.6 mm of
x = 10 mm, away from the cooled ends)
against the series at the same particles, and the edge-strain factor phi = theta_mean -
theta_edge from the PD temperatures (row 0 as the edge) and from the series (at the row-0
centres and at the edge itself).
"""

import os
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import critical_dt  # noqa: E402


def main():
    results, t0 = sys.argv[1], float(sys.argv[2])
    dx = float(sys.argv[3]) if len(sys.argv) > 3 else 2.5e-4
    tw, half, h, k, rho, c = 20.0, 5e-3, 5e4, 31.0, 3980.0, 880.0
    kappa = k / (rho * c)
    lam = critical_dt.eigenvalues(h * half / k, 400)
    coef = 4 * np.sin(lam) / (2 * lam + np.sin(2 * lam))
    root = ET.parse(os.path.join(results, "particles_heat.xdmf")).getroot()
    grids = [g for g in root.iter("Grid") if g.get("GridType") == "Uniform"]
    for wanted in (0.04, 0.14, 0.2):
        grid = min(grids, key=lambda g: abs(float(g.find("Time").get("Value")) - wanted))
        time = float(grid.find("Time").get("Value"))
        item = grid.find("Geometry").find("DataItem").text.strip().split(":")[0]
        with h5py.File(os.path.join(results, item), "r") as f:
            x, temp = np.array(f["nodes"]), np.array(f["temperature"])[:, 0]
        sel = np.abs(x[:, 0] - 0.01) < 0.0026
        y, tp = x[sel, 1], temp[sel]
        fo = kappa * time / half**2
        decay = coef * np.exp(-lam**2 * fo)
        ta = tw + (t0 - tw) * (np.cos(np.outer(np.abs(y - half) / half, lam)) * decay).sum(1)
        rows = np.minimum(np.floor(y / dx), np.floor((2 * half - y) / dx)).astype(int)
        parts = [f"row {r}: PD {tp[rows == r].mean():.2f}, series {ta[rows == r].mean():.2f}"
                 for r in (0, 1, 2, 4, 8, 19)]
        print(f"t = {1e3 * time:.0f} ms: " + "; ".join(parts))
        mean = (decay * np.sin(lam) / lam).sum()
        row0 = (decay * np.cos(lam * (1 - 0.5 * dx / half))).sum()
        edge = (decay * np.cos(lam)).sum()
        print(f"  phi: PD (mean - row 0) {(tp.mean() - tp[rows == 0].mean()) / (t0 - tw):.4f}, "
              f"series at the row-0 centres {mean - row0:.4f}, at the edge {mean - edge:.4f}")


if __name__ == "__main__":
    main()
