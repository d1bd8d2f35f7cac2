#!/usr/bin/python3
"""Cracks of the alumina quench (README.md) from the particle output of perideal-solid.

For each run folder given (run.sh writes them: <dir>/results/particles*.h5, run.log, time.log)
the particle files are read (the last one for the table, every one for the history) and their
cracks are counted:

- the lattice: every particle sits within (epsilon dx / 2) of the centre of its lattice cell, so
  its cell indices (i, j) = floor(x / dx) identify it on a grid (dx from --dx);
- a damaged particle has damage > --threshold (default 0.3, README.md "Crack measure": the two
  particle rows along an open straight crack lose about 40 % of their bonds, the rows beyond
  them 20 % and less, so 0.3 marks the crack's two faces and not its halo);
- every particle belongs to its nearest edge (ties to the long edges) of those --edges names
  (default all four sides of the particles' bounding box; a segment or a PD band names only
  the quenched sides, e.g. `--edges bottom` for quench_strength.prm, whose other sides are the
  segment's cut ends and the band's inner side); per edge, the damaged
  particles that are connected (8 neighbours on the grid) to the edge's own particle row form
  the edge's damage; the others are interior damage (a crack that starts inside);
- the depth profile: per column along the edge (one lattice column), the deepest such particle;
  a crack is a maximal run of columns whose deepest particle centre lies at least --min-depth
  deep (default one horizon, rounded up to the next particle centre: 0.875 mm at dx = 0.25 mm;
  damage shallower than the horizon is the skin the surface layer loses, not a crack the
  nonlocal model resolves); its position is its deepest column, its length that depth (normal
  to the edge, to the particle centre: plus dx/2 to the edge itself);
- spacing: the mean distance between neighbouring cracks along the long edges (bottom and top,
  those of them --edges names); the count per long edge is their mean over those edges.

Writes <out>/cracks.csv (one row per crack), <out>/history.csv (per run and output time: the
cracks per long edge, their mean and largest length, the interior clusters), the figures
<out>/fields_T<T0>.png (damage beside the temperature at the end and two intermediate times),
<out>/cracks_vs_T0.png and <out>/broken_bonds.png (with --prefix before each name), for a run
whose particles change in number (the adaptive PD region) <out>/<prefix>pd_zone.png, and prints
a table with the cost of each run (wall and CPU time and peak memory from time.log and the run's
summary) and the most particles of any output time. Coupled and adaptive runs: the cracks are in
the particles (every damaged particle is PD only), the temperature plot shows the FE heat
(solution_heat*.h5) under the particles'.
"""

import argparse
import csv
import os
import re
import sys
import xml.etree.ElementTree as ET

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def snapshots(xdmf):
    """(time, h5 file) of each grid of an XDMF time collection."""
    root = ET.parse(xdmf).getroot()
    out = []
    for grid in root.iter("Grid"):
        if grid.get("GridType") != "Uniform":
            continue
        time = float(grid.find("Time").get("Value"))
        item = grid.find("Geometry").find("DataItem").text.strip()
        out.append((time, os.path.join(os.path.dirname(xdmf), item.split(":")[0])))
    return out


def read(h5file, names):
    with h5py.File(h5file, "r") as f:
        return [np.array(f[n]) for n in names]


def on_grid(nodes, values, dx):
    """The particle values on their lattice cells (NaN where there is no particle)."""
    idx = np.floor(nodes / dx + 1e-9).astype(int)
    out = np.full((idx[:, 0].max() + 1, idx[:, 1].max() + 1), np.nan)
    out[idx[:, 0], idx[:, 1]] = values
    return out


def extent(nodes, dx):
    """The image extent [mm] of the lattice cells of on_grid()."""
    idx = np.floor(nodes / dx + 1e-9).astype(int)
    return [0, 1e3 * dx * (idx[:, 0].max() + 1), 0, 1e3 * dx * (idx[:, 1].max() + 1)]


