#!/usr/bin/env python3
"""Post-processing of the 3D Kalthoff-Winkler benchmark (kalthoff_3d_pd.prm, kalthoff_3d_adaptive.prm).

Usage: postprocess.py RESULTS_DIR [--notch-tip X,Y] [--threshold D] [--base NAME]

Reads RESULTS_DIR/particles.xdmf (the HDF5 files of the particles, 3D reference positions) and
statistics.csv and measures the cracks layer by layer: the lattice has one layer of particles per
dx through the thickness, and each layer is a 2D lattice on which the 2D benchmark's measure runs
unchanged (../kalthoff_winkler/postprocess.py: measure_crack(), new_damage(); the crack is the
connected cluster of particles with new damage > threshold that touches the notch tip, its angle
the least-squares line through the tip and the crack path, from the notch direction +x towards
+y; the lower crack mirrored). Writes into RESULTS_DIR:
  crack_layers.csv   per output time and layer z: angle, chord angle, path length and crack tip
                     of the upper crack, angle of the lower one;
  crack_front.png    the crack front through the thickness: the upper crack's path length and
                     tip against z at several times, and the angle of each layer at the end;
  damage_3d.png      the broken particles (new damage > threshold) in 3D at the last output,
                     beside the damage maps of the mid-thickness layer and of a face layer;
  pd_zone.png        the particles (the PD zone) over time: their number and their footprint in
                     the x-y plane at four times (adaptive runs; constant for all-PD);
  fe_stress.png      (coupled runs) the FE von Mises stress of the cells that cut the
                     mid-thickness plane, where FE remains, with the damage of the mid-thickness
                     particle layer on top, at four times;
  energies.png       as the 2D script.
It checks that every HDF5 file of particles.xdmf (and of solution.xdmf, the FE field, if there)
loads with h5py and holds the datasets the XDMF file names.
The LAST line printed is "crack angle mid-thickness [deg]: <value>", for the upper crack at the
last output time (the mean of the two middle layers when the layer count is even).
"""
import argparse
import csv
import os
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, ".."))
sys.path.insert(0, os.path.join(here, "..", "kalthoff_winkler"))
from particle_series import read_particles, read_series  # noqa: E402
from postprocess import (finish_specimen, lattice_spacing, measure_crack,  # noqa: E402
                         new_damage, plot_damage, plot_energies, read_statistics)
from matplotlib.collections import PolyCollection  # noqa: E402
from matplotlib.colors import Normalize  # noqa: E402

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def check_hdf5(directory, base):
    """Open every HDF5 file the XDMF file names, and each dataset it names; (files, datasets)."""
    path = os.path.join(directory, base + ".xdmf")
    tree = ET.parse(path)
    n_sets = 0
    for item in tree.iter("DataItem"):
        if item.get("Format") != "HDF" or item.text is None:
            continue
        name, dataset = item.text.strip().split(":")
        with h5py.File(os.path.join(directory, name), "r") as f:
            shape = tuple(int(v) for v in item.get("Dimensions").split())
            assert f[dataset].shape[0] == shape[0], (name, dataset, f[dataset].shape, shape)
            n_sets += 1
    files = {i.text.strip().split(":")[0] for i in tree.iter("DataItem")
             if i.get("Format") == "HDF" and i.text}
    return len(files), n_sets


def layers_of(nodes, dx):
    """The z of each lattice layer, sorted, and each particle's layer index."""
    key = np.round(nodes[:, 2] / dx * 2).astype(np.int64)
    values, index = np.unique(key, return_inverse=True)
    return values * dx / 2, index


def measure_layers(nodes, new, tip, dx, threshold):
    """[(z, upper, lower)] for every layer (measure_crack's dicts or None)."""
    zs, index = layers_of(nodes, dx)
    lower_tip = np.array([tip[0], -tip[1]])
    result = []
    for k, z in enumerate(zs):
        mask = index == k
        plane = nodes[mask][:, :2]
        result.append((z, measure_crack(plane, new[mask], tip, dx, threshold, +1.0),
                       measure_crack(plane, new[mask], lower_tip, dx, threshold, -1.0)))
    return result


