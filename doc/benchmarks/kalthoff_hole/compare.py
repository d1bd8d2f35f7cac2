#!/usr/bin/env python3
"""Compare the adaptive run of the Kalthoff-Winkler plate with a hole with its all-PD reference.

Usage: compare.py ADAPTIVE_DIR ALL_PD_DIR OUT_DIR [--threshold D]

Reads both runs' particle series (crack paths as doc/benchmarks/kalthoff_winkler/postprocess.py
measures them: the shortest lattice path through the particles with new damage > threshold from
the notch tip to the farthest such particle) and run.log ("Wall time of the run", "Peak memory"),
and writes OUT_DIR/paths.png (both runs' final paths over the all-PD damage, the hole) and
OUT_DIR/paths.csv. Prints, per crack, the largest distance between the two paths (the symmetric
Hausdorff distance of the two point sets, in mm and in horizons delta = 3.015 dx) and the crack
lengths, then the wall time and memory ratios adaptive / all-PD. The LAST line is
"largest path distance [horizons]: <upper crack's value>".
"""
import argparse
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "kalthoff_winkler"))
from postprocess import crack_history  # noqa: E402

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Rectangle  # noqa: E402

HOLE = (0.070, 0.082, 0.044, 0.056)  # as make_mesh.py


def path_distance(a, b):
    """The largest distance from a point of one path to the other path (symmetric Hausdorff)."""
    d = np.linalg.norm(a[:, None, :] - b[None, :, :], axis=2)
    return max(d.min(axis=1).max(), d.min(axis=0).max())


def measure(directory, what):
    log = open(os.path.join(directory, "run.log")).read()
    return float(re.search(what + r": ([\d.e+]+)", log).group(1))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("adaptive")
    parser.add_argument("all_pd")
    parser.add_argument("out")
    parser.add_argument("--threshold", type=float, default=0.35, help="new-damage threshold")
    args = parser.parse_args()
    tip = np.array([0.05, 0.025])
    runs = {}
    for name, directory in (("adaptive", args.adaptive), ("all-PD", args.all_pd)):
        _, dx, _, final = crack_history(directory, tip, args.threshold)
        runs[name] = dict(dx=dx, final=final)
    dx = runs["all-PD"]["dx"]
    horizon = 3.015 * dx

    fig, ax = plt.subplots(figsize=(5.0, 8.5))
    _, nodes, damage, _, _, _ = runs["all-PD"]["final"]
    ax.scatter(nodes[:, 0] * 1e3, nodes[:, 1] * 1e3, c=damage, cmap="Greys", vmin=0.0, vmax=1.0,
               s=0.05, marker="s", linewidths=0)
    ax.add_patch(Rectangle((HOLE[0] * 1e3, HOLE[2] * 1e3), (HOLE[1] - HOLE[0]) * 1e3,
                           (HOLE[3] - HOLE[2]) * 1e3, fill=False, color="b", lw=1.0))
    rows = []
    result = {}
    for k, side in ((4, "upper"), (5, "lower")):
        paths = {name: run["final"][k] for name, run in runs.items()}
        if any(p is None for p in paths.values()):
            print("%s crack: not grown in %s" % (side, ", ".join(n for n, p in paths.items()
                                                               if p is None)))
            continue
        distance = path_distance(paths["adaptive"]["path"], paths["all-PD"]["path"])
        result[side] = distance / horizon
        print("%s crack: largest distance between the adaptive and all-PD paths %.2f mm = %.2f "
              "horizons; path lengths %.1f / %.1f mm, angles %.1f / %.1f deg (adaptive / all-PD)"
              % (side, distance * 1e3, distance / horizon, paths["adaptive"]["length"] * 1e3,
                 paths["all-PD"]["length"] * 1e3, paths["adaptive"]["angle"],
                 paths["all-PD"]["angle"]))
        rows.append((side, distance, distance / horizon, paths["adaptive"]["length"],
                     paths["all-PD"]["length"]))
        for name, style in (("all-PD", "k--"), ("adaptive", "r-")):
            p = paths[name]["path"]
            ax.plot(p[:, 0] * 1e3, p[:, 1] * 1e3, style, lw=1.0,
                    label=name if side == "upper" else None)
    ax.set_aspect("equal")
    ax.set_xlim(0, 100)
    ax.set_ylim(-100, 100)
    ax.set_xlabel("x [mm] (impact direction)")
    ax.set_ylabel("y [mm]")
    ax.legend(fontsize=8, loc="lower left")
    ax.set_title("crack paths at the end: adaptive (red) and all-PD (black dashed)\nover the "
                 "all-PD damage; the hole in blue (dx = %.3g mm)" % (dx * 1e3), fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "paths.png"), dpi=150)
    plt.close(fig)
    with open(os.path.join(args.out, "paths.csv"), "w") as f:
        f.write("crack,distance_m,distance_horizons,length_adaptive_m,length_all_pd_m\n")
        for row in rows:
            f.write("%s,%.6g,%.6g,%.6g,%.6g\n" % row)

    for what, label in (("Wall time of the run", "wall time"), ("Peak memory", "peak memory")):
        print("%s adaptive / all-PD: %.2f" % (label, measure(args.adaptive, what)
                                               / measure(args.all_pd, what)))
    print("largest path distance [horizons]: %.2f" % result.get("upper", float("nan")))
    return 0


if __name__ == "__main__":
    sys.exit(main())
