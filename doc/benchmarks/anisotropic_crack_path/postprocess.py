#!/usr/bin/env python3
"""Benchmark anisotropic_crack_path: the crack deflection angle of each run against the
material orientation, with the reference directions.

usage: postprocess.py RESULTS_DIR... [--plot PREFIX] [--threshold D] [--window R0,R1]
                      [--robustness] [--skip-damage SET,SET]

Each RESULTS_DIR holds run.prm (the parameter file of the run; 'include' lines are followed),
particles.xdmf with its particles_NNNNN.h5 files, and optionally wall_time (seconds, written by
run.sh). A run's set is the name of the directory that holds RESULTS_DIR. From run.prm: the
lattice spacing dx and horizon delta, the notch (the first pre-crack, from its first point to
its tip, the second), the material axes (Orientation, z-x-z Euler angles as in ElasticMaterial),
the fracture energy ratios (1, 1, 1 if the entry is absent) and the model (`bond based`: an
isotropic PMB control, plotted at alpha = 0).

Material angle alpha: the angle from the notch direction to the material axis 3 (the fibre, the
stiff axis of the transversely isotropic solid), folded into (-90, 90].

Crack deflection angle (the last output time; coordinates in the notch frame, the notch along
+x):
  1. new damage = damage - damage at t = 0 (the pre-crack's faces start damaged);
  2. crack particles: new damage > D (0.3), not behind the notch tip by more than 2 delta;
  3. the crack is the 8-connected lattice cluster of crack particles that touches the tip
     (particles within 2 delta of it); its path is the shortest path (Dijkstra along the
     cluster, a start costing twice its distance from the tip) from the tip to the cluster
     particle farthest along the cluster, so branches and damage near the grips do not enter
     the fit;
  4. the angle is that of the least-squares line (principal axis of the centred points)
     through the path particles at distances R0 <= r <= R1 from the tip (R0 = delta, R1 =
     20 mm), measured from the notch direction towards +y, in (-90, 90]. The line is not forced
     through the tip: a crack that runs between two particle rows next to the notch line is
     damaged on one row more than on the other, which would tilt a line through the tip by
     about (dx/2)/R1.
  The near-tip angle (the same fit over delta <= r <= 5 mm: the kink), the chord angle (tip
  to the path particle nearest to r = R1) and the angle of the line through all cluster
  particles in the window (not only the path) are printed as well.

Reference directions (alpha the fibre angle, ratios r_t for a crack along the fibres, i.e. its
normal along the in-plane transverse axis, and r_f for a crack across them):
  weak plane   the direction of least fracture resistance: the fibre direction alpha when
               r_t < r_f (none with equal ratios);
  LEFM kink    the maximum over phi of G*(phi) / G_c(phi): G*(phi) = cos^4(phi/2) G, the energy
               release rate of a kink at phi from a mode-I crack tip to first order (K_I* =
               K_I cos^3(phi/2), K_II* = K_I sin(phi/2) cos^2(phi/2), the local stresses of the
               isotropic field; elastic anisotropy neglected) and G_c(phi) = G0 (r_t cos^2(phi -
               alpha) + r_f sin^2(phi - alpha)), the model's continuum interpolation for a crack
               running at phi;
  straight     the maximum over phi of cos^2(phi) / G_c(phi): the direction of a straight
               inclined crack under remote tension normal to the notch (K_I = s sqrt(pi a)
               cos^2 phi, K_II = s sqrt(pi a) sin phi cos phi, G ~ cos^2 phi) that releases the
               most energy per unit of fracture resistance.
  With equal ratios all three are 0; so is the maximum hoop stress of the anisotropic mode-I
  field for any elastic anisotropy (tau_r theta = 0 at theta = 0, where d sigma_theta theta /
  d theta = -3/2 tau_r theta vanishes).

Prints one line per run and, with --robustness, the angle for thresholds 0.2, 0.3, 0.45 and
windows R1 = 10, 15, 20, 25 mm. With --plot, PREFIX_angle.png (crack angle against alpha, one
series per set, with the reference curves of each pair of ratios) and PREFIX_damage_<set>.png
(the final damage of the runs of each set, but those of --skip-damage, with the path, the fitted
line and the fibre direction).
"""
import argparse
import heapq
import math
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from particle_series import read_particles, read_series  # noqa: E402


# ----------------------------------------------------------------------------- parameters


