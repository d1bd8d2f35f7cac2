#!/usr/bin/env python3
"""Post-processing of the plate_uniaxial_tension benchmark (seed 002, thesis ch. 6).

Reads the last particle file (HDF5 written by deal.II: datasets 'nodes' with the 2D reference
positions and 'displacement' padded to 3 components) and statistics.csv of one or more result
directories, compares the displacement along the two mid-lines with the plane-stress elasticity
solution

    u_y = eps (y - L/2),   u_x = -nu eps (x - L/2),   eps = 2 U / L,

prints the errors in the central half of each line and the grip reaction against E eps L h, and
plots PD against elasticity (mid_lines.png in the first directory, or in --plot-dir). With
--markdown it also prints one table row per directory, as in README.md.

Usage: postprocess.py DIR [DIR ...] [--labels A,B,...] [--plot-dir DIR] [--markdown]
                      [--grip-displacement U]
Needs numpy, h5py, matplotlib (Debian: python3-numpy python3-h5py python3-matplotlib).
"""

import argparse
import glob
import itertools
import os
import re
import sys

import h5py
import numpy as np

L = 0.05  # plate side [m]
U = 5.6141e-4  # grip displacement [m] (seed 002, Table 6.2: half elongation)
NU = 1.0 / 3.0  # Poisson ratio implied by 2D plane-stress PMB
E = 192e9  # Young's modulus [Pa]
H = 1e-4  # thickness [m]


def last_particle_file(directory):
    files = glob.glob(os.path.join(directory, "particles_*.h5"))
    if not files:
        sys.exit(f"no particles_*.h5 in {directory}")
    return max(files, key=lambda f: int(re.findall(r"(\d+)\.h5$", f)[0]))


def mid_line(position, along, value, across_centre, dx):
    """Average of `value` over the two particle lines nearest to the mid-line
    (the cell-centred lattice has none on it), as a function of `along`."""
    keep = (np.abs(across_centre) < dx) & (along > 0.0) & (along < L)
    coords = np.round(along[keep] / dx * 2.0).astype(int)
    result = {}
    for c, v in zip(coords, value[keep]):
        result.setdefault(c, []).append(v)
    keys = sorted(result)
    return np.array([k * dx / 2.0 for k in keys]), np.array([np.mean(result[k]) for k in keys])


def errors(s, u_pd, u_el):
    """Errors in the central half L/4 <= s <= 3L/4, relative to the largest elastic value there;
    and the relative error of the least-squares slope there."""
    central = (s >= L / 4) & (s <= 3 * L / 4)
    scale = np.max(np.abs(u_el[central]))
    e = np.abs(u_pd[central] - u_el[central]) / scale
    slope_pd = np.polyfit(s[central], u_pd[central], 1)[0]
    slope_el = np.polyfit(s[central], u_el[central], 1)[0]
    return e.max(), e.mean(), slope_pd / slope_el - 1.0


