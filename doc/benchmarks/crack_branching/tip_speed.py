#!/usr/bin/env python3
"""Post-processing of the crack-branching benchmark: crack-tip path length and speed against
time, the branch point, and a picture of the damage.

Usage: tip_speed.py RESULTS_DIR [RESULTS_DIR ...] [--horizon-factor M] [--threshold D]
                    [--labels A,B,...] [--compare OUT.png]

Reads RESULTS_DIR/particles.xdmf (the particle HDF5 files written by perideal-solid: /nodes =
reference positions, /damage) and writes into RESULTS_DIR:
  damage.png       damage index at the last output (reference configuration) with the two
                   crack paths (red) and the branch point (white circle);
  tip_speed.png    path length of the crack and crack-tip speed against time, with the Rayleigh
                   speed c_R of the model (PMB in plane stress: nu = 1/3) and 0.6 c_R;
  tip_speed.csv    time [s], path length [m] of the upper and lower crack, tip x, y [m] of both,
                   speed [m/s] of the longer one (slope of the least-squares line through
                   five consecutive outputs, given at the middle one).
With several RESULTS_DIR and --compare OUT.png, also one plot of the tip speeds of all runs.
For each run it prints the summary lines; the LAST line is "branch point x [mm]: <value>"
(of the last RESULTS_DIR, the branch point at the last output; "none" if the crack did not
branch). The first branching (the first output at which the two paths part, definition 4) is
printed too: where a branch arrests and the crack branches again later, the two differ.

Definitions (chosen so that they do not depend on the pre-cracked notch faces or on short side
branches):
  1. new damage = damage(t), less, within a horizon of the notch, the particle's damage in the
     first output that has it (the notch faces start with a damage index of about 0.3 that is
     not crack growth);
  2. crack particles: new damage > threshold (0.35) and x >= x_tip - 3 dx;
  3. the crack is the 8-connected lattice cluster of crack particles that touches the notch tip
     (a particle within 2 horizons of it); path lengths are measured from the notch tip along
     the cluster (Dijkstra); the upper (lower) crack tip is the cluster particle with y > 0
     (y < 0) of the largest path length, and its crack path the shortest path to it;
  4. the branch point is the last point of the upper path that lies within one horizon of the
     lower path (where the two paths part), its x the branching position; the crack has
     branched when both tips lie more than 2 horizons beyond it (a single crack that runs off
     the notch line has particles on both sides of y = 0 too, but its two paths do not part);
  5. the tip speed is the slope of the larger path length against time, a least-squares line
     through five consecutive outputs that all have a crack (a mean over 4 output intervals,
     about 4 us; a single interval gives steps of dx / interval from the lattice).
"""
import argparse
import csv
import heapq
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from particle_series import read_particles, read_series  # noqa: E402

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

NOTCH_TIP = (0.05, 0.0)
E, NU, RHO = 72e9, 1.0 / 3.0, 2440.0


def rayleigh_speed():
    """c_R of plane stress with E, nu = 1/3 (the PMB's), rho: the root of the Rayleigh equation
    (2 - x^2)^2 = 4 sqrt(1 - x^2) sqrt(1 - x^2 c_s^2/c_p^2), x = c/c_s, by bisection."""
    mu = E / (2 * (1 + NU))
    cs = math.sqrt(mu / RHO)
    cp = math.sqrt(E / (RHO * (1 - NU * NU)))

    def f(x):
        return ((2 - x * x) ** 2
                - 4 * math.sqrt(1 - x * x) * math.sqrt(1 - x * x * cs ** 2 / cp ** 2))

    lo, hi = 0.5, 0.9999
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if f(lo) * f(mid) <= 0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi) * cs, cs, cp


def lattice_spacing(nodes):
    """dx of the particles: the smallest gap between the distinct x of a regular lattice; for a
    perturbed lattice (Discretization/Lattice perturbation; all-PD runs only) the square root
    of the plate's area per particle."""
    xs = np.unique(np.round(nodes[:, 0], 12))
    if len(xs) < len(nodes) / 4:
        return float(np.min(np.diff(xs)))
    return math.sqrt(0.1 * 0.04 / len(nodes))


def keys(nodes, dx):
    return [tuple(k) for k in np.round(nodes / dx * 2.0).astype(np.int64)]