def expand(path):
    """The text of a parameter file with its 'include FILE' lines replaced by the files
    (relative paths resolved against the working directory, as perideal-solid reads them,
    then the including file's directory and this script's)."""
    with open(path) as f:
        text = f.read()

    def include(match):
        name = match.group(1)
        for candidate in (name, os.path.join(os.path.dirname(path), name),
                          os.path.join(os.path.dirname(os.path.abspath(__file__)), name)):
            if os.path.exists(candidate):
                return expand(candidate)
        raise SystemExit(f"postprocess.py: {path} includes {name}, which is not found")

    return re.sub(r"^\s*include\s+(\S+)\s*$", include, text, flags=re.MULTILINE)


def entry(text, name, default=None):
    """The last value of 'set NAME = value' in a parameter file."""
    values = re.findall(r"set\s+" + re.escape(name) + r"\s*=\s*([^\n#]*)", text)
    if not values:
        if default is None:
            raise SystemExit(f"postprocess.py: no entry '{name}'")
        return default
    return values[-1].strip()


def numbers(value):
    return [float(v) for v in re.split(r"[,:;\s]+", value.strip()) if v]


def euler_axes(phi, theta, psi):
    """Columns: the material axes in global coordinates, R = R_z(phi) R_x(theta) R_z(psi)
    (ElasticMaterial's z-x-z convention, degrees)."""
    def about(axis, degrees):
        c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
        r = np.eye(3)
        p, q = (axis + 1) % 3, (axis + 2) % 3
        r[p, p] = r[q, q] = c
        r[p, q], r[q, p] = -s, s
        return r
    return about(2, phi) @ about(0, theta) @ about(2, psi)


def fold(angle):
    """An undirected angle [deg] folded into (-90, 90]."""
    a = (angle + 90.0) % 180.0 - 90.0
    return 90.0 if a == -90.0 else a


# ----------------------------------------------------------------------------- references


NEAR_TIP = 0.005  # [m] the outer radius of the near-tip fit (the kink)
PHI = np.radians(np.linspace(-89.95, 89.95, 3599))


def fracture_resistance(phi, alpha, r_t, r_f):
    """G_c / G0 of a crack running at phi (radians) in a material whose fibre is at alpha."""
    return r_t * np.cos(phi - alpha) ** 2 + r_f * np.sin(phi - alpha) ** 2


def lefm_kink(alpha_deg, r_t, r_f):
    if r_t == r_f:
        return 0.0
    a = math.radians(alpha_deg)
    f = np.cos(PHI / 2) ** 4 / fracture_resistance(PHI, a, r_t, r_f)
    return math.degrees(PHI[np.argmax(f)])


def straight_inclined(alpha_deg, r_t, r_f):
    if r_t == r_f:
        return 0.0
    a = math.radians(alpha_deg)
    f = np.cos(PHI) ** 2 / fracture_resistance(PHI, a, r_t, r_f)
    return math.degrees(PHI[np.argmax(f)])


def weak_plane(alpha_deg, r_t, r_f):
    if r_t == r_f:
        return float("nan")
    return fold(alpha_deg if r_t < r_f else alpha_deg + 90.0)


# ----------------------------------------------------------------------------- results


def principal_angle(points, centred):
    """The angle [deg] of the principal axis of the points (centred, or through the origin),
    oriented away from the origin, folded into (-90, 90]."""
    p = points - points.mean(axis=0) if centred else points
    w, v = np.linalg.eigh(p.T @ p)
    d = v[:, np.argmax(w)]
    return fold(math.degrees(math.atan2(d[1], d[0])))


