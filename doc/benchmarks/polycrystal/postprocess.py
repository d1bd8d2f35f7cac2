"""Postprocessing of the polycrystal benchmark (run.sh): for every grain-boundary fracture
energy ratio, the share of the crack that runs along grain boundaries, and the plots
polycrystal_intergranular.png (that share against the ratio) and polycrystal_cracks.png (the
crack over the grains for three ratios).

The crack: the particles beyond the notch tip (x > 20 mm, away from the grips) with damage
> 0.35. A crack particle is intergranular if it lies within dx of a grain boundary: the distance
to the boundary between its grain and the nearest other one, (d2^2 - d1^2) / (2 |s2 - s1|)
with d1, d2 the distances to the two nearest seeds s1, s2 (the bisector of the Voronoi cells).
A crack that ignored the grains would give the share of all particles within dx of a boundary
(the baseline, printed): the grains are only 8 dx across, so that share is large.

usage: postprocess.py RATIO [RATIO ...]   (in the benchmark's directory, after run.sh)
"""
import os
import re
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from scipy.spatial import cKDTree  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from particle_series import read_particles, read_series  # noqa: E402

DX = 0.5e-3
DAMAGED = 0.35


def boundary_distance(x, seeds):
    """The distance of every point of x to the bisector of its two nearest seeds, and its grain."""
    distance, nearest = cKDTree(seeds).query(x, k=2)
    s1, s2 = seeds[nearest[:, 0]], seeds[nearest[:, 1]]
    return ((distance[:, 1] ** 2 - distance[:, 0] ** 2) / (2. * np.linalg.norm(s2 - s1, axis=1)),
            nearest[:, 0])


def log_value(path, label):
    with open(path) as f:
        match = re.search(rf"^{label}: (\S+)", f.read(), re.M)
    return float(match.group(1)) if match else float("nan")


def analyse(directory, seeds):
    """The crack of one run: (crack particles, share along grain boundaries, baseline,
    dissipated energy, wall time, (x, damage, grain))."""
    x, damage = read_particles(read_series(directory)[-1][1])
    to_boundary, grain = boundary_distance(x, seeds)
    body = (np.abs(x[:, 1]) < 0.0285) & (x[:, 0] > 0.020)
    crack = body & (damage > DAMAGED)
    near = to_boundary < DX
    share = near[crack].mean() if crack.any() else float("nan")
    dissipated = log_value(os.path.join(directory, "run.log"), "Dissipated energy")
    with open(os.path.join(directory, "wall_time")) as f:
        wall = float(f.read())
    return crack.sum(), share, near[body].mean(), dissipated, wall, (x, damage, grain)


def main():
    ratios = sys.argv[1:]
    grains = np.loadtxt("grains.txt")
    seeds, phi = grains[:, :2], grains[:, 2]
    runs = {(kind, ratio): analyse(os.path.join("results", prefix + f"ratio_{ratio}"), seeds)
            for kind, prefix in (("all-PD", ""), ("coupled", "coupled_")) for ratio in ratios}

    print("| grain-boundary ratio | along grain boundaries: all-PD, coupled | crack particles "
          "| dissipated energy [mJ] | wall time [s] |")
    print("|---|---|---|---|---|")
    for ratio in ratios:
        a, c = runs[("all-PD", ratio)], runs[("coupled", ratio)]
        print(f"| {ratio} | {a[1]:.2f}, {c[1]:.2f} | {a[0]}, {c[0]} | {1e3 * a[3]:.2f}, "
              f"{1e3 * c[3]:.2f} | {a[4]:.1f}, {c[4]:.1f} |")
    print(f"baseline (share of all particles within dx of a grain boundary): "
          f"{runs[('all-PD', ratios[0])][2]:.2f}")
    # Rises between neighbouring ratios smaller than the binomial standard deviation of the
    # share of about 190 particles (0.035) are noise.
    for kind in ("all-PD", "coupled"):
        rows = [runs[(kind, ratio)] for ratio in ratios]
        shares = [row[1] for row in rows]
        noise = max(np.sqrt(s * (1. - s) / row[0]) for s, row in zip(shares, rows))
        trend = all(b <= a + noise for a, b in zip(shares, shares[1:]))
        print(f"{kind}: the share along grain boundaries does not grow with the ratio (within "
              f"one standard deviation, {noise:.3f}): {'yes' if trend else 'NO'}; "
              f"{shares[0]:.2f} at {ratios[0]}, {shares[-1]:.2f} at {ratios[-1]}")
    walls = [runs[("coupled", r)][4] / runs[("all-PD", r)][4] for r in ratios]
    print(f"wall time coupled / all-PD: {min(walls):.2f} ... {max(walls):.2f}")

    fig, ax = plt.subplots(figsize=(5.5, 4))
    for kind, style in (("all-PD", "o-"), ("coupled", "s--")):
        ax.plot([float(r) for r in ratios], [runs[(kind, r)][1] for r in ratios], style,
                label=f"{kind}: crack along grain boundaries")
    ax.axhline(runs[("all-PD", ratios[0])][2], color="gray", ls=":",
               label="baseline (all particles within dx)")
    ax.set_xlabel("grain-boundary fracture energy / grain fracture energy")
    ax.set_ylabel("share of the crack (particles)")
    ax.set_ylim(0, 1)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig("polycrystal_intergranular.png", dpi=150)

    shown = [r for r in dict.fromkeys((ratios[0], "1", ratios[-1])) if r in ratios]
    fig, axes = plt.subplots(len(shown), 2, figsize=(13, 2.4 * len(shown)), squeeze=False)
    for row, ratio in zip(axes, shown):
        for ax, kind in zip(row, ("all-PD", "coupled")):
            x, damage, grain = runs[(kind, ratio)][5]
            window = (np.abs(x[:, 1]) < 0.008) & (x[:, 0] > 0.015)
            ax.scatter(1e3 * x[window, 0], 1e3 * x[window, 1], c=phi[grain[window]],
                       cmap="twilight", vmin=0, vmax=180, s=2, marker="s")
            cracked = window & (damage > DAMAGED)
            ax.scatter(1e3 * x[cracked, 0], 1e3 * x[cracked, 1], c="k", s=3, marker="s")
            ax.set_aspect("equal")
            ax.set_title(f"{kind}, grain-boundary ratio {ratio}: damage > {DAMAGED} black "
                         "(x < 20 mm: the notch)", fontsize=9)
            ax.set_xlabel("x [mm]")
            ax.set_ylabel("y [mm]")
    fig.tight_layout()
    fig.savefig("polycrystal_cracks.png", dpi=150)


if __name__ == "__main__":
    main()
