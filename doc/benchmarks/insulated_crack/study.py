#!/usr/bin/python3
"""Steady heat flow across an insulated central crack (doc/benchmarks/insulated_crack/README.md):
the heat flow Q through the bar and the temperature jump across the crack's middle, all-PD,
coupled (PD band, FE far field) and FE with the crack as a slit, as dx and h shrink. Prints a
Markdown table and writes convergence.png.
usage: /usr/bin/python3 doc/benchmarks/insulated_crack/study.py [path/to/perideal-solid]
"""
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, ".."))
import prm_runs  # noqa: E402

solver = prm_runs.solver(sys.argv)
mesh = os.path.join(prm_runs.ROOT, "meshes", "antiplane_cracked_bar_half_2d.msh")


def run(template, values):
    log = prm_runs.run(solver, os.path.join(here, template), values)[0]
    Q = float(re.search(r"Reaction top: ([0-9.e+-]+) W", log).group(1))
    probes = [float(v) for v in re.findall(r"temperature \[K\]: ([0-9.e+-]+)", log)]
    jump = probes[0] - probes[1] if len(probes) >= 2 else None
    return Q, jump


rows = []
for r in range(4):
    Q, _ = run("crack_fe.prm", {"MESH": mesh, "REFINE": str(r)})
    rows.append(("FE, slit", 0.02 / 2 ** r, Q, None))
for dx in [0.02, 0.01, 0.005]:
    probes = f"{dx / 2:.17g}, {dx / 2:.17g}; {dx / 2:.17g}, {-dx / 2:.17g}"
    Q, jump = run("crack_pd.prm", {"DX": f"{dx:.17g}", "DEPTH": f"{3 * dx:.17g}",
                                   "BOTTOM_LOWER": f"-0.5, {-0.5 - 3 * dx:.17g}",
                                   "TOP_UPPER": f"0.5, {0.5 + 3 * dx:.17g}", "PROBES": probes})
    rows.append(("all-PD", dx, Q, jump))
    n = round(1 / dx)
    Q, jump = run("crack_coupled.prm",
                  {"DX": f"{dx:.17g}", "PROBES": probes,
                   "GENERATOR_ARGUMENTS": f"{n}, {n} : -0.5, -0.5 : 0.5, 0.5 : true"})
    rows.append(("coupled (PD band, FE h = dx)", dx, Q, jump))

print("| model | dx or h | heat flow Q [W] (uncracked: 100) | T(dx/2, +dx/2) - T(dx/2, -dx/2) [K] |")
print("|---|---|---|---|")
for model, size, Q, jump in rows:
    print(f"| {model} | {size:g} | {Q:.4f} | {'' if jump is None else f'{jump:.3f}'} |")

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

fig, ax = plt.subplots(figsize=(5.5, 3.8))
for model, marker in [("FE, slit", "k^-"), ("all-PD", "o-"), ("coupled (PD band, FE h = dx)", "s-")]:
    sel = [r for r in rows if r[0] == model]
    ax.semilogx([r[1] for r in sel], [r[2] for r in sel], marker, label=model)
prm_runs.finish(fig, ax, os.path.join(here, "convergence.png"), "dx (PD) or h (FE)",
                "heat flow through the bar Q [W]",
                "Insulated central crack, a = 0.2, bar 1 x 1, dT = 100 K, k = 1")
