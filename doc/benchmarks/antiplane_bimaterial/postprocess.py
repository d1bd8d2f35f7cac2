#!/usr/bin/env python3
"""Bimaterial bar under antiplane shear (seed 000, example 8.2) against the exact solution.

usage: postprocess.py --pd RESULTS... [--fe RESULTS...] [--plot profile.png convergence.png]

PD runs are results directories named <model>_dx<dx> (model bb: bond-based; sb: state-based;
sbs<alpha>: state-based with that stabilization), FE runs fe_l<level>. For each it reads the last
particle (particles_*.h5) or FE (solution_*.h5) output, drops the fictitious layers (y < -1/2) and prints
the largest error against the exact solution, relative to its largest value 1.5e-3, and the value
at the top row of particles (y = 1/2 - dx/2) against the exact value there.

Exact solution (seed note 000, sec. 5.2): the sides are free, so w depends on y alone:
w = S (y + 1/2)/mu1 for y < 0 (mu1 = 12e6), S/(2 mu1) + S y/mu2 for y > 0 (mu2 = 6e6), S = 12000.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from antiplane_runs import convergence_plot, label, read_run  # noqa: E402

S, MU1, MU2 = 12000.0, 12e6, 6e6
W_MAX = S * (0.5 / MU1 + 0.5 / MU2)


def exact(y):
    y = np.asarray(y, float)
    return np.where(y < 0, S * (y + 0.5) / MU1, S * 0.5 / MU1 + S * y / MU2)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--pd", nargs="*", default=[])
    parser.add_argument("--fe", nargs="*", default=[])
    parser.add_argument("--plot", nargs=2)
    args = parser.parse_args()
    print(f"exact: w(top face) = {W_MAX:.6e}, slope ratio mu1/mu2 = {MU1 / MU2:g}")

    runs = {}
    print("\nrun               dx / h     points  max|w - exact|/w_max  w(top row)     exact there"
          "    error")
    for run in args.pd + args.fe:
        name = run.rstrip("/").split("/")[-1]
        model, size, nodes, w = read_run(run, 0.1)
        body = nodes[:, 1] >= -0.5
        nodes, w = nodes[body], w[body]
        error = np.max(np.abs(w - exact(nodes[:, 1]))) / W_MAX
        y_top = 0.5 if model == "fe" else 0.5 - size / 2
        top = np.abs(nodes[:, 1] - y_top) < 1e-9
        w_top = np.mean(w[top])
        top_error = w_top / exact(y_top) - 1
        runs.setdefault(model, []).append((size, error, top_error, nodes, w))
        print(f"{name:16s}  {size:<9g} {len(w):7d}  {100 * error:10.4f} %         {w_top:.6e}  "
              f"{exact(y_top):.6e}  {100 * top_error:+.4f} %")

    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        profile, convergence = args.plot
        fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
        y = np.linspace(-0.5, 0.5, 201)
        axes[0].plot(exact(y), y, "k-", lw=1, label="exact")
        markers = iter("os^vdx")
        for model, values in runs.items():
            # The finest run at dx = 0.01 (the paper's lattice), else the first.
            size, _, _, nodes, w = next((v for v in values if abs(v[0] - 0.01) < 1e-12), values[0])
            column = np.abs(nodes[:, 0] - np.min(np.abs(nodes[:, 0]))) < 1e-9
            column &= nodes[:, 0] >= 0
            order = np.argsort(nodes[column, 1])
            name = label(model)
            axes[0].plot(w[column][order], nodes[column, 1][order], next(markers), ms=3,
                         mfc="none", label=f"{name} ({size:g})")
            axes[1].plot(nodes[column, 1][order],
                         (w[column][order] - exact(nodes[column, 1][order])) / W_MAX, "-",
                         label=f"{name} ({size:g})")
        axes[0].axhline(0, color="gray", lw=0.5)
        axes[0].set_xlabel("w")
        axes[0].set_ylabel("y")
        axes[0].set_title("w along the vertical axis (x = dx/2)")
        axes[1].set_xlabel("y")
        axes[1].set_ylabel("(w - exact) / w_max")
        axes[1].set_title("error along the vertical axis")
        for ax in axes:
            ax.grid(True, lw=0.3)
            ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(profile, dpi=120)
        print(f"\nwrote {profile}")

        convergence_plot({m: v for m, v in runs.items() if m != "fe"},
                         [(1, "o-", "max error"), (2, "s--", "|top error|")], "dx",
                         "relative to w_max = 1.5e-3",
                         "Bimaterial bar: PD error against the exact solution", convergence)


if __name__ == "__main__":
    main()