def label(mask):
    """Connected components (8 neighbours) of a boolean grid: labels, 0 = not in the mask."""
    labels = np.zeros(mask.shape, dtype=int)
    current = 0
    nx, ny = mask.shape
    for start in zip(*np.nonzero(mask)):
        if labels[start]:
            continue
        current += 1
        labels[start] = current
        stack = [start]
        while stack:
            i, j = stack.pop()
            for a in (-1, 0, 1):
                for b in (-1, 0, 1):
                    p, q = i + a, j + b
                    if 0 <= p < nx and 0 <= q < ny and mask[p, q] and not labels[p, q]:
                        labels[p, q] = current
                        stack.append((p, q))
    return labels, current


EDGES = ["bottom", "top", "left", "right"]


def measure(nodes, damage, dx, threshold, min_depth_cells, order=EDGES):
    """Cracks per edge of one snapshot: a dict edge -> list of (position [m], length [m]), and
    the number of damaged clusters that do not reach an edge. A crack's deepest particle lies at
    least @p min_depth_cells full cells below the edge's particle row. @p order: the edges that
    are the body's (of bottom, top, left, right; the particles belong to the nearest of them)."""
    idx = np.floor(nodes / dx + 1e-9).astype(int)
    nx, ny = idx[:, 0].max() + 1, idx[:, 1].max() + 1
    grid = np.zeros((nx, ny), dtype=bool)
    present = np.zeros((nx, ny), dtype=bool)
    grid[idx[:, 0], idx[:, 1]] = damage > threshold
    present[idx[:, 0], idx[:, 1]] = True
    i, j = np.meshgrid(np.arange(nx), np.arange(ny), indexing="ij")
    # Depth (in cells) from each edge and the nearest edge (long edges win ties).
    depths = {"bottom": j, "top": ny - 1 - j, "left": i, "right": nx - 1 - i}
    stack = np.stack([depths[e] for e in order])
    nearest = np.argmin(stack, axis=0)
    result, interior = {}, 0
    for k, edge in enumerate(order):
        mine = grid & (nearest == k)
        labels, n = label(mine)
        depth = depths[edge]
        on_edge = set(np.unique(labels[mine & (depth == 0)])) - {0}
        for lab in range(1, n + 1):
            if lab not in on_edge:
                interior += 1
        connected = np.isin(labels, list(on_edge)) & mine
        # Column profile along the edge.
        along = i if edge in ("bottom", "top") else j
        ncol = nx if edge in ("bottom", "top") else ny
        profile = np.full(ncol, -1)
        for c in range(ncol):
            sel = connected & (along == c)
            if sel.any():
                profile[c] = depth[sel].max()
        cracks = []
        c = 0
        while c < ncol:
            if profile[c] >= min_depth_cells:
                start = c
                while c < ncol and profile[c] >= min_depth_cells:
                    c += 1
                run = profile[start:c]
                deepest = start + int(np.argmax(run))
                cracks.append(((deepest + 0.5) * dx, (run.max() + 0.5) * dx))
            else:
                c += 1
        result[edge] = cracks
    return result, interior


def cost(run_dir):
    wall, rss, peak, cpu = float("nan"), float("nan"), "", float("nan")
    try:
        text = open(os.path.join(run_dir, "time.log")).read()
        m = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): ([0-9:.]+)", text)
        if m:
            parts = [float(p) for p in m.group(1).split(":")]
            wall = sum(p * 60 ** (len(parts) - 1 - k) for k, p in enumerate(parts))
        m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", text)
        if m:
            rss = int(m.group(1)) / 1024.0
        cpu = sum(float(x) for x in re.findall(r"(?:User|System) time \(seconds\): ([0-9.]+)", text))
    except OSError:
        pass
    try:
        for line in open(os.path.join(run_dir, "run.log")):
            if line.startswith("Peak memory:"):
                peak = line.split(":")[1].split(",")[0].strip()
    except OSError:
        pass
    return wall, rss, peak, cpu