def fe_mid_layer(path):
    """(footprints, von Mises) of the FE cells of one output file that cut the mid-thickness
    plane: each hexahedron's x-y outline (the extruded mesh's cells are prisms through z, so the
    outline is its four distinct corners in x-y, in cyclic order) and the mean of its corners'
    von Mises stress."""
    with h5py.File(path, "r") as f:
        nodes = np.array(f["nodes"])
        cells = np.array(f["cells"]).astype(np.int64)
        mises = np.array(f["von_mises_stress"])[:, 0]
    z_mid = 0.5 * (nodes[:, 2].min() + nodes[:, 2].max())
    z = nodes[cells, 2]
    cut = (z.min(axis=1) <= z_mid) & (z.max(axis=1) > z_mid)
    footprints = []
    for cell in cells[cut]:
        corners = np.unique(np.round(nodes[cell, :2] / 1e-9).astype(np.int64), axis=0) * 1e-9
        centre = corners.mean(axis=0)
        order = np.argsort(np.arctan2(corners[:, 1] - centre[1], corners[:, 0] - centre[0]))
        footprints.append(corners[order])
    return footprints, mises[cells[cut]].mean(axis=1)


def plot_fe_stress(directory, series, out, n_panels=4):
    """The FE von Mises stress in the mid-thickness plane where FE remains, with the damage of the
    middle particle layer on top (its extent is the PD zone), at n_panels output times."""
    fe_series = read_series(directory, "solution")
    picks = np.unique(np.linspace(0, len(fe_series) - 1, n_panels).round().astype(int))
    layers = [fe_mid_layer(fe_series[k][1]) for k in picks]
    limit = max(np.percentile(v, 99) for _, v in layers)
    fig, axes = plt.subplots(1, len(picks), figsize=(2.6 * len(picks) + 2.2, 5.4), sharey=True,
                             layout="constrained")
    for ax, k, (footprints, mises) in zip(np.atleast_1d(axes), picks, layers):
        time, path = series[k]
        nodes, damage = read_particles(path, dim=3)
        dx = lattice_spacing(nodes)
        zs, index = layers_of(nodes, dx)
        mid = index == len(zs) // 2
        ax.add_collection(PolyCollection([f * 1e3 for f in footprints], array=mises,
                                         cmap="viridis", norm=Normalize(0.0, limit),
                                         edgecolors="none"))
        ax.scatter(nodes[mid, 0] * 1e3, nodes[mid, 1] * 1e3, c=damage[mid], cmap="hot_r",
                   vmin=0.0, vmax=1.0, s=(72.0 * dx * 1e3 * 5.4 / 200.0) ** 2, marker="s",
                   linewidths=0)
        ax.set_xlim(0, 100)
        ax.set_ylim(-100, 100)
        ax.set_aspect("equal")
        ax.set_title("t = %.0f us, %d particles" % (time * 1e6, len(nodes)), fontsize=8)
        ax.set_xlabel("x [mm]")
    finish_specimen(fig, axes, limit, "Mid-thickness plane: FE stress where FE remains, the "
                    "middle particle layer (the PD zone) with its damage", out)