def measure(run, threshold, r0, r1):
    """The crack from the notch tip of @p run: dict(angle, near, through_tip, cluster, chord,
    length, reach, path, line), angles from the notch direction, or None when no crack has
    grown beyond r0."""
    nodes, dx, delta, tip = run["nodes"], run["dx"], run["delta"], run["tip"]
    # Coordinates in the notch frame: origin at the tip, x along the notch's direction.
    c, s = math.cos(math.radians(run["notch"])), math.sin(math.radians(run["notch"]))
    turn = np.array([[c, -s], [s, c]])
    rel = (nodes - tip) @ turn
    idx = np.nonzero((run["new_damage"] > threshold) & (rel[:, 0] >= -2.0 * delta))[0]
    if idx.size == 0:
        return None
    pts = rel[idx]
    # Lattice indices from the lowest particle (positions relative to the tip would sit at
    # half spacings, where rounding goes to the even integer).
    ij = np.round((nodes[idx] - nodes.min(axis=0)) / dx).astype(int)
    lookup = {tuple(k): n for n, k in enumerate(ij)}
    dist = np.hypot(pts[:, 0], pts[:, 1])
    seeds = np.nonzero(dist <= 2.0 * delta)[0]
    if seeds.size == 0:
        return None
    # Dijkstra from the particles near the tip; a start costs twice its distance from the tip,
    # so that the path starts next to the tip rather than anywhere within 2 delta of it.
    best = np.full(len(pts), np.inf)
    prev = np.full(len(pts), -1)
    heap = [(2.0 * dist[s], s) for s in seeds]
    for d, s in heap:
        best[s] = d
    heapq.heapify(heap)
    steps = [(a, b) for a in (-1, 0, 1) for b in (-1, 0, 1) if (a, b) != (0, 0)]
    while heap:
        d, k = heapq.heappop(heap)
        if d > best[k]:
            continue
        for a, b in steps:
            m = lookup.get((ij[k][0] + a, ij[k][1] + b))
            if m is None:
                continue
            nd = d + dx * math.hypot(a, b)
            if nd < best[m]:
                best[m], prev[m] = nd, k
                heapq.heappush(heap, (nd, m))
    reached = np.isfinite(best)
    end = int(np.argmax(np.where(reached, best, -1.0)))
    path = []
    k = end
    while k >= 0:
        path.append(k)
        k = prev[k]
    path = np.array(path[::-1])
    in_window = path[(dist[path] >= r0) & (dist[path] <= r1)]
    if in_window.size < 3:
        return None
    window_pts = pts[in_window]
    cluster = np.nonzero(reached & (dist >= r0) & (dist <= r1))[0]
    chord_at = in_window[np.argmin(np.abs(dist[in_window] - r1))]
    angle = principal_angle(window_pts, centred=True)
    near = path[(dist[path] >= r0) & (dist[path] <= max(r0, NEAR_TIP))]
    near_angle = principal_angle(pts[near], centred=True) if near.size >= 3 else float("nan")
    # The fitted line for the plots: through the centroid, from r0 to r1 along the path.
    centre = window_pts.mean(axis=0)
    direction = np.array([math.cos(math.radians(angle)), math.sin(math.radians(angle))])
    if direction @ (window_pts[-1] - window_pts[0]) < 0:
        direction = -direction
    t = (window_pts - centre) @ direction
    line = np.array([centre + t.min() * direction, centre + t.max() * direction])
    return {
        "angle": angle,
        "near": near_angle,
        "through_tip": principal_angle(window_pts, centred=False),
        "cluster": principal_angle(pts[cluster], centred=True),
        "chord": fold(math.degrees(math.atan2(pts[chord_at][1], pts[chord_at][0]))),
        "length": float(best[end] - best[path[0]] + dist[path[0]]),
        "reach": float(dist[in_window].max()),
        "path": nodes[idx][path],
        "line": line @ turn.T + tip,
    }


