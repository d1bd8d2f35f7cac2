#!/usr/bin/python3
"""Coupled linear-temperature patch test (bond based conduction particles in an FE heat plate).

Runs tests/app-solid/coupled_heat_patch_{blended,schwarz}_2d.prm with perideal-solid: the
Schwarz method once, the blended method for overlap ramps W = 5, 10, 20 mm (and dx = 0.5 mm at
W = 10 mm); prints a Markdown table of the temperature error and the ghost flux and writes
ghost_flux.png.
usage: /usr/bin/python3 doc/benchmarks/heat_coupling_patch/study.py [path/to/perideal-solid]
"""
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, ".."))
import prm_runs  # noqa: E402

solver = prm_runs.solver(sys.argv)
tests = os.path.join(prm_runs.ROOT, "tests", "app-solid")
T_RANGE = 150.  # the exact field 300 + 1000 x + 500 y spans 300 ... 450 K


def run(method, W=0.01, dx=1e-3):
    a, b = 0.04 - W, 0.06 + W
    blending = (f"min(1, max(0, min(min((x - {a:g}) / {W:g}, ({b:g} - x) / {W:g}), "
                f"min((y - {a:g}) / {W:g}, ({b:g} - y) / {W:g}))))")
    log = prm_runs.run(solver, os.path.join(tests, f"coupled_heat_patch_{method}_2d.prm"),
                       {}, [(r"Blending function = .*", f"Blending function = {blending}"),
                            (r"Lattice spacing = .*", f"Lattice spacing = {dx:g}")])[0]
    error = re.search(r"FE nodes ([0-9.e+-]+), particles ([0-9.e+-]+)", log)
    flux = re.search(r"Force residual of the exact field: ([0-9.e+-]+) N", log)
    return 450. * max(float(error.group(1)), float(error.group(2))), float(flux.group(1))


print("| method | W [mm] | dx [mm] | max temperature error [K] | relative to the range (150 K) "
      "| ghost flux: largest unbalanced heat [W] |")
print("|---|---|---|---|---|---|")
rows = []
for method, W, dx in [("schwarz", 0.01, 1e-3), ("blended", 0.005, 1e-3), ("blended", 0.01, 1e-3),
                      ("blended", 0.02, 1e-3), ("blended", 0.01, 5e-4)]:
    error, flux = run(method, W, dx)
    rows.append((method, W, dx, error, flux))
    print(f"| {method} | {W * 1e3:g} | {dx * 1e3:g} | {error:.3e} | {error / T_RANGE:.2e} "
          f"| {flux:.3e} |")

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

blended = [r for r in rows if r[0] == "blended" and r[2] == 1e-3]
fig, ax = plt.subplots(figsize=(5, 3.6))
W = [r[1] * 1e3 for r in blended]
ax.loglog(W, [r[3] for r in blended], "o-", label="blended: max |T - T_exact| [K]")
ax.loglog(W, [r[4] * 10 for r in blended], "s--", label="blended: ghost flux [W] x 10")
ax.loglog(W, [blended[0][3] * W[0] / w for w in W], "k:", label="slope -1")
ax.set_xlabel("overlap ramp W [mm]")
ax.set_title("Linear temperature through the overlap (dx = 1 mm, h = 4 mm)", fontsize=9)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(here, "ghost_flux.png"), dpi=120)
