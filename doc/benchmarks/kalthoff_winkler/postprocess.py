#!/usr/bin/env python3
"""Post-processing of the Kalthoff-Winkler benchmark (all-PD and, later, FE+PD variants).

Usage: postprocess.py RESULTS_DIR [--notch-tip X,Y] [--threshold D] [--base NAME]

Reads RESULTS_DIR/particles.xdmf (the time series of particle HDF5 files written by
perideal-solid: datasets /nodes (reference positions), /damage, /displacement, ...) and
RESULTS_DIR/statistics.csv, and writes into RESULTS_DIR:
  damage_final.png    damage index at the last output time (reference configuration);
  energies.png        kinetic, strain, external work, kinetic + strain, the energy of the
                      broken bonds (dissipated) and the balance with and without it;
  crack_angle.png     crack angle and crack length against time;
  crack_angle.csv     the same numbers (time, angle, chord angle, length, tip x, tip y);
  specimen.png        coupled variants (RESULTS_DIR/solution.xdmf, the FE field): the whole
                      specimen at four output times, the FE von Mises stress where FE remains,
                      the particles' damage on top and the outline of the FE part, so that the
                      PD zone is seen growing (adaptive variant) or fixed (band).
The LAST line printed is "crack angle [deg]: <value>" for the crack grown from the upper notch
tip at the last output time.

Crack angle (defined so that it does not depend on branches or on the damage of the notch
faces):
  1. "new damage" = damage(t), less, within a horizon of the notches, the particle's damage in
     the first output that has it (t = 0, or the output after the adaptive PD region created
     it): the pre-cracked notch faces start with a damage index of about 0.3 that is not crack
     growth (elsewhere a particle the adaptive region created may be cracked by the next
     output, so its first damage is not subtracted);
  2. crack particles: new damage > threshold (0.35), in the half plane beyond the upper notch
     (y >= y_tip, the side the experiment's crack runs to) and not behind the tip
     (x >= x_tip - 3 dx);
  3. the crack is the 8-connected lattice cluster of crack particles that touches the notch tip
     (a particle within 2 horizons of it); its tip is the cluster particle with the largest
     path length (Dijkstra along the cluster) from the notch tip, and the crack path is that
     shortest path, so side branches do not enter the fit;
  4. the angle is that of the least-squares line through the notch tip and the path particles
     (principal direction of sum (p - tip)(p - tip)^T), measured from the notch direction +x
     (the impact direction) towards +y, i.e. as in the experiment (about 70 deg). The chord angle
     (notch tip to crack tip) is reported too.
The lower crack (mirror image) is measured the same way as a symmetry check.
"""
import argparse
import csv
import heapq
import math
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from particle_series import read_particles, read_series  # noqa: E402

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection, PolyCollection  # noqa: E402
from matplotlib.colors import Normalize  # noqa: E402


def lattice_spacing(nodes):
    xs = np.unique(np.round(nodes[:, 0], 12))
    return float(np.min(np.diff(xs)))