def analyse(directory, eps):
    fname = last_particle_file(directory)
    with h5py.File(fname, "r") as f:
        x = f["nodes"][:]
        u = f["displacement"][:]
    dx = np.min(np.diff(np.unique(np.round(x[:, 0], 12))))
    stats = np.genfromtxt(os.path.join(directory, "statistics.csv"), delimiter=",", names=True)

    y_line, uy = mid_line(x, x[:, 1], u[:, 1], x[:, 0] - L / 2, dx)
    x_line, ux = mid_line(x, x[:, 0], u[:, 0], x[:, 1] - L / 2, dx)
    uy_el = eps * (y_line - L / 2)
    ux_el = -NU * eps * (x_line - L / 2)
    result = {
        "file": fname,
        "dx": dx,
        "y": y_line,
        "uy": uy,
        "uy_el": uy_el,
        "x": x_line,
        "ux": ux,
        "ux_el": ux_el,
        "uy_errors": errors(y_line, uy, uy_el),
        "ux_errors": errors(x_line, ux, ux_el),
        "time": stats["time"][-1],
        "kinetic": stats["kinetic_energy"][-1],
        "strain": stats["strain_energy"][-1],
        "max_kinetic": np.max(stats["kinetic_energy"]),
        "reaction": stats["reaction_pull_top_y"][-1],
    }
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("directories", nargs="+")
    parser.add_argument("--labels", default=None, help="comma-separated legend labels")
    parser.add_argument("--plot-dir", default=None, help="where to write mid_lines.png")
    parser.add_argument("--markdown", action="store_true", help="also print README table rows")
    parser.add_argument("--grip-displacement", type=float, default=U,
                        help=f"half elongation U [m], default {U}; eps = 2 U / L")
    args = parser.parse_args()
    labels = args.labels.split(",") if args.labels else args.directories
    eps = 2.0 * args.grip_displacement / L

    results = [analyse(d, eps) for d in args.directories]
    reaction_el = E * eps * L * H
    print(f"applied strain eps = {eps:.7g}, nu = {NU:.6f}; "
          f"elastic reaction E eps L h = {reaction_el:.5e} N")
    for label, r in zip(labels, results):
        print(f"\n{label}: {r['file']} at t = {r['time']:.4e} s")
        print(f"  kinetic energy {r['kinetic']:.3e} J (max during the run {r['max_kinetic']:.3e} J), "
              f"strain energy {r['strain']:.5e} J")
        print(f"  reaction of the top grip {r['reaction']:.5e} N ({100 * (r['reaction'] / reaction_el - 1):+.2f} %)")
        for name, key in (("u_y on the vertical mid-line  ", "uy_errors"), ("u_x on the horizontal mid-line", "ux_errors")):
            emax, emean, slope = r[key]
            print(f"  {name}: central half: max error {100 * emax:.2f} %, mean error {100 * emean:.2f} % "
                  f"(of the largest elastic value there), slope error {100 * slope:+.2f} %")
    if args.markdown:
        print()

        def signed(value):  # with the typographic minus of the README
            return f"{100 * value:+.2f} %".replace("-", "\u2212")

        for label, r in zip(labels, results):
            uy_max, uy_mean, uy_slope = r["uy_errors"]
            ux_max, ux_mean, ux_slope = r["ux_errors"]
            print(f"| {label} | {100 * uy_max:.2f} % / {100 * uy_mean:.2f} % | {signed(uy_slope)} "
                  f"| {100 * ux_max:.2f} % / {100 * ux_mean:.2f} % | {signed(ux_slope)} | "
                  f"{signed(r['reaction'] / reaction_el - 1)} |")

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5), sharex="col")
    r0 = results[0]
    axes[0, 0].plot(r0["y"] * 1e3, r0["uy_el"] * 1e3, "k-", lw=1, label="plane-stress elasticity")
    axes[0, 1].plot(r0["x"] * 1e3, r0["ux_el"] * 1e3, "k-", lw=1, label="plane-stress elasticity")
    for label, r, marker in zip(labels, results, itertools.cycle("os^dv<>ph")):
        axes[0, 0].plot(r["y"] * 1e3, r["uy"] * 1e3, marker, ms=3, mfc="none", label=f"PD, {label}")
        axes[0, 1].plot(r["x"] * 1e3, r["ux"] * 1e3, marker, ms=3, mfc="none", label=f"PD, {label}")
        axes[1, 0].plot(r["y"] * 1e3, (r["uy"] - r["uy_el"]) * 1e6, marker + "-", ms=3, lw=0.5, mfc="none", label=label)
        axes[1, 1].plot(r["x"] * 1e3, (r["ux"] - r["ux_el"]) * 1e6, marker + "-", ms=3, lw=0.5, mfc="none", label=label)
    for ax in axes.flat:
        ax.axvspan(L / 4 * 1e3, 3 * L / 4 * 1e3, color="0.92", zorder=0)
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=7)
    axes[0, 0].set_ylabel("u_y [mm]")
    axes[0, 1].set_ylabel("u_x [mm]")
    axes[1, 0].set_ylabel("u_y(PD) - u_y(elasticity) [um]")
    axes[1, 1].set_ylabel("u_x(PD) - u_x(elasticity) [um]")
    axes[1, 0].set_xlabel("y [mm] (vertical mid-line)")
    axes[1, 1].set_xlabel("x [mm] (horizontal mid-line)")
    fig.suptitle("Thin plate in uniaxial tension (seed 002): PD steady state vs elasticity; shaded: central half")
    fig.tight_layout()
    out = os.path.join(args.plot_dir or args.directories[0], "mid_lines.png")
    fig.savefig(out, dpi=130)
    print(f"\nplot: {out}")


if __name__ == "__main__":
    main()
