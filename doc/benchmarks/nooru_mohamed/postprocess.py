#!/usr/bin/env python3
"""Nooru-Mohamed benchmark (load path 4b): the curves, crack paths and checks of the all-PD and
coupled runs.

Usage: postprocess.py RESULTS_DIR [--plot PREFIX]
  RESULTS_DIR holds full_pd/ and coupled/ (each with statistics.csv and particles.xdmf).

Measures (full_pd.prm):
  - normal displacement: u_y(133 mm) - u_y(67 mm) of the edge particles, averaged over the left
    and right sides (probes 1-2 and 3-4); lateral displacement: the same for u_x;
  - normal force: the reaction of the top platen (statistics column reaction_top_y); lateral
    force: P_s(t) of the parameter files (10 kN, ramped over the first 0.4 ms);
  - crack particles: damage >= DAMAGE in the last output.
Checks:
  - both cracks start at the notch tips: crack particles within one horizon of each tip;
  - point symmetry about the centre: the largest distance from a crack particle's image under
    x -> 200 mm - x, y -> 200 mm - y to the nearest crack particle (Hausdorff), <= one dx;
  - the normal force peaks and softens: the last value below SOFTENED of the peak;
  - coupled against all-PD: peak normal force and the distance between the crack sets.
"""
import csv
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from particle_series import read_particles, read_series  # noqa: E402

DX, DELTA, SIZE = 0.002, 0.006, 0.2
TIPS = ((0.025, 0.1), (0.175, 0.1))
DAMAGE = 0.3
SOFTENED = 0.8
SHEAR_FORCE, SHEAR_RAMP = 1e4, 4e-4  # P_s [N] applied over [0, SHEAR_RAMP] [s] (full_pd.prm)


def read_run(directory):
    """Statistics columns and the final crack particles of one run."""
    with open(os.path.join(directory, "statistics.csv")) as f:
        rows = list(csv.DictReader(f))
    col = {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}
    run = {
        "t": col["time"],
        "normal_force": col["reaction_top_y"],
        "lateral_force": SHEAR_FORCE * np.minimum(1., col["time"] / SHEAR_RAMP),
        "normal": 0.5 * (col["probe2_y"] - col["probe1_y"] + col["probe4_y"] - col["probe3_y"]),
        "lateral": 0.5 * (col["probe2_x"] - col["probe1_x"] + col["probe4_x"] - col["probe3_x"]),
        "dissipated": col["dissipated_energy"],
    }
    series = read_series(directory)
    nodes, damage = read_particles(series[-1][1])
    run["nodes"], run["damage"] = nodes, damage
    run["crack"] = nodes[damage >= DAMAGE]
    run["series"] = series
    return run


def nearest(points, to):
    """Distance from each of @p points to the nearest of @p to."""
    if len(points) == 0 or len(to) == 0:
        return np.array([np.inf])
    d = np.sqrt(((points[:, None, :] - to[None, :, :]) ** 2).sum(axis=2))
    return d.min(axis=1)


def checks(name, run):
    crack = run["crack"]
    tips = [float(nearest(np.array([tip]), crack)[0]) for tip in TIPS]
    mirror = np.array([SIZE, SIZE]) - crack
    symmetry = float(max(nearest(mirror, crack).max(), nearest(crack, mirror).max()))
    force = run["normal_force"]
    peak_at = int(np.argmax(force))
    result = {
        "tips": tips,
        "symmetry": symmetry,
        "peak": float(force[peak_at]),
        "peak_normal": float(run["normal"][peak_at]),
        "last_fraction": float(force[-1] / force[peak_at]),
        "n_crack": len(crack),
    }
    ok_tips = all(d <= DELTA for d in tips)
    ok_sym = symmetry <= DX + 1e-12
    ok_soft = peak_at < len(force) - 1 and result["last_fraction"] < SOFTENED
    print(f"{name}: {len(crack)} crack particles (damage >= {DAMAGE})")
    print(f"  nearest crack particle to the notch tips: {tips[0] * 1e3:.2f}, {tips[1] * 1e3:.2f} mm "
          f"(<= one horizon, {DELTA * 1e3:.0f} mm): {'ok' if ok_tips else 'FAILED'}")
    print(f"  point symmetry about the centre: {symmetry * 1e3:.2f} mm (<= dx = {DX * 1e3:.0f} mm): "
          f"{'ok' if ok_sym else 'FAILED'}")
    print(f"  normal force: peak {result['peak'] / 1e3:.2f} kN at a normal displacement of "
          f"{result['peak_normal'] * 1e6:.1f} um, last {result['last_fraction']:.3f} of the peak "
          f"(peaks and softens below {SOFTENED}): {'ok' if ok_soft else 'FAILED'}")
    print(f"  at the peak: t = {run['t'][peak_at] * 1e3:.3f} ms, lateral displacement "
          f"{run['lateral'][peak_at] * 1e6:.2f} um; dissipated energy at the end "
          f"{run['dissipated'][-1]:.3f} J")
    return result, ok_tips and ok_sym and ok_soft


