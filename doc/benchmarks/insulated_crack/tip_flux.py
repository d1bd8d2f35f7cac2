#!/usr/bin/python3
"""Flux concentration ahead of the crack tips of the insulated crack
(doc/benchmarks/insulated_crack/README.md): the heat flux |q| on the crack line at the distances
d = 0.05 and 0.1 ahead of the tip x = a = 0.2, over the uncracked flux k dT / L = 100 W/m^2,
for FE with the crack as a slit (nodal flux of the half mesh on the ligament y = 0), all-PD and
coupled (the particles' heat_flux field, averaged over the rows y = +-dx/2), as dx and h
shrink. Prints a Markdown table and writes tip_flux.png.
usage: /usr/bin/python3 doc/benchmarks/insulated_crack/tip_flux.py [path/to/perideal-solid]
"""
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, ".."))
import prm_runs  # noqa: E402
from prm_fill import fill_text  # noqa: E402

solver = prm_runs.solver(sys.argv)
mesh = os.path.join(prm_runs.ROOT, "meshes", "antiplane_cracked_bar_half_2d.msh")
a, q0, distances = 0.2, 100., [0.05, 0.1]


def fields_of(template, values, name):
    """Run the template with HDF5 output; the nodes and fields of results/<name>_00001.h5."""
    path = os.path.join(here, template)
    text = fill_text(open(path).read(), values, path)
    text = text.replace("set Write HDF5   = false", "set Write HDF5 = true")
    text = text.replace("set Write HDF5 = false", "set Write HDF5 = true")
    with tempfile.TemporaryDirectory() as work:
        with open(os.path.join(work, "p.prm"), "w") as f:
            f.write(text)
        subprocess.run([solver, "p.prm"], cwd=work, env=prm_runs.ENV, capture_output=True,
                       check=True)
        with h5py.File(os.path.join(work, "results", name + "_00001.h5")) as h5:
            return {key: np.array(h5[key]) for key in h5}


def along_line(x, q, points):
    """Linear interpolation in x of the values q at the abscissae x (sorted here)."""
    order = np.argsort(x)
    return [float(np.interp(p, x[order], q[order])) for p in points]


def fe_flux(refine):
    f = fields_of("crack_fe.prm", {"MESH": mesh, "REFINE": str(refine)}, "solution")
    x, y = f["nodes"][:, 0], f["nodes"][:, 1]
    on = (np.abs(y) < 1e-12) & (x > a)
    q = np.hypot(f["heat_flux_x"][on, 0], f["heat_flux_y"][on, 0])
    return along_line(x[on], q, [a + d for d in distances])


def particle_flux(template, values, dx):
    f = fields_of(template, values, "particles")
    x, y = f["nodes"][:, 0], f["nodes"][:, 1]
    q = np.hypot(f["heat_flux"][:, 0], f["heat_flux"][:, 1])
    result = []
    for d in distances:
        # The columns that bracket x = a + d, each averaged over the two rows y = +-dx/2.
        rows = (np.abs(np.abs(y) - dx / 2) < 1e-9) & (np.abs(x - a - d) < dx)
        columns = sorted(set(np.round(x[rows], 12)))
        means = [q[rows & (np.abs(x - c) < 1e-9)].mean() for c in columns]
        result.append(float(np.interp(a + d, columns, means)))
    return result


rows = []
for r in range(4):
    rows.append(("FE, slit", 0.02 / 2 ** r, fe_flux(r)))
for dx in [0.02, 0.01, 0.005]:
    rows.append(("all-PD", dx, particle_flux(
        "crack_pd.prm", {"DX": f"{dx:.17g}", "DEPTH": f"{3 * dx:.17g}",
                         "BOTTOM_LOWER": f"-0.5, {-0.5 - 3 * dx:.17g}",
                         "TOP_UPPER": f"0.5, {0.5 + 3 * dx:.17g}",
                         "PROBES": f"{dx / 2:.17g}, {dx / 2:.17g}"}, dx)))
    n = round(1 / dx)
    rows.append(("coupled (PD band, FE h = dx)", dx, particle_flux(
        "crack_coupled.prm", {"DX": f"{dx:.17g}", "PROBES": f"{dx / 2:.17g}, {dx / 2:.17g}",
                              "GENERATOR_ARGUMENTS": f"{n}, {n} : -0.5, -0.5 : 0.5, 0.5 : true"},
        dx)))

print("| model | dx or h | " + " | ".join(f"|q(a + {d:g}, 0)| / q0" for d in distances) + " |")
print("|---|---|" + "---|" * len(distances))
for model, size, q in rows:
    print(f"| {model} | {size:g} | " + " | ".join(f"{v / q0:.4f}" for v in q) + " |")

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

fig, ax = plt.subplots(figsize=(5.5, 3.8))
for model, marker in [("FE, slit", "k^-"), ("all-PD", "o-"), ("coupled (PD band, FE h = dx)", "s-")]:
    sel = [r for r in rows if r[0] == model]
    for k, d in enumerate(distances):
        ax.semilogx([r[1] for r in sel], [r[2][k] / q0 for r in sel], marker,
                    label=f"{model}, d = {d:g}", alpha=1. if k else 0.6)
prm_runs.finish(fig, ax, os.path.join(here, "tip_flux.png"), "dx (PD) or h (FE)",
                "|q| at d ahead of the tip / uncracked flux",
                "Insulated crack: flux on the crack line at d ahead of the tip x = 0.2")
