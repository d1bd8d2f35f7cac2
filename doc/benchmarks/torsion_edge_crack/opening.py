#!/usr/bin/env python3
"""Torsion of the bar with an edge crack (seed 000, example 8.5): the crack opening profile.

usage: opening.py FE_RUN PD_RUN... [--plot opening.png]

The opening is the jump of the warping across the crack, w(x, dx/2) - w(x, -dx/2) between the
two particle rows next to the crack line (PD), and the same jump of the FE solution of the slit
section (FE_RUN, e.g. results/fe_a0.5_l3) between y = +-dx/2, interpolated linearly within each
half of the slit mesh (the crack faces' nodes belong to the half of their cells), together with
its limit on the faces, w(x, 0+) - w(x, 0-). Printed per PD run: the opening at a few points, and
the largest difference from the FE jump over the crack and over the ligament ahead of the tip
(where the section's symmetry makes w odd in y and the jump small), relative to the largest
opening.
"""
import argparse
import glob
import os
import re

import h5py
import numpy as np
from scipy.interpolate import griddata


# The PD runs' names pd_<model>_a<a>_dx<dx> (run.sh).
MODELS = {"bond": "bond-based", "state": "state-based (stabilization 0, the paper's)",
          "statestab": "state-based (stabilization 0.1)"}


def last_h5(run, prefix):
    files = sorted(glob.glob(os.path.join(run, f"{prefix}_*.h5")))
    if not files:
        raise SystemExit(f"no {prefix}_*.h5 in {run}")
    return h5py.File(files[-1], "r")


def fe_halves(run):
    """The vertices (x, y, w) of the cells above and of the cells below the crack line."""
    with last_h5(run, "solution") as h5:
        nodes, cells = np.asarray(h5["nodes"][:, :2]), np.asarray(h5["cells"][:])
        w = np.asarray(h5["w"][:, 0])
    above = nodes[cells].mean(axis=1)[:, 1] > 0
    halves = []
    for side in (above, ~above):
        index = np.unique(cells[side].ravel())
        halves.append((nodes[index], w[index]))
    return halves


def fe_opening(run, xs, y):
    """w(x, y) - w(x, -y) of the FE run at the points xs (y = 0: the crack faces)."""
    (upper_nodes, upper_w), (lower_nodes, lower_w) = fe_halves(run)
    up = griddata(upper_nodes, upper_w, np.column_stack([xs, np.full_like(xs, y)]), method="linear")
    down = griddata(lower_nodes, lower_w, np.column_stack([xs, np.full_like(xs, -y)]), method="linear")
    return up - down


def pd_opening(run):
    """(dx, xs, w(x, dx/2) - w(x, -dx/2)) of a PD run (results directory named ..._dx<dx>)."""
    dx = float(re.search(r"_dx([0-9.]+)$", run.rstrip("/")).group(1))
    with last_h5(run, "particles") as h5:
        x, w = np.asarray(h5["nodes"][:, :2]), np.asarray(h5["w"][:, 0])
    upper = {round(p[0], 9): v for p, v in zip(x, w) if abs(p[1] - dx / 2) < 1e-9}
    lower = {round(p[0], 9): v for p, v in zip(x, w) if abs(p[1] + dx / 2) < 1e-9}
    xs = np.array(sorted(set(upper) & set(lower)))
    return dx, xs, np.array([upper[s] - lower[s] for s in xs])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("fe")
    parser.add_argument("pd", nargs="+")
    parser.add_argument("--plot")
    args = parser.parse_args()
    tip = -0.5 + float(re.search(r"_a([0-9.]+)", args.fe).group(1))
    print(f"Crack opening (psi = mu = 1), crack x = -0.5 ... {tip:g}; FE: {args.fe}")
    curves = []
    for run in args.pd:
        dx, xs, opening = pd_opening(run)
        reference = fe_opening(args.fe, xs, dx / 2)
        on_crack = xs < tip
        largest = np.abs(reference[on_crack]).max()
        error = np.abs(opening - reference)[on_crack].max() / largest
        # Ahead of the tip w is odd in y (the section is symmetric about the crack line), so the
        # jump between the rows is small; the state-based model's odd-even mode is not.
        ligament = np.abs(opening - reference)[xs > tip + dx].max() / largest
        points = [-0.5 + dx / 2, -0.25, tip - 0.1, tip - dx / 2]
        values = ", ".join(f"x = {p:+.3f}: {np.interp(p, xs, opening):.5f} (FE "
                           f"{np.interp(p, xs, reference):.5f})" for p in points)
        print(f"  {os.path.basename(run.rstrip('/'))}: {values}; largest difference over the "
              f"crack {100 * error:.1f} % of the largest opening, ahead of the tip (the ligament) "
              f"{100 * ligament:.1f} %")
        curves.append((os.path.basename(run.rstrip("/")), xs, opening, dx))
    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6.5, 4.2))
        fine = np.linspace(-0.5, 0.5, 401)
        ax.plot(fine, fe_opening(args.fe, fine, 0.0), "k-", lw=1.2,
                label="FE slit section, crack faces y = 0±")
        for dx in sorted({c[3] for c in curves}):
            ax.plot(fine, fe_opening(args.fe, fine, dx / 2), "k--", lw=0.8,
                    label=f"FE slit section, y = ±{dx / 2:g}")
        for name, xs, opening, dx in curves:
            model = MODELS[name.split("_")[1]]
            ax.plot(xs, opening, "o" if "_bond_" in name else "s", ms=2.5,
                    label=f"PD {model}, dx = {dx:g}: rows y = ±{dx / 2:g}")
        ax.axvline(tip, color="grey", lw=0.5, ls=":")
        ax.set_xlabel("x")
        ax.set_ylabel("opening w(x, y) - w(x, -y) / psi")
        ax.set_title(f"Example 8.5, a = {tip + 0.5:g}: the warping's jump across the crack")
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(args.plot, dpi=150)
        print(f"wrote {args.plot}")


if __name__ == "__main__":
    main()