def middle(values):
    """The middle value of a list (the mean of the two middle ones for an even count)."""
    n = len(values)
    return values[n // 2] if n % 2 else 0.5 * (values[n // 2 - 1] + values[n // 2])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("results", help="directory with particles.xdmf and statistics.csv")
    parser.add_argument("--notch-tip", default="0.05,0.025", help="upper notch tip x,y [m]")
    parser.add_argument("--threshold", type=float, default=0.35, help="new-damage threshold")
    parser.add_argument("--base", default="particles", help="base name of the particle files")
    args = parser.parse_args()
    tip = np.array([float(v) for v in args.notch_tip.split(",")])
    out = lambda name: os.path.join(args.results, name)  # noqa: E731

    n_files, n_sets = check_hdf5(args.results, args.base)
    fe = ""
    if os.path.exists(out("solution.xdmf")):
        m, s = check_hdf5(args.results, "solution")
        fe = ", solution.xdmf: %d files, %d datasets" % (m, s)
    print("HDF5 check (h5py): particles.xdmf: %d files, %d datasets load with the shapes the "
          "XDMF names%s" % (n_files, n_sets, fe))

    stats = read_statistics(args.results)
    plot_energies(stats, out("energies.png"))

    series = read_series(args.results, args.base)
    first_damage = {}
    history = []  # (time, n particles, [(z, upper, lower)])
    footprints = []  # (time, x-y of the particles of the middle layer)
    final = None
    dx = None
    for time, path in series:
        nodes, damage = read_particles(path, dim=3)
        if dx is None:
            dx = lattice_spacing(nodes)
        new = new_damage(nodes, damage, tip, dx, first_damage)
        layers = measure_layers(nodes, new, tip, dx, args.threshold)
        history.append((time, len(nodes), layers))
        zs, index = layers_of(nodes, dx)
        footprints.append((time, nodes[index == len(zs) // 2][:, :2]))
        final = (time, nodes, damage, new, layers)

    with open(out("crack_layers.csv"), "w") as f:
        w = csv.writer(f)
        w.writerow(["time", "particles", "z", "angle_upper", "chord_upper", "length_upper",
                    "tip_x_upper", "tip_y_upper", "angle_lower"])
        for time, n, layers in history:
            for z, up, lo in layers:
                row = [time, n, z]
                row += (["nan"] * 5 if up is None else
                        [up["angle"], up["chord"], up["length"], up["tip"][0], up["tip"][1]])
                row += ["nan" if lo is None else lo["angle"]]
                w.writerow(["%.6g" % v if isinstance(v, float) else v for v in row])

    # The crack front through the thickness.
    fig, (ax, axa) = plt.subplots(1, 2, figsize=(10, 4.2))
    grown = [h for h in history if any(up is not None for _, up, _ in h[2])]
    picks = np.unique(np.linspace(0, len(grown) - 1, min(6, len(grown))).round().astype(int)) \
        if grown else []
    for k in picks:
        time, _, layers = grown[k]
        z = np.array([l[0] for l in layers]) * 1e3
        length = np.array([np.nan if l[1] is None else l[1]["length"] for l in layers]) * 1e3
        ax.plot(length, z, "o-", ms=3, label="%.0f us" % (time * 1e6))
    ax.set_xlabel("upper crack path length from the notch tip [mm]")
    ax.set_ylabel("z [mm] (through the thickness)")
    ax.set_title("crack front through the thickness", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    time, nodes, damage, new, layers = final
    z = np.array([l[0] for l in layers]) * 1e3
    axa.plot([np.nan if l[1] is None else l[1]["angle"] for l in layers], z, "o-",
             label="upper crack")
    axa.plot([np.nan if l[2] is None else l[2]["angle"] for l in layers], z, "s--",
             label="lower crack (mirrored)")
    axa.axvline(70.0, color="k", lw=0.8, ls=":", label="experiment, about 70 deg")
    axa.set_xlabel("crack angle at t = %.0f us [deg]" % (time * 1e6))
    axa.set_ylabel("z [mm]")
    axa.grid(alpha=0.3)
    axa.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out("crack_front.png"), dpi=120)
    plt.close(fig)

    # The broken particles in 3D, and two layers' damage maps.
    zs, index = layers_of(nodes, dx)
    broken = new > args.threshold
    p = nodes[broken] * 1e3
    for k, label in ((len(zs) // 2, "mid"), (0, "face")):
        mask = index == k
        plot_damage(nodes[mask][:, :2], damage[mask], None, time,
                    [layers[k][1], layers[k][2]], out("damage_%s.png" % label))
    fig = plt.figure(figsize=(13, 6.5))
    ax3 = fig.add_subplot(1, 3, (1, 2), projection="3d")
    ax3.scatter(p[:, 0], p[:, 1], p[:, 2], c=p[:, 2], cmap="viridis", s=1.5, depthshade=False)
    ax3.set_xlim(0, 100)
    ax3.set_ylim(-100, 100)
    ax3.set_zlim(0, 9)
    ax3.set_box_aspect((1, 2, 0.45))
    ax3.view_init(elev=40, azim=-65)
    ax3.set_xlabel("x [mm] (impact)")
    ax3.set_ylabel("y [mm]")
    ax3.set_zlabel("z [mm]")
    ax3.set_title("broken particles (new damage > %.2f) at %.0f us, colour: z (the thickness "
                  "exaggerated)" % (args.threshold, time * 1e6), fontsize=9)
    axm = fig.add_subplot(1, 3, 3)
    for k, colour in ((len(zs) // 2, "C0"), (0, "C3")):
        mask = (index == k) & broken
        axm.scatter(nodes[mask, 0] * 1e3, nodes[mask, 1] * 1e3, s=1, c=colour,
                    label="layer z = %.2f mm" % (zs[k] * 1e3))
    axm.set_xlim(0, 100)
    axm.set_ylim(-100, 100)
    axm.set_aspect("equal")
    axm.set_xlabel("x [mm]")
    axm.set_ylabel("y [mm]")
    axm.legend(fontsize=7, markerscale=5)
    axm.set_title("mid-thickness and face layer", fontsize=9)
    fig.tight_layout()
    fig.savefig(out("damage_3d.png"), dpi=120)
    plt.close(fig)

    # The PD zone over time.
    fig, (axn, *axes) = plt.subplots(1, 5, figsize=(15, 4.2),
                                     gridspec_kw={"width_ratios": [1.6, 1, 1, 1, 1]})
    axn.plot([h[0] * 1e6 for h in history], [h[1] for h in history], "o-", ms=3)
    axn.set_xlabel("time [us]")
    axn.set_ylabel("particles")
    axn.set_title("particles (PD zone, blended part included)", fontsize=8)
    axn.grid(alpha=0.3)
    for ax, k in zip(axes, np.unique(np.linspace(0, len(footprints) - 1, 4).round().astype(int))):
        t, xy = footprints[k]
        ax.scatter(xy[:, 0] * 1e3, xy[:, 1] * 1e3, s=0.3, c="C1")
        ax.set_xlim(0, 100)
        ax.set_ylim(-100, 100)
        ax.set_aspect("equal")
        ax.set_title("t = %.0f us: %d particles" % (t * 1e6, history[k][1]), fontsize=8)
        ax.set_xlabel("x [mm]")
    fig.suptitle("the PD zone in the x-y plane (particles of the middle layer)", fontsize=9)
    fig.tight_layout()
    fig.savefig(out("pd_zone.png"), dpi=120)
    plt.close(fig)

    if os.path.exists(out("solution.xdmf")):
        plot_fe_stress(args.results, series, out("fe_stress.png"))

    print("results: %s (t_end = %.3g us, dx = %.3g mm, %d layers, %d output times, particles "
          "%d at the start, %d at the end)" % (args.results, time * 1e6, dx * 1e3, len(zs),
                                               len(series), history[0][1], history[-1][1]))
    dissipated = stats.get("dissipated_energy", [0.])[-1]
    print("final energies [J]: kinetic %.6g, strain %.6g, external work %.6g, dissipated %.6g, "
          "kinetic + strain + dissipated - work %.3g; broken bonds %d"
          % (stats["kinetic_energy"][-1], stats["strain_energy"][-1], stats["external_work"][-1],
             dissipated, stats["energy_error"][-1], stats["broken_bonds"][-1]))
    angles = [np.nan if up is None else up["angle"] for _, up, _ in layers]
    lower = [np.nan if lo is None else lo["angle"] for _, _, lo in layers]
    lengths = [np.nan if up is None else up["length"] * 1e3 for _, up, _ in layers]
    print("per layer z [mm]: " + ", ".join("%.2f" % (z * 1e3) for z in zs))
    print("  upper angle [deg]: " + ", ".join("%.1f" % a for a in angles))
    print("  lower angle [deg]: " + ", ".join("%.1f" % a for a in lower))
    print("  upper path length [mm]: " + ", ".join("%.1f" % v for v in lengths))
    print("crack angle faces [deg]: %.1f, %.1f (lower crack %.1f, %.1f)"
          % (angles[0], angles[-1], lower[0], lower[-1]))
    print("crack angle mid-thickness, lower crack [deg]: %.1f" % middle(lower))
    print("crack angle mid-thickness [deg]: %.1f" % middle(angles))
    return 0


if __name__ == "__main__":
    sys.exit(main())