def measure_crack(nodes, new_damage, tip, dx, threshold, sign=+1.0):
    """Crack from the notch tip into the half plane sign*(y - y_tip) >= 0.

    Returns dict(angle, chord, length, tip) or None when no crack has grown.
    """
    x = nodes[:, 0] - tip[0]
    y = sign * (nodes[:, 1] - tip[1])
    mask = (new_damage > threshold) & (y >= -0.5 * dx) & (x >= -3.0 * dx)
    idx = np.nonzero(mask)[0]
    if idx.size == 0:
        return None
    ij = np.round(np.column_stack((x[idx], y[idx])) / dx * 2.0).astype(int)  # half-cell units
    lookup = {(a, b): k for k, (a, b) in enumerate(map(tuple, ij))}
    pts = np.column_stack((x[idx], y[idx]))
    dist_tip = np.hypot(pts[:, 0], pts[:, 1])
    seeds = np.nonzero(dist_tip <= 2.0 * 3.015 * dx + 1e-12)[0]
    if seeds.size == 0:
        return None
    # Dijkstra from the particles next to the notch tip (start cost: their distance to it).
    best = np.full(len(pts), np.inf)
    prev = np.full(len(pts), -1)
    heap = []
    for s in seeds:
        best[s] = dist_tip[s]
        heap.append((best[s], s))
    heapq.heapify(heap)
    steps = [(da, db) for da in (-2, 0, 2) for db in (-2, 0, 2) if (da, db) != (0, 0)]
    while heap:
        d, k = heapq.heappop(heap)
        if d > best[k]:
            continue
        a, b = ij[k]
        for da, db in steps:
            m = lookup.get((a + da, b + db))
            if m is None:
                continue
            nd = d + 0.5 * dx * math.hypot(da, db)
            if nd < best[m]:
                best[m] = nd
                prev[m] = k
                heapq.heappush(heap, (nd, m))
    reached = np.isfinite(best)
    if not reached.any():
        return None
    end = int(np.argmax(np.where(reached, best, -1.0)))
    path = []
    k = end
    while k >= 0:
        path.append(k)
        k = prev[k]
    p = pts[path]
    length = float(best[end])
    if np.hypot(*pts[end]) < 2.0 * 3.015 * dx:
        return None  # only the damage around the tip itself: no crack yet
    # Least-squares line through the notch tip (origin) and the path particles.
    m2 = p.T @ p
    w, v = np.linalg.eigh(m2)
    direction = v[:, np.argmax(w)]
    if direction @ pts[end] < 0:
        direction = -direction
    angle = math.degrees(math.atan2(direction[1], direction[0]))
    chord = math.degrees(math.atan2(pts[end][1], pts[end][0]))
    return dict(
        angle=angle,
        chord=chord,
        length=length,
        tip=(tip[0] + pts[end][0], tip[1] + sign * pts[end][1]),
        path=np.column_stack((tip[0] + p[:, 0], tip[1] + sign * p[:, 1])),
        fit=np.array([[tip[0], tip[1]],
                      [tip[0] + direction[0] * (direction @ pts[end]),
                       tip[1] + sign * direction[1] * (direction @ pts[end])]]),
    )


def read_statistics(directory):
    with open(os.path.join(directory, "statistics.csv")) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def plot_energies(stats, out):
    t = stats["time"] * 1e6
    fig, ax = plt.subplots(figsize=(7, 4.5))
    kin, strain, work = stats["kinetic_energy"], stats["strain_energy"], stats["external_work"]
    ax.plot(t, kin, label="kinetic")
    ax.plot(t, strain, label="strain")
    ax.plot(t, work, label="external work")
    ax.plot(t, kin + strain, "k--", label="kinetic + strain")
    # energy_error is kinetic + strain + dissipated - work where the run reports the energy the
    # broken bonds took (dissipated_energy).
    dissipated = stats.get("dissipated_energy", np.zeros_like(t))
    ax.plot(t, stats["energy_error"] - dissipated, ":", label="kinetic + strain - work")
    if "dissipated_energy" in stats:
        ax.plot(t, dissipated, label="dissipated (broken bonds)")
        ax.plot(t, stats["energy_error"], "k-.", label="kinetic + strain + dissipated - work")
    ax.set_xlabel("time [us]")
    ax.set_ylabel("energy per unit thickness [J/m]")
    ax.grid(alpha=0.3)
    ax2 = ax.twinx()
    ax2.plot(t, stats["broken_bonds"], color="grey", lw=0.8, label="broken bonds")
    ax2.set_ylabel("broken bonds (grey)")
    ax.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)