def measure(nodes, new_damage, dx, horizon, threshold):
    """The two crack paths in one output: dict(upper, lower) with (length, tip, path) each, or
    None entries where no crack has grown."""
    x = nodes[:, 0] - NOTCH_TIP[0]
    y = nodes[:, 1] - NOTCH_TIP[1]
    idx = np.nonzero((new_damage > threshold) & (x >= -3.0 * dx))[0]
    out = dict(upper=None, lower=None)
    if idx.size == 0:
        return out
    pts = np.column_stack((x[idx], y[idx]))
    ij = np.round(pts / dx * 2.0).astype(np.int64)  # half-cell units
    lookup = {(a, b): k for k, (a, b) in enumerate(map(tuple, ij))}
    dist_tip = np.hypot(pts[:, 0], pts[:, 1])
    seeds = np.nonzero(dist_tip <= 2.0 * horizon + 1e-12)[0]
    if seeds.size == 0:
        return out
    best = np.full(len(pts), np.inf)
    prev = np.full(len(pts), -1)
    heap = [(dist_tip[s], int(s)) for s in seeds]
    for d, s in heap:
        best[s] = d
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
    for name, side in (("upper", pts[:, 1] > 0), ("lower", pts[:, 1] < 0)):
        cand = reached & side
        if not cand.any():
            continue
        end = int(np.argmax(np.where(cand, best, -1.0)))
        if np.hypot(*pts[end]) < 2.0 * horizon:
            continue  # only the damage around the notch tip: no crack yet
        path = []
        k = end
        while k >= 0:
            path.append(k)
            k = prev[k]
        p = pts[path[::-1]] + np.array(NOTCH_TIP)
        out[name] = dict(length=float(best[end]), tip=p[-1], path=p)
    return out


def branch_point(cracks, horizon):
    """x, y of the branch point, or None if the crack has not branched (definition 4)."""
    up, lo = cracks["upper"], cracks["lower"]
    if up is None or lo is None:
        return None
    last = None
    for p in up["path"]:
        if np.min(np.hypot(*(lo["path"] - p).T)) <= horizon:
            last = p
    if last is None:
        return None
    if min(np.hypot(*(up["tip"] - last)), np.hypot(*(lo["tip"] - last))) <= 2 * horizon:
        return None  # one crack (its two faces), or a branch not yet 2 horizons long
    return last


def analyse(directory, horizon_factor, threshold):
    series = read_series(directory)
    first = {}
    rows = []
    final = None
    for time, path in series:
        nodes, damage = read_particles(path)
        dx = lattice_spacing(nodes)
        horizon = horizon_factor * dx
        k = keys(nodes, dx)
        near_notch = (nodes[:, 0] <= NOTCH_TIP[0] + horizon) & (np.abs(nodes[:, 1]) <= horizon)
        base = np.zeros(len(nodes))
        for n in np.nonzero(near_notch)[0]:
            base[n] = first.setdefault(k[n], damage[n])
        cracks = measure(nodes, damage - base, dx, horizon, threshold)
        rows.append((time, cracks))
        final = (time, nodes, damage, cracks, dx, horizon)
    return rows, final


def write_csv(rows, out):
    speeds = []
    with open(out, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["time", "length_upper", "length_lower", "tip_x_upper", "tip_y_upper",
                    "tip_x_lower", "tip_y_lower", "speed"])
        t = np.array([time for time, _ in rows])
        length = np.array([max(c["upper"]["length"] if c["upper"] else 0.0,
                               c["lower"]["length"] if c["lower"] else 0.0) for _, c in rows])
        for k, (time, c) in enumerate(rows):
            # Slope of the least-squares line through the outputs k - 2 ... k + 2 that all have
            # a crack (the path length grows in lattice steps: a difference of two outputs
            # jumps by dx / interval).
            window = slice(max(k - 2, 0), min(k + 3, len(rows)))
            speed = np.nan
            if k >= 2 and k + 2 < len(rows) and np.all(length[window] > 0):
                speed = np.polyfit(t[window], length[window], 1)[0]
            speeds.append((time, length[k], speed))
            lu = c["upper"]["length"] if c["upper"] else 0.0
            ll = c["lower"]["length"] if c["lower"] else 0.0
            tu = c["upper"]["tip"] if c["upper"] else (np.nan, np.nan)
            tl = c["lower"]["tip"] if c["lower"] else (np.nan, np.nan)
            w.writerow(["%.6e" % v for v in (time, lu, ll, tu[0], tu[1], tl[0], tl[1], speed)])
    return np.array(speeds)


def plot_damage(final, bp, out, title):
    time, nodes, damage, cracks, dx, _ = final
    lo = (np.floor(nodes.min(axis=0) / dx) + 0.5) * dx  # the lattice's first cell centre
    ij = np.round((nodes - lo) / dx).astype(int)
    image = np.full(ij.max(axis=0) + 1, np.nan)
    image[ij[:, 0], ij[:, 1]] = damage
    extent = [(lo[0] - dx / 2) * 1e3, (lo[0] + (image.shape[0] - 0.5) * dx) * 1e3,
              (lo[1] - dx / 2) * 1e3, (lo[1] + (image.shape[1] - 0.5) * dx) * 1e3]
    fig, ax = plt.subplots(figsize=(8, 3.8))
    s = ax.imshow(image.T, origin="lower", extent=extent, cmap="viridis", vmin=0, vmax=1,
                  interpolation="nearest")
    for c in (cracks["upper"], cracks["lower"]):
        if c is not None:
            ax.plot(c["path"][:, 0] * 1e3, c["path"][:, 1] * 1e3, "r-", lw=0.6, alpha=0.8)
    if bp is not None:
        ax.plot(bp[0] * 1e3, bp[1] * 1e3, "wo", mfc="none", ms=8)
    ax.set_xlim(0, 100)
    ax.set_ylim(-20, 20)
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_title("%sdamage at t = %.1f us (red: crack paths, circle: branch point)"
                 % (title, time * 1e6), fontsize=9)
    fig.colorbar(s, ax=ax, shrink=0.8, label="damage index")
    fig.tight_layout()
    fig.savefig(out, dpi=150)
    plt.close(fig)


