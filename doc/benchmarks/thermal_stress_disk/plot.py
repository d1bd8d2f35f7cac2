"""Convergence plot of the thermal-stress disk (README.md): the root-mean-square and the
largest displacement error relative to the largest exact displacement against the lattice
spacing, per case, on the particles and on the FE nodes outside the PD-only core."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
fig, axes = plt.subplots(1, 2, figsize=(10, 4), sharey=True)
for ax, norm in zip(axes, ("rms", "max")):
    for case, marker in (("pd", "o"), ("blended", "s"), ("schwarz", "^")):
        data = [r for r in rows if r["case"] == case and r["particle_max"] != "failed"]
        dx = [1e3 * float(r["dx"]) for r in data]
        ax.loglog(dx, [float(r["particle_" + norm]) for r in data], marker + "-",
                  label=f"{case}: particles")
        if case != "pd":
            ax.loglog(dx, [float(r["fe_" + norm]) for r in data], marker + "--",
                      label=f"{case}: FE nodes, r >= 20 mm")
    ax.set_xlabel("lattice spacing dx [mm] (FE cells refined with it)")
    ax.set_title(f"{norm} of |u - u_exact| / max |u_exact|")
    ax.grid(True, which="both", alpha=0.3)
axes[0].set_ylabel("relative displacement error")
axes[0].legend(fontsize=7)
fig.suptitle("Thermal stresses in a disk, T = T_ref + 100 K (1 - r^2/b^2), plane stress")
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=130)