def plot_damage(nodes, damage, disp, time, cracks, out):
    fig, ax = plt.subplots(figsize=(5.2, 8.5))
    dx = lattice_spacing(nodes)
    # The particles sit on a lattice: draw the damage as an image, one pixel per particle (blank
    # where there is none, e.g. in the finite-element part of a coupled variant).
    lo = nodes.min(axis=0)
    ij = np.round((nodes - lo) / dx).astype(int)
    image = np.full(ij.max(axis=0) + 1, np.nan)
    image[ij[:, 0], ij[:, 1]] = damage
    extent = [(lo[0] - dx / 2) * 1e3, (lo[0] + (image.shape[0] - 0.5) * dx) * 1e3,
              (lo[1] - dx / 2) * 1e3, (lo[1] + (image.shape[1] - 0.5) * dx) * 1e3]
    s = ax.imshow(image.T, origin="lower", extent=extent, cmap="viridis", vmin=0.0, vmax=1.0,
                  interpolation="nearest")
    for crack in cracks:
        if crack is None:
            continue
        ax.plot(crack["path"][:, 0] * 1e3, crack["path"][:, 1] * 1e3, "r-", lw=0.6, alpha=0.7)
        ax.plot(crack["fit"][:, 0] * 1e3, crack["fit"][:, 1] * 1e3, "w--", lw=0.8)
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm] (impact direction)")
    ax.set_ylabel("y [mm]")
    ax.set_title("damage at t = %.1f us (reference configuration)\nred: crack path, white dashed: "
                 "fitted line (crack angle)" % (time * 1e6), fontsize=8)
    fig.colorbar(s, ax=ax, shrink=0.6, label="damage index")
    fig.tight_layout()
    fig.savefig(out, dpi=150)
    plt.close(fig)


def read_fe(path):
    """(nodes, cells, von Mises stress per node) of one FE output file (the cells with FE
    unknowns; the cells that became PD only are not in it)."""
    with h5py.File(path, "r") as f:
        return (np.array(f["nodes"])[:, :2], np.array(f["cells"]).astype(np.int64),
                np.array(f["von_mises_stress"])[:, 0])


def fe_outline(nodes, cells):
    """The edges [(node, node)] that belong to one cell only: the outline of the FE part (the
    specimen's boundary and the edge of the PD-only zone). Nodes are matched by position: each
    MPI rank writes its own copy of the nodes on the partition boundary (so the notches, slits
    whose two faces have nodes at the same positions, are not drawn)."""
    _, index = np.unique(np.round(nodes / (1e-6 * np.ptp(nodes))).astype(np.int64), axis=0,
                         return_inverse=True)
    count = {}
    for cell in cells:
        for a, b in zip(cell, np.roll(cell, -1)):
            key = (min(index[a], index[b]), max(index[a], index[b]))
            count[key] = count.get(key, (a, b, 0))[:2] + (count.get(key, (0, 0, 0))[2] + 1,)
    return [(a, b) for a, b, n in count.values() if n == 1]


def plot_specimen(directory, series, base, out, n_panels=4):
    """The whole specimen at n_panels output times from the first with a grown PD zone to the
    last: von Mises stress of the FE field where FE unknowns remain, the damage of the particles
    on top (white: undamaged; their extent is the PD zone, PD only or blended) and the outline
    of the FE part (black; inside the particles it is the edge of the PD-only zone)."""
    fe_series = read_series(directory, "solution")
    picks = np.unique(np.linspace(0, len(series) - 1, n_panels).round().astype(int))
    fe_picks = [read_fe(fe_series[k][1]) for k in picks]
    limit = max(np.percentile(v, 99) for _, _, v in fe_picks)
    fig, axes = plt.subplots(1, len(picks), figsize=(2.6 * len(picks) + 2.2, 5.4), sharey=True,
                             layout="constrained")
    for ax, k, (fe_nodes, cells, mises) in zip(np.atleast_1d(axes), picks, fe_picks):
        time, path = series[k]
        nodes, damage = read_particles(path)
        polygons = PolyCollection(fe_nodes[cells] * 1e3, array=mises[cells].mean(axis=1),
                                  cmap="viridis", norm=Normalize(0.0, limit), edgecolors="none")
        ax.add_collection(polygons)
        dx = lattice_spacing(nodes)
        ax.scatter(nodes[:, 0] * 1e3, nodes[:, 1] * 1e3, c=damage, cmap="hot_r", vmin=0.0,
                   vmax=1.0, s=(72.0 * dx * 1e3 * 6.2 / 200.0) ** 2, marker="s", linewidths=0)
        edges = fe_outline(fe_nodes, cells)
        ax.add_collection(LineCollection(fe_nodes[np.array(edges)] * 1e3, colors="k",
                                         linewidths=0.4))
        ax.set_xlim(fe_nodes[:, 0].min() * 1e3, fe_nodes[:, 0].max() * 1e3)
        ax.set_ylim(fe_nodes[:, 1].min() * 1e3, fe_nodes[:, 1].max() * 1e3)
        ax.set_aspect("equal")
        ax.set_title("t = %.0f us, %d particles" % (time * 1e6, len(nodes)), fontsize=8)
        ax.set_xlabel("x [mm]")
    finish_specimen(fig, axes, limit, "Whole specimen: FE field where FE remains, particles (the "
                    "PD zone) with their damage,\noutline of the FE part (black)", out)