def plot(prefix, runs):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for name, run in runs.items():
        axes[0].plot(run["normal"] * 1e6, run["normal_force"] / 1e3, lw=1.2, label=name)
        axes[1].plot(run["lateral"] * 1e6, run["lateral_force"] / 1e3, lw=1.2, label=name)
    axes[0].set_xlabel("normal displacement (66 mm gauge) [um]")
    axes[0].set_ylabel("normal force [kN]")
    axes[0].set_title("(a) normal")
    axes[1].set_xlabel("lateral displacement (66 mm gauge) [um]")
    axes[1].set_ylabel("lateral force [kN]")
    axes[1].set_title("(b) lateral (10 kN applied, then held)")
    for ax in axes:
        ax.grid(alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(prefix + "_force_displacement.png", dpi=120)

    # The band of the cracks, |y - 100 mm| <= 20 mm, one row per run.
    fig, axes = plt.subplots(len(runs), 1, figsize=(11, 2.6 * len(runs)), squeeze=False)
    for ax, (name, run) in zip(axes[:, 0], runs.items()):
        nodes, damage = run["nodes"], run["damage"]
        band = np.abs(nodes[:, 1] - 0.1) <= 0.02
        sc = ax.scatter(nodes[band, 0] * 1e3, nodes[band, 1] * 1e3, c=damage[band], s=9,
                        cmap="inferno_r", vmin=0, vmax=1, marker="s")
        for x0, x1 in ((0, 25), (175, 200)):
            ax.fill([x0, x1, x1, x0], [97.5, 97.5, 102.5, 102.5], color="0.6")
        mirror = np.array([SIZE, SIZE]) - run["crack"]
        ax.plot(mirror[:, 0] * 1e3, mirror[:, 1] * 1e3, "c+", ms=3,
                label="crack particles turned 180 deg about the centre")
        ax.set_aspect("equal")
        ax.set_xlim(-2, 202)
        ax.set_ylim(79, 121)
        ax.set_ylabel("y [mm]")
        ax.set_title(f"{name}: final damage, band |y - 100 mm| <= 20 mm")
        ax.legend(loc="upper center", fontsize=7)
    axes[-1, 0].set_xlabel("x [mm]")
    fig.colorbar(sc, ax=axes[:, 0].tolist(), shrink=0.9, label="damage")
    fig.savefig(prefix + "_cracks.png", dpi=120)


def main():
    args = sys.argv[1:]
    prefix = None
    if "--plot" in args:
        prefix = args[args.index("--plot") + 1]
        del args[args.index("--plot"):args.index("--plot") + 2]
    if len(args) != 1:
        raise SystemExit(__doc__)
    top = args[0]
    runs = {name: read_run(os.path.join(top, name)) for name in ("full_pd", "coupled")
            if os.path.isfile(os.path.join(top, name, "statistics.csv"))}
    all_ok = True
    results = {}
    for name, run in runs.items():
        results[name], ok = checks(name, run)
        all_ok &= ok
    if len(runs) == 2:
        a, b = runs["full_pd"], runs["coupled"]
        distance = max(nearest(a["crack"], b["crack"]).max(), nearest(b["crack"], a["crack"]).max())
        ratio = results["coupled"]["peak"] / results["full_pd"]["peak"]
        print(f"coupled / all-PD peak normal force: {ratio:.4f}; crack sets within "
              f"{distance * 1e3:.2f} mm ({distance / DELTA:.2f} horizons)")
    if prefix:
        plot(prefix, runs)
    print("all checks: " + ("ok" if all_ok else "FAILED"))


if __name__ == "__main__":
    main()