def read_run(directory, threshold, r0, r1):
    prm = expand(os.path.join(directory, "run.prm"))
    dx = float(entry(prm, "Lattice spacing"))
    delta = float(entry(prm, "Horizon factor")) * dx
    # The notch: the first pre-crack, from its first point to its tip (the second).
    crack = numbers(entry(prm, "Cracks"))
    start, tip = np.array(crack[0:2]), np.array(crack[2:4])
    notch = math.degrees(math.atan2(tip[1] - start[1], tip[0] - start[0]))
    perturbation = float(entry(prm, "Lattice perturbation", "0"))
    seed = int(entry(prm, "Perturbation seed", "1"))
    pmb = entry(prm, "Model") == "bond based"
    phi, theta, psi = numbers(entry(prm, "Orientation"))
    axes = euler_axes(phi, theta, psi)
    ratios = numbers(entry(prm, "Fracture energy ratios", "1, 1, 1"))
    # The axes in the plane (z component 0) and their ratios; alpha is the angle of axis 3.
    in_plane = [a for a in range(3) if abs(axes[2, a]) < 1e-9]
    alpha = fold(round(math.degrees(math.atan2(axes[1, 2], axes[0, 2])) - notch, 6))
    if 2 not in in_plane:
        raise SystemExit(f"postprocess.py: {directory}: material axis 3 is not in the plane")
    transverse = [a for a in in_plane if a != 2][0]
    r_f, r_t = ratios[2], ratios[transverse]
    if pmb:
        # Isotropic PMB (a control): no material angle, plotted at alpha = 0.
        alpha, r_f, r_t = 0.0, 1.0, 1.0
    series = read_series(directory)
    nodes0, damage0 = read_particles(series[0][1])
    nodes, damage = read_particles(series[-1][1])
    assert np.allclose(nodes, nodes0), "particle sets differ between output files"
    wall = None
    if os.path.exists(os.path.join(directory, "wall_time")):
        with open(os.path.join(directory, "wall_time")) as f:
            wall = float(f.read().split()[0])
    run = {
        "name": "/".join(directory.rstrip("/").split("/")[-2:]), "dir": directory, "pmb": pmb,
        "set": os.path.basename(os.path.dirname(os.path.abspath(directory))), "dx": dx,
        "delta": delta, "tip": tip, "notch": notch, "alpha": alpha, "r_t": r_t, "r_f": r_f, "ratios": ratios,
        "time": series[-1][0], "nodes": nodes, "new_damage": damage - damage0,
        "damage": damage, "wall": wall, "n_particles": len(nodes),
        "perturbation": perturbation, "seed": seed,
    }
    run["crack"] = measure(run, threshold, r0 if r0 is not None else delta, r1)
    return run


def horizon_factor(run):
    return round(run["delta"] / run["dx"], 3)


def set_label(run):
    """What a set of runs is: the fracture energy, dx, delta, the grips and the plate's turn
    against the lattice (from the set's name: run.sh's _clamped and _rotBETA)."""
    fracture = ("isotropic G_c" if run["r_t"] == run["r_f"] else
                f"G_c {run['r_t']:g} (along fibres) : {run['r_f']:g} (across)")
    if run["pmb"]:
        fracture = "isotropic PMB (bond based), no material angle"
    m = horizon_factor(run)
    label = f"{fracture}, dx = {run['dx'] * 1e3:g} mm"
    if m != 3.015:
        label += f", delta = {m:g} dx"
    if abs(run["notch"]) > 1e-9:
        label += f", plate turned {run['notch']:.0f} deg (grips clamped)"
    elif "clamped" in run["set"]:
        label += ", grips clamped"
    if "continuum" in run["set"]:
        label += ", continuum calibration"
    if "_fit" in run["set"]:
        label += ", stiffness fit"
    if run["perturbation"] > 0:
        label += f", perturbed (eps = {run['perturbation']:g})"
    return label


def set_key(run):
    """The series of a run in the angle plot: the directory that holds the run's directory,
    without run.sh's _sSEED, so that the seeds of a perturbed lattice form one series (their
    mean, with the range as an error bar)."""
    return re.sub(r"_s[0-9]+(?=_|$)", "", run["set"])


# ----------------------------------------------------------------------------- output