def finish_specimen(fig, axes, limit, title, out):
    """The y label, the colour bars of the FE stress (0 to limit [Pa]) and of the particles'
    damage, the title; writes the figure to out (plot_specimen(), and the 3D script's)."""
    np.atleast_1d(axes)[0].set_ylabel("y [mm]")
    fig.colorbar(plt.cm.ScalarMappable(Normalize(0.0, limit * 1e-6), "viridis"),
                 ax=axes, shrink=0.6, label="FE von Mises stress [MPa]")
    fig.colorbar(plt.cm.ScalarMappable(Normalize(0.0, 1.0), "hot_r"), ax=axes, shrink=0.6,
                 label="particle damage index")
    fig.suptitle(title, fontsize=8)
    fig.savefig(out, dpi=150)
    plt.close(fig)


def new_damage(nodes, damage, tip, dx, first_damage):
    """The damage less, within a horizon of the notches (y = +-tip[1], x <= tip[0]), the
    particle's damage in the first output that has it (kept in first_damage, by lattice point:
    pass the same dict for every output of a run). nodes may be 2D or 3D (the notches are then
    planes through the thickness: only x and y are looked at)."""
    reach = 3.015 * dx + dx  # the pre-cracks damage particles within a horizon of the notches
    near_notch = ((np.abs(np.abs(nodes[:, 1]) - tip[1]) <= reach)
                  & (nodes[:, 0] <= tip[0] + reach))
    keys = map(tuple, np.round(nodes[near_notch] / dx * 2).astype(np.int64).tolist())
    new = damage.copy()
    new[near_notch] -= np.array([first_damage.setdefault(k, d)
                                 for k, d in zip(keys, damage[near_notch])])
    return new


