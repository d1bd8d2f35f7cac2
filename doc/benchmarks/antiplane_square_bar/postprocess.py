#!/usr/bin/env python3
"""Square bar under antiplane shear (seed 000, example 8.1) against the Fourier series.

usage: postprocess.py --pd RESULTS... [--fe RESULTS...] [--plot field.png convergence.png]

PD runs are results directories named <model>_dx<dx> (bb: bond-based; sb: state-based; sbs<alpha>:
state-based with that stabilization), FE runs fe_l<level> (h = 2^-level). For each it reads the
last particle (particles_*.h5) or FE (solution_*.h5) output, drops the fictitious layers (|x| > 1/2)
and prints: the maximum of w against the series at the same point (PD: the top particles
(+-dx/2, 1/2 - dx/2); FE: the node (0, 1/2)), and the largest error over all points, relative to
the series maximum 3.727434e-4, also over the points at least 0.1 away from the top corners (where
the clamp meets the load and the gradient is singular).

Series (seed note 000, sec. 5.1): w = (S/mu) sum_n 4 (-1)^n / k_n^2 cosh(k_n (y + 1/2)) / sinh(k_n)
cos(k_n x), k_n = (2n + 1) pi, S/mu = 1e-3, 2000 terms (the terms fall like 1/n^2 on the top face).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from antiplane_runs import convergence_plot, label, read_run  # noqa: E402

GAMMA = 12000.0 / 12e6
K = (2 * np.arange(2000) + 1) * np.pi
SIGN = np.where(np.arange(2000) % 2 == 0, 1.0, -1.0)


def series(x, y):
    """w at the points (x, y), |x|, |y| <= 1/2, without overflow."""
    x = np.asarray(x, float)[..., None]
    y = np.asarray(y, float)[..., None]
    # cosh(k (y + 1/2)) / sinh(k) = (e^{k (y - 1/2)} + e^{-k (y + 3/2)}) / (1 - e^{-2k})
    ratio = (np.exp(K * (y - 0.5)) + np.exp(-K * (y + 1.5))) / (1 - np.exp(-2 * K))
    return GAMMA * np.sum(4 * SIGN / K**2 * ratio * np.cos(K * x), axis=-1)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--pd", nargs="*", default=[])
    parser.add_argument("--fe", nargs="*", default=[])
    parser.add_argument("--plot", nargs=2)
    args = parser.parse_args()
    w_max = series(0.0, 0.5)
    print(f"series: w(0, 1/2) = {w_max:.6e}, w(0.005, 0.495) = {series(0.005, 0.495):.6e}")

    runs = {}
    print("\nrun               dx / h     points  w_max          series there   error      "
          "max|w - series|/w_max  (0.1 from the top corners)")
    for run in args.pd + args.fe:
        name = run.rstrip("/").split("/")[-1]
        model, size, nodes, w = read_run(run, 1.0)
        body = np.abs(nodes[:, 0]) <= 0.5
        nodes, w = nodes[body], w[body]
        exact = series(nodes[:, 0], nodes[:, 1])
        # The top point nearest to the axis: the FE node (0, 1/2), the particles (+-dx/2, 1/2 - dx/2).
        top = np.argmin(np.hypot(nodes[:, 0], nodes[:, 1] - 0.5))
        error = np.abs(w - exact) / w_max
        away = np.hypot(np.abs(nodes[:, 0]) - 0.5, nodes[:, 1] - 0.5) > 0.1
        runs.setdefault(model, []).append((size, w[top] / exact[top] - 1, np.max(error),
                                           np.max(error[away]), nodes, w))
        print(f"{name:16s}  {size:<9g} {len(w):7d}  {w[top]:.6e}   {exact[top]:.6e}   "
              f"{100 * (w[top] / exact[top] - 1):+.3f} %   {100 * np.max(error):8.3f} %"
              f"             ({100 * np.max(error[away]):.3f} %)")

    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        field_plot, convergence = args.plot
        chosen = {m: next((v for v in values if abs(v[0] - 0.01) < 1e-12), values[-1])
                  for m, values in runs.items() if m != "fe"}
        fig, axes = plt.subplots(1, len(chosen) + 1, figsize=(4.2 * (len(chosen) + 1), 4))
        levels = np.linspace(0, w_max, 13)
        g = np.linspace(-0.5, 0.5, 101)
        X, Y = np.meshgrid(g, g)
        panels = [("series", X.ravel(), Y.ravel(), series(X.ravel(), Y.ravel()))]
        panels += [(f"{label(m)} (dx = {v[0]:g})", v[4][:, 0], v[4][:, 1], v[5])
                   for m, v in chosen.items()]
        for ax, (title, x, y, w) in zip(axes, panels):
            c = ax.tricontourf(x, y, w, levels=levels)
            ax.tricontour(g.repeat(101), np.tile(g, 101), series(g.repeat(101), np.tile(g, 101)),
                          levels=levels, colors="k", linewidths=0.4)
            ax.set_title(title, fontsize=9)
            ax.set_aspect("equal")
        fig.colorbar(c, ax=axes, shrink=0.8, label="w (black lines: series)")
        fig.savefig(field_plot, dpi=110)
        print(f"\nwrote {field_plot}")

        convergence_plot(runs, [(1, "o-", "|w_max error|"), (3, "s--", "max error (0.1 from corners)")],
                         "dx (PD), h (FE)", "relative to w_max = 3.727e-4",
                         "Square bar: error against the series", convergence)


if __name__ == "__main__":
    main()