def plot_angles(runs, prefix, skip_damage=()):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    n_series = len({set_key(r) for r in runs})
    # Many series: the legend goes below the axes, where it hides no data.
    below = n_series > 5
    fig, ax = plt.subplots(figsize=(8, 5.6 + (0.16 * (n_series + 3) if below else 0.)))
    sets = {}
    for r in runs:
        sets.setdefault(set_key(r), []).append(r)
    markers = ["o", "s", "^", "v", "D", "x", "P", "*"]
    alphas = np.linspace(0.0, 90.0, 181)
    drawn = set()
    def order_key(item):
        r = item[1][0]
        return (r["r_t"] == r["r_f"], r["r_f"], -r["dx"], horizon_factor(r), item[0])
    order = sorted(sets.items(), key=order_key)
    for k, (key, members) in enumerate(order):
        members.sort(key=lambda r: r["alpha"])
        style = markers[k % len(markers)] + ("-" if members[0]["r_t"] != members[0]["r_f"] else ":")
        by_alpha = {}
        for r in members:
            by_alpha.setdefault(r["alpha"], []).append(r["crack"]["angle"] if r["crack"] else np.nan)
        a = sorted(by_alpha)
        y = [np.nanmean(by_alpha[x]) if np.isfinite(by_alpha[x]).any() else np.nan for x in a]
        n_seeds = max(len(v) for v in by_alpha.values())
        label = "PD: " + set_label(members[0])
        if n_seeds > 1:
            label += f", {n_seeds} seeds"
            low = [y[i] - np.nanmin(by_alpha[x]) for i, x in enumerate(a)]
            high = [np.nanmax(by_alpha[x]) - y[i] for i, x in enumerate(a)]
            ax.errorbar(a, y, yerr=[low, high], fmt=style, lw=1, ms=5, capsize=3, label=label)
        else:
            ax.plot(a, y, style, lw=1, ms=5, label=label)
        r_t, r_f = members[0]["r_t"], members[0]["r_f"]
        if r_t != r_f and (r_t, r_f) not in drawn:
            drawn.add((r_t, r_f))
            pairs = {(x[0]["r_t"], x[0]["r_f"]) for x in sets.values() if x[0]["r_t"] != x[0]["r_f"]}
            suffix = f" ({r_t:g} : {r_f:g})" if len(pairs) > 1 else ""
            weak = [weak_plane(x, r_t, r_f) for x in alphas[:-1]] + [np.nan]
            kink = [lefm_kink(x, r_t, r_f) for x in alphas]
            straight = [straight_inclined(x, r_t, r_f) for x in alphas]
            if len(drawn) == 1:
                ax.plot(alphas, weak, "k:", lw=1.2, label="weak plane (fibre direction)")
            grey = ["0.25", "0.6", "0.8"][min(len(drawn) - 1, 2)]
            ax.plot(alphas, kink, "--", color=grey, lw=1,
                    label="LEFM kink: max cos^4(phi/2)/G_c(phi)" + suffix)
            ax.plot(alphas, straight, "-.", color=grey, lw=1,
                    label="LEFM straight inclined crack: max cos^2(phi)/G_c(phi)" + suffix)
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.set_xlabel("material angle alpha: fibre (stiff axis) from the notch line [deg]")
    ax.set_ylabel("crack angle from the notch line [deg] (fit over delta <= r <= 20 mm)")
    ax.set_xticks(range(0, 91, 15))
    ax.set_xlim(-3, 93)
    ax.set_ylim(-35, 95)
    ax.grid(alpha=0.3)
    if below:
        ax.legend(fontsize=6.5, loc="upper left", bbox_to_anchor=(0.0, -0.1))
    else:
        ax.legend(fontsize=6.5, loc="upper left")
    ax.set_title("Edge-notched plate under remote mode I, anisotropic bond-based PD:\n"
                 "crack angle against the material orientation", fontsize=9)
    fig.tight_layout()
    fig.savefig(f"{prefix}_angle.png", dpi=110)
    plt.close(fig)

    by_set = {}
    for r in runs:
        by_set.setdefault(r["set"], []).append(r)
    for key, members in by_set.items():
        if key in skip_damage:
            continue
        members.sort(key=lambda r: r["alpha"])
        n = len(members)
        cols = min(4, n)
        rows = (n + cols - 1) // cols
        fig, axs = plt.subplots(rows, cols, figsize=(max(6.5, 3.1 * cols), 3.1 * rows + 0.4),
                                squeeze=False)
        for ax in axs.flat[n:]:
            ax.axis("off")
        for ax, r in zip(axs.flat, members):
            nodes, dx = r["nodes"], r["dx"]
            lo = nodes.min(axis=0)
            ij = np.round((nodes - lo) / dx).astype(int)
            image = np.full(ij.max(axis=0) + 1, np.nan)
            image[ij[:, 0], ij[:, 1]] = r["damage"]
            extent = [(lo[0] - dx / 2) * 1e3, (lo[0] + (image.shape[0] - 0.5) * dx) * 1e3,
                      (lo[1] - dx / 2) * 1e3, (lo[1] + (image.shape[1] - 0.5) * dx) * 1e3]
            ax.imshow(image.T, origin="lower", extent=extent, cmap="viridis", vmin=0, vmax=1,
                      interpolation="nearest")
            c = r["crack"]
            if c is not None:
                ax.plot(c["path"][:, 0] * 1e3, c["path"][:, 1] * 1e3, "r-", lw=0.5, alpha=0.8)
                ax.plot(c["line"][:, 0] * 1e3, c["line"][:, 1] * 1e3, "w--", lw=1.0)
            # The fibre direction from the notch tip.
            t = r["tip"] * 1e3
            a = math.radians(r["alpha"] + r["notch"])
            ax.plot([t[0], t[0] + 12 * math.cos(a)], [t[1], t[1] + 12 * math.sin(a)], "m-", lw=1)
            ax.set_title(f"alpha = {r['alpha']:g} deg: "
                         + (f"{c['angle']:.1f} deg" if c else "no crack"), fontsize=8)
            ax.tick_params(labelsize=6)
        fig.suptitle("damage, " + set_label(members[0]) + "\nred: crack path, white dashed: "
                     "fitted line, magenta: fibre direction", fontsize=8)
        fig.tight_layout()
        fig.savefig(f"{prefix}_damage_{key}.png", dpi=90)
        plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("results", nargs="+")
    parser.add_argument("--plot", metavar="PREFIX")
    parser.add_argument("--threshold", type=float, default=0.3)
    parser.add_argument("--window", default=None,
                        help="R0,R1 [m]: the distances from the tip of the fitted path "
                        "particles (default: delta, 0.02)")
    parser.add_argument("--robustness", action="store_true")
    parser.add_argument("--skip-damage", default="",
                        help="SET,SET: sets whose damage figure is not drawn")
    args = parser.parse_args()
    r0, r1 = (None, 0.02) if args.window is None else tuple(float(v) for v in args.window.split(","))
    runs = [read_run(d, args.threshold, r0, r1) for d in args.results]
    runs.sort(key=lambda r: (r["r_t"] == r["r_f"], r["r_f"], -r["dx"], horizon_factor(r),
                             r["alpha"]))
    print(f"{'run':<26} {'dx':>5} {'alpha':>6} {'ratios':>9} {'angle':>7} {'near':>7} "
          f"{'tip fit':>7} {'cluster':>7} {'chord':>7} {'weak':>6} {'kink':>6} {'strt':>6} "
          f"{'length':>7} {'wall':>6}")
    print(f"{'':<26} {'[mm]':>5} {'[deg]':>6} {'t : f':>9} {'[deg]':>7} {'[deg]':>7} "
          f"{'[deg]':>7} {'[deg]':>7} {'[deg]':>7} {'[deg]':>6} {'[deg]':>6} {'[deg]':>6} "
          f"{'[mm]':>7} {'[s]':>6}")
    for r in runs:
        c = r["crack"]
        f = (lambda k: f"{c[k]:7.1f}") if c else (lambda k: f"{'-':>7}")
        wall = f"{r['wall']:6.1f}" if r["wall"] is not None else f"{'-':>6}"
        print(f"{r['name']:<26} {r['dx'] * 1e3:5.2f} {r['alpha']:6.1f} "
              f"{r['r_t']:4g}:{r['r_f']:<4g} {f('angle')} {f('near')} {f('through_tip')} {f('cluster')} "
              f"{f('chord')} {weak_plane(r['alpha'], r['r_t'], r['r_f']):6.1f} "
              f"{lefm_kink(r['alpha'], r['r_t'], r['r_f']):6.1f} "
              f"{straight_inclined(r['alpha'], r['r_t'], r['r_f']):6.1f} "
              f"{(c['length'] * 1e3 if c else 0):7.1f} {wall}")
    if args.robustness:
        thresholds = [0.2, 0.3, 0.45]
        windows = [0.010, 0.015, 0.020, 0.025]
        print("robustness: angle [deg] for damage thresholds (columns D) and fit windows "
              "delta <= r <= R1 (R1 in mm)")
        head = " ".join(f"D{d:g}" .rjust(6) for d in thresholds) + " " + \
            " ".join(f"R{w * 1e3:g}".rjust(6) for w in windows)
        print(f"{'run':<26} {head}  spread")
        for r in runs:
            values = []
            for d in thresholds:
                c = measure(r, d, r["delta"], r1)
                values.append(c["angle"] if c else np.nan)
            for w in windows:
                c = measure(r, args.threshold, r["delta"], w)
                values.append(c["angle"] if c else np.nan)
            spread = np.nanmax(values) - np.nanmin(values)
            print(f"{r['name']:<26} " + " ".join(f"{v:6.1f}" for v in values) + f"  {spread:6.1f}")
    if args.plot:
        plot_angles(runs, args.plot, [k for k in args.skip_damage.split(",") if k])


if __name__ == "__main__":
    main()