def crack_history(results, tip, threshold, base="particles"):
    """The cracks of every output time of a run: (series, dx, history, final) with history
    [(time, upper, lower)] (measure_crack's dicts or None; the lower crack grows from the notch
    tip mirrored at y = 0) and final = (time, nodes, damage, displacement, upper, lower) of the
    last output."""
    lower_tip = np.array([tip[0], -tip[1]])
    series = read_series(results, base)
    nodes0, _ = read_particles(series[0][1])
    dx = lattice_spacing(nodes0)
    history = []
    final = None
    first_damage = {}  # per lattice point near a notch: its damage when it first appears
    for time, path in series:
        nodes, damage, disp = read_particles(path, with_displacement=True)
        new = new_damage(nodes, damage, tip, dx, first_damage)
        upper = measure_crack(nodes, new, tip, dx, threshold, +1.0)
        lower = measure_crack(nodes, new, lower_tip, dx, threshold, -1.0)
        history.append((time, upper, lower))
        final = (time, nodes, damage, disp, upper, lower)
    return series, dx, history, final


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("results", help="directory with particles.xdmf and statistics.csv")
    parser.add_argument("--notch-tip", default="0.05,0.025", help="upper notch tip x,y [m]")
    parser.add_argument("--threshold", type=float, default=0.35, help="new-damage threshold")
    parser.add_argument("--base", default="particles", help="base name of the particle files")
    args = parser.parse_args()
    tip = np.array([float(v) for v in args.notch_tip.split(",")])

    stats = read_statistics(args.results)
    plot_energies(stats, os.path.join(args.results, "energies.png"))

    series, dx, history, final = crack_history(args.results, tip, args.threshold, args.base)

    with open(os.path.join(args.results, "crack_angle.csv"), "w") as f:
        f.write("time,angle_upper,chord_upper,length_upper,tip_x_upper,tip_y_upper,"
                "angle_lower,chord_lower,length_lower\n")
        for time, up, lo in history:
            def fmt(c, keys):
                return ",".join("nan" if c is None else "%.6g" % c[k] for k in keys)
            tips = "nan,nan" if up is None else "%.6g,%.6g" % up["tip"]
            f.write("%.6g,%s,%s,%s\n" % (time, fmt(up, ["angle", "chord", "length"]), tips,
                                        fmt(lo, ["angle", "chord", "length"])))

    t = np.array([h[0] for h in history]) * 1e6
    ang_u = np.array([np.nan if h[1] is None else h[1]["angle"] for h in history])
    ang_l = np.array([np.nan if h[2] is None else h[2]["angle"] for h in history])
    len_u = np.array([np.nan if h[1] is None else h[1]["length"] for h in history])
    fig, (ax, axl) = plt.subplots(2, 1, figsize=(6.5, 6), sharex=True)
    ax.plot(t, ang_u, "o-", label="upper crack (fit)")
    ax.plot(t, ang_l, "s--", label="lower crack (fit, mirrored)")
    ax.axhline(70.0, color="k", lw=0.8, ls=":", label="experiment, about 70 deg")
    ax.set_ylabel("crack angle [deg]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    axl.plot(t, len_u * 1e3, "o-")
    axl.set_xlabel("time [us]")
    axl.set_ylabel("upper crack path length [mm]")
    axl.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(args.results, "crack_angle.png"), dpi=120)
    plt.close(fig)

    time, nodes, damage, disp, upper, lower = final
    plot_damage(nodes, damage, disp, time, [upper, lower], os.path.join(args.results, "damage_final.png"))
    if os.path.exists(os.path.join(args.results, "solution.xdmf")):
        plot_specimen(args.results, series, args.base, os.path.join(args.results, "specimen.png"))

    print("results: %s (t_end = %.3g us, dx = %.3g mm, %d output times)"
          % (args.results, time * 1e6, dx * 1e3, len(series)))
    dissipated = stats.get("dissipated_energy", [0.])[-1]
    print("final energies [J/m]: kinetic %.6g, strain %.6g, external work %.6g, dissipated %.6g, "
          "kinetic + strain - work %.4g, kinetic + strain + dissipated - work %.3g; broken bonds %d"
          % (stats["kinetic_energy"][-1], stats["strain_energy"][-1], stats["external_work"][-1],
             dissipated, stats["energy_error"][-1] - dissipated, stats["energy_error"][-1],
             stats["broken_bonds"][-1]))
    initiated = [h[0] for h in history if h[1] is not None]
    if initiated:
        print("first output time with a grown upper crack: %.3g us" % (initiated[0] * 1e6))
    grown = [(h[0], h[1]["length"]) for h in history if h[1] is not None]
    if len(grown) >= 2:
        # Mean speed of the upper crack path from the first output with a crack to the first
        # output at which it has its final length (it stops at the boundary or runs to the end).
        t0, l0 = grown[0]
        t1, l1 = next((t, l) for t, l in grown if l >= grown[-1][1] - 1e-12)
        if t1 > t0:
            print("mean upper crack-path speed %.3g-%.3g us: %.0f m/s"
                  % (t0 * 1e6, t1 * 1e6, (l1 - l0) / (t1 - t0)))
    if lower is not None:
        print("lower crack: angle %.1f deg (chord %.1f deg), path length %.1f mm"
              % (lower["angle"], lower["chord"], lower["length"] * 1e3))
    if upper is None:
        print("upper crack: none grown from the notch tip")
        print("crack angle [deg]: nan")
        return 1
    print("upper crack: tip at (%.1f, %.1f) mm, path length %.1f mm, chord angle %.1f deg"
          % (upper["tip"][0] * 1e3, upper["tip"][1] * 1e3, upper["length"] * 1e3, upper["chord"]))
    print("crack angle [deg]: %.1f" % upper["angle"])
    return 0


if __name__ == "__main__":
    sys.exit(main())
