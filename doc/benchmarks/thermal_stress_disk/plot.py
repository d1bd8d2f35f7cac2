"""Convergence plot of the thermal-stress disk (README.md): the largest displacement error
relative to the largest exact displacement against the lattice spacing, per case and part."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
fig, ax = plt.subplots(figsize=(5.5, 4))
for case, marker in (("pd", "o"), ("blended", "s"), ("schwarz", "^")):
    data = [r for r in rows if r["case"] == case]
    dx = [1e3 * float(r["dx"]) for r in data]
    ax.loglog(dx, [float(r["particle_error"]) for r in data], marker + "-",
              label=f"{case}: particles")
    if case != "pd":
        ax.loglog(dx, [float(r["fe_error"]) for r in data], marker + "--",
                  label=f"{case}: FE nodes")
ax.set_xlabel("lattice spacing dx [mm] (FE cells refined with it)")
ax.set_ylabel("largest |u - u_exact| / largest |u_exact|")
ax.set_title("Thermal stresses in a disk, T = T_ref + 100 K (1 - r^2/b^2)")
ax.grid(True, which="both", alpha=0.3)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=130)