def plot_speed(runs, c_r, out):
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(6.5, 6), sharex=True)
    for label, speeds, t_branch in runs:
        t = speeds[:, 0] * 1e6
        line, = a1.plot(t, speeds[:, 1] * 1e3, "-", label=label)
        a2.plot(t, speeds[:, 2], ".-", color=line.get_color(), label=label)
        if t_branch is not None:
            a2.axvline(t_branch * 1e6, color=line.get_color(), ls=":", lw=0.8)
    a2.axhline(c_r, color="k", ls="--", lw=0.8, label="c_R = %.0f m/s" % c_r)
    a2.axhline(0.6 * c_r, color="gray", ls=":", lw=0.8, label="0.6 c_R")
    a1.set_ylabel("crack path length [mm]")
    a2.set_ylabel("crack-tip speed [m/s]")
    a2.set_xlabel("t [us]")
    a2.set_ylim(0, 1.1 * c_r)
    a1.legend(fontsize=7)
    a2.legend(fontsize=7, loc="lower right")
    a1.set_title("crack path length and tip speed (dotted: first output with two branches)",
                 fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=150)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("results", nargs="+")
    ap.add_argument("--horizon-factor", type=float, default=4.0)
    ap.add_argument("--threshold", type=float, default=0.35)
    ap.add_argument("--labels", default="")
    ap.add_argument("--compare", default="")
    args = ap.parse_args()
    labels = args.labels.split(",") if args.labels else [os.path.basename(os.path.normpath(d))
                                                          for d in args.results]
    c_r, c_s, c_p = rayleigh_speed()
    print("model wave speeds (plane stress, nu = 1/3): c_p = %.0f m/s, c_s = %.0f m/s, "
          "c_R = %.0f m/s" % (c_p, c_s, c_r))
    runs = []
    last_line = "branch point x [mm]: none"
    for directory, label in zip(args.results, labels):
        rows, final = analyse(directory, args.horizon_factor, args.threshold)
        speeds = write_csv(rows, os.path.join(directory, "tip_speed.csv"))
        t_branch, first_bp = None, None
        for time, c in rows:
            first_bp = branch_point(c, final[5])
            if first_bp is not None:
                t_branch = time
                break
        bp = branch_point(final[3], final[5])
        moving = speeds[speeds[:, 1] > 0]
        start = moving[0, 0] if len(moving) else float("nan")
        vmax = float(np.nanmax(speeds[:, 2])) if np.isfinite(speeds[:, 2]).any() else 0.0
        pre = speeds[(speeds[:, 0] <= t_branch)] if t_branch is not None else speeds
        vpre = float(np.nanmax(pre[:, 2])) if np.isfinite(pre[:, 2]).any() else 0.0
        tips = [final[3][s]["tip"] for s in ("upper", "lower") if final[3][s] is not None]
        print("%s: first output with a crack longer than 2 horizons %.2f us; max tip speed "
              "%.0f m/s (%.2f c_R), before branching %.0f m/s (%.2f c_R)"
              % (label, start * 1e6, vmax, vmax / c_r, vpre, vpre / c_r))
        print("%s: tips at t = %.1f us: %s" % (label, final[0] * 1e6, "; ".join(
            "(%.1f, %.1f) mm" % (t[0] * 1e3, t[1] * 1e3) for t in tips)))
        if first_bp is not None:
            print("%s: first branching at the output of %.1f us at (%.1f, %.1f) mm"
                  % (label, t_branch * 1e6, first_bp[0] * 1e3, first_bp[1] * 1e3))
        if bp is not None:
            print("%s: branch point at the end (%.1f, %.1f) mm"
                  % (label, bp[0] * 1e3, bp[1] * 1e3))
            last_line = "branch point x [mm]: %.1f" % (bp[0] * 1e3)
        else:
            print("%s: no branching" % label)
            last_line = "branch point x [mm]: none"
        plot_damage(final, bp, os.path.join(directory, "damage.png"), label + ": ")
        plot_speed([(label, speeds, t_branch)], c_r, os.path.join(directory, "tip_speed.png"))
        runs.append((label, speeds, t_branch))
    if args.compare:
        plot_speed(runs, c_r, args.compare)
    print(last_line)


if __name__ == "__main__":
    main()