def fe_temperature(ax, res, time, t0):
    """The FE temperature of the heat (solution_heat*.h5 of the output time nearest @p time) as
    a colour field under the particles' image (coupled and adaptive runs); nothing without FE."""
    fe = snapshots(os.path.join(res, "solution_heat.xdmf")) if os.path.exists(
        os.path.join(res, "solution_heat.xdmf")) else []
    if not fe:
        return
    k = min(range(len(fe)), key=lambda q: abs(fe[q][0] - time))
    nodes, cells, temp = read(fe[k][1], ["nodes", "cells", "temperature"])
    if cells.size == 0:
        return
    triangles = np.concatenate([cells[:, [0, 1, 2]], cells[:, [0, 2, 3]]])
    ax.tripcolor(1e3 * nodes[:, 0], 1e3 * nodes[:, 1], triangles, temp[:, 0], cmap="coolwarm",
                 vmin=20, vmax=t0, shading="gouraud")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("runs", nargs="+", help="run folders T<T0> written by run.sh")
    ap.add_argument("--out", default=".", help="where the table and figures go")
    ap.add_argument("--dx", type=float, default=2.5e-4, help="lattice spacing [m]")
    ap.add_argument("--horizon-factor", type=float, default=3.015)
    ap.add_argument("--threshold", type=float, default=0.3, help="damage of a crack particle")
    ap.add_argument("--min-depth", type=float, default=None,
                    help="shortest crack [m] (default: one horizon)")
    ap.add_argument("--end-time", type=float, default=0.4, help="<Time stepping/End time> [s]")
    ap.add_argument("--method", default="all-PD", help="the method's name in the titles")
    ap.add_argument("--prefix", default="", help="put before the figures' file names")
    ap.add_argument("--edges", default=",".join(EDGES),
                    help="the sides of the particles' bounding box that are edges of the body, "
                    "of bottom, top, left, right (a segment or band: the quenched ones only)")
    args = ap.parse_args()
    edges = [e.strip() for e in args.edges.split(",") if e.strip()]
    if not edges or any(e not in EDGES for e in edges):
        ap.error(f"--edges takes some of {', '.join(EDGES)}, not '{args.edges}'")
    long_names = [e for e in ("bottom", "top") if e in edges]
    n_long_edges = max(1, len(long_names))
    dx = args.dx
    min_depth = args.min_depth if args.min_depth is not None else args.horizon_factor * dx
    # The deepest damaged particle of a crack sits (profile + 1/2) dx from the edge.
    min_cells = int(np.ceil(min_depth / dx - 0.5 - 1e-9))

    rows, summary, history, zone = [], [], [], []
    for run_dir in args.runs:
        m = re.match(r"T(\d+)", os.path.basename(os.path.normpath(run_dir)))
        t0 = float(m.group(1)) if m else float("nan")
        res = os.path.join(run_dir, "results")
        mech = snapshots(os.path.join(res, "particles.xdmf"))
        heat = snapshots(os.path.join(res, "particles_heat.xdmf"))
        if not mech:
            print(f"{run_dir}: no particle output", file=sys.stderr)
            continue
        # The cracks' history: count and lengths along the long edges at each output time.
        for time, h5 in mech:
            x, d = read(h5, ["nodes", "damage"])
            c, inside = measure(x, d[:, 0], dx, args.threshold, min_cells, edges)
            lens = [l for e in long_names for _, l in c[e]]
            history.append(dict(T0=t0, t_ms=1e3 * time * args.end_time, count_long_mean=
                                len(lens) / n_long_edges, mean_length_mm=1e3 * np.mean(lens) if lens else 0.,
                                max_length_mm=1e3 * max(lens) if lens else 0., interior=inside))
        nodes, damage = read(mech[-1][1], ["nodes", "damage"])
        cracks, interior = measure(nodes, damage[:, 0], dx, args.threshold, min_cells, edges)
        cracks = {e: cracks.get(e, []) for e in EDGES}
        stats = np.genfromtxt(os.path.join(res, "statistics.csv"), delimiter=",", names=True)
        broken = int(stats["broken_bonds"][-1])
        t_end = mech[-1][0] * args.end_time
        wall, rss, peak, cpu = cost(run_dir)
        # The particles (the PD zone and its halo): at the end and the most at any output time.
        counts = [(mech_t * args.end_time, read(h5, ["nodes"])[0].shape[0]) for mech_t, h5 in mech]
        zone.append((t0, counts))
        long_edges = [c for e in long_names for c in cracks[e]]
        spacings = []
        for e in long_names:
            pos = sorted(p for p, _ in cracks[e])
            spacings += list(np.diff(pos))
        lengths = np.array([l for _, l in long_edges]) if long_edges else np.zeros(0)
        n_long = int((lengths >= 0.5 * lengths.max()).sum()) if lengths.size else 0
        s = dict(T0=t0, dT=t0 - 20.0, t_end=t_end, broken=broken, interior=interior,
                 count_bottom=len(cracks["bottom"]), count_top=len(cracks["top"]),
                 count_left=len(cracks["left"]), count_right=len(cracks["right"]),
                 count_long_mean=len(long_edges) / n_long_edges,
                 spacing=float(np.mean(spacings)) if spacings else float("nan"),
                 mean_length=float(lengths.mean()) if lengths.size else 0.0,
                 max_length=float(lengths.max()) if lengths.size else 0.0,
                 n_long=n_long, n_short=int(lengths.size - n_long),
                 wall=wall, rss=rss, peak=peak, cpu=cpu,
                 particles=max(c for _, c in counts))
        summary.append(s)
        for e in edges:
            for p, l in cracks[e]:
                rows.append(dict(T0=t0, edge=e, position_mm=1e3 * p, length_mm=1e3 * l))

        # Damage beside temperature: the end and two intermediate output times.
        picks = sorted(set([len(mech) - 1, len(mech) // 3, (2 * len(mech)) // 3]))
        fig, axes = plt.subplots(len(picks), 2, figsize=(13, 1.9 * len(picks) + 0.6),
                                 squeeze=False)
        for r, k in enumerate(picks):
            x, d = read(mech[k][1], ["nodes", "damage"])
            tk = mech[k][0] * args.end_time
            hk = min(range(len(heat)), key=lambda q: abs(heat[q][0] - tk)) if heat else None
            ax = axes[r][0]
            im = ax.imshow(on_grid(x, d[:, 0], dx).T, origin="lower", cmap="inferno_r", vmin=0,
                           vmax=0.6, extent=extent(x, dx), interpolation="nearest")
            ax.set_title(f"{args.method}, T0 = {t0:.0f} C, t = {1e3 * tk:.1f} ms: damage"
                         " (white: no particles)", fontsize=9)
            fig.colorbar(im, ax=ax, fraction=0.02)
            ax = axes[r][1]
            fe_temperature(ax, res, tk, t0)
            if hk is not None:
                xh, temp = read(heat[hk][1], ["nodes", "temperature"])
                im = ax.imshow(on_grid(xh, temp[:, 0], dx).T, origin="lower", cmap="coolwarm",
                               vmin=20, vmax=t0, extent=extent(xh, dx), interpolation="nearest")
                ax.set_title(f"temperature [C] (heat output at t = {1e3 * heat[hk][0]:.1f} ms)",
                             fontsize=9)
                fig.colorbar(im, ax=ax, fraction=0.02)
        for ax in axes.flat:
            ax.set_xlabel("x [mm]", fontsize=8)
            ax.set_ylabel("y [mm]", fontsize=8)
            ax.tick_params(labelsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(args.out, f"{args.prefix}fields_T{t0:.0f}.png"), dpi=130)
        plt.close(fig)

    if not summary:
        return 1
    with open(os.path.join(args.out, "cracks.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["T0", "edge", "position_mm", "length_mm"],
                           lineterminator="\n")
        w.writeheader()
        w.writerows(rows)

    with open(os.path.join(args.out, "history.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(history[0].keys()), lineterminator="\n")
        w.writeheader()
        for h in history:
            w.writerow({k: (f"{v:.3f}" if isinstance(v, float) else v) for k, v in h.items()})
    print(f"Crack measure: damage > {args.threshold}, connected to the edge, at least "
          f"{1e3 * (min_cells + 0.5) * dx:.3f} mm deep (particle centre); lengths to the particle "
          f"centre (+{5e2 * dx:.3f}"
          " mm to the edge)")
    head = ("T0[C] t_end[ms] broken  interior  cracks(bottom,top|left,right)  per-long-edge "
            "spacing[mm] mean/max_length[mm] long/short  wall[s] CPU[s] maxRSS[MiB] peak(summary) "
            "particles(max)")
    print(head)
    for s in summary:
        print(f"{s['T0']:5.0f} {1e3 * s['t_end']:8.1f} {s['broken']:7d} {s['interior']:8d}  "
              f"{s['count_bottom']:3d},{s['count_top']:3d} | {s['count_left']:2d},"
              f"{s['count_right']:2d}              {s['count_long_mean']:6.1f}    "
              f"{1e3 * s['spacing']:8.2f}    {1e3 * s['mean_length']:6.2f}/"
              f"{1e3 * s['max_length']:5.2f}        {s['n_long']:3d}/{s['n_short']:3d}  "
              f"{s['wall']:8.0f} {s['cpu']:6.0f} {s['rss']:9.0f}  {s['peak']}  {s['particles']}")

    # Count, spacing and lengths against T0.
    t0s = np.array([s["T0"] for s in summary])
    fig, axes = plt.subplots(1, 3, figsize=(12, 3.6))
    axes[0].plot(t0s, [s["count_long_mean"] for s in summary], "o-", label="PD, per long edge")
    axes[0].set_ylabel("cracks per 50 mm edge" if edges == EDGES else
                       "cracks per long edge (of the segment)")
    axes[1].plot(t0s, [1e3 * s["spacing"] for s in summary], "o-", label="PD")
    axes[1].set_ylabel("mean crack spacing [mm]")
    axes[2].plot(t0s, [1e3 * s["mean_length"] for s in summary], "o-", label="PD mean")
    axes[2].plot(t0s, [1e3 * s["max_length"] for s in summary], "s--", label="PD max")
    axes[2].set_ylabel("crack length [mm]")
    for ax in axes:
        ax.set_xlabel("T0 [C] (water 20 C)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Alumina quench, %s (dx = %.4g mm): Jiang et al. 2012's counts not found, "
                 "see README.md" % (args.method, 1e3 * dx), fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, f"{args.prefix}cracks_vs_T0.png"), dpi=130)
    plt.close(fig)

    # Broken bonds against time: does the cracking stop before the run ends?
    fig, ax = plt.subplots(figsize=(6, 3.6))
    for run_dir, s in zip(args.runs, summary):
        st = np.genfromtxt(os.path.join(run_dir, "results", "statistics.csv"), delimiter=",",
                           names=True)
        ax.plot(1e3 * st["time"] * args.end_time, st["broken_bonds"], label=f"T0 = {s['T0']:.0f} C")
    ax.set_xlabel("t [ms]")
    ax.set_ylabel("broken bonds")
    ax.set_xscale("symlog", linthresh=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, f"{args.prefix}broken_bonds.png"), dpi=130)
    plt.close(fig)

    # The particles against time (the PD zone of an adaptive run grows; fixed otherwise).
    if any(len(set(c for _, c in counts)) > 1 for _, counts in zone):
        fig, ax = plt.subplots(figsize=(6, 3.6))
        for t0, counts in zone:
            ax.plot([1e3 * t for t, _ in counts], [c for _, c in counts], "o-",
                    label=f"T0 = {t0:.0f} C")
        ax.set_xlabel("t [ms]")
        ax.set_ylabel("particles (PD zone and its halo)")
        ax.set_title(f"{args.method}: the PD zone over time (all-PD: 8000)", fontsize=9)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(args.out, f"{args.prefix}pd_zone.png"), dpi=130)
        plt.close(fig)
    return 0


if __name__ == "__main__":
    sys.exit(main())
