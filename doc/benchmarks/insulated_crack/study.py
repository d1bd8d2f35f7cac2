#!/usr/bin/python3
"""Steady heat flow across an insulated central crack (doc/benchmarks/insulated_crack/README.md):
the heat flow Q through the bar and the temperature jump across the crack's middle, all-PD,
coupled (PD band, FE far field) and FE with the crack as a slit, as dx and h shrink. Prints a
Markdown table and writes convergence.png.
usage: /usr/bin/python3 doc/benchmarks/insulated_crack/study.py [path/to/perideal-solid]
"""
import os
import re
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.normpath(os.path.join(here, "..", "..", ".."))
solver = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build", "bin", "perideal-solid")
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
mesh = os.path.join(root, "meshes", "antiplane_cracked_bar_half_2d.msh")


def run(template, values):
    text = open(os.path.join(here, template)).read()
    for key, value in values.items():
        text = re.sub(r"\b" + key + r"\b", value, text)
    with tempfile.TemporaryDirectory() as work:
        with open(os.path.join(work, "p.prm"), "w") as f:
            f.write(text)
        log = subprocess.run([solver, "p.prm"], cwd=work, env=env, capture_output=True,
                             text=True, check=True).stdout
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
                                   "LOW": f"{-0.5 - 3 * dx:.17g}", "HIGH": f"{0.5 + 3 * dx:.17g}",
                                   "PROBES": probes})
    rows.append(("all-PD", dx, Q, jump))
    Q, jump = run("crack_coupled.prm", {"DX": f"{dx:.17g}", "NC": str(round(1 / dx)),
                                        "PROBES": probes})
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
ax.set_xlabel("dx (PD) or h (FE)")
ax.set_ylabel("heat flow through the bar Q [W]")
ax.set_title("Insulated central crack, a = 0.2, bar 1 x 1, dT = 100 K, k = 1", fontsize=9)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(here, "convergence.png"), dpi=120)
