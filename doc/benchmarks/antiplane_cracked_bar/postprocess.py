#!/usr/bin/env python3
"""The square bar with a central crack under antiplane shear (seed 000, example 8.3): tables and plots.

usage: postprocess.py RESULTS [--plot load.png] [--damage damage.png] [--opening opening.png]

RESULTS is the directory of run.sh:
 - traction_<bb|sb>: the paper's loading (total crack length 0.2, S = 12000 psi);
 - grips_<bb|sb>_a<a>: growth to separation under grips, half crack length a;
 - fe_a<a>_l<level>: FE Q2 of the gripped half bar (h = 1/(50 2^level)), grip displacement
   DELTA; fe_traction: FE of the half bar under the traction S (a = 0.1, level 3).

A crack that cuts the bar leaves the grips' reaction at 0 (R / R_max printed); damage beyond
|y| = delta shows where the path left the crack line (a branch, or the cut families at the
sides).

The FE energy release rate of the gripped bar is G = -dU/da (U the energy of the half bar, a
central difference over a +- 0.02, extrapolated to h = 0 as the energy converges like h: the r^(1/2)
tips), so the crack runs at the grip displacement DELTA sqrt(G_IIIc / G) and the far-field stress
S_c = R(a) sqrt(G_IIIc / G) / W (R the grip's reaction at DELTA). A PD run brackets S_c: the
reaction per unit width in the last load step before the crack ran, and that of the step in which
it ran (the reaction before it, scaled by the grip displacements). LEFM for an infinitely high
strip (collinear cracks of period W): S_c = sqrt(2 mu G_IIIc / (W tan(pi a / W))).
"""
import argparse
import csv
import glob
import math
import os
import re

import h5py
import numpy as np

MU = 12e6  # psi
G_C = 2.1161  # lb/in, r_c = 0.0035 at delta = 0.03015
DELTA = 8e-4  # in, the grip displacement at the end of the FE and PD runs
WIDTH = 1.0
DA = 0.02
LABELS = {"bb": "bond-based", "sb": "state-based (stabilization 0.1)"}


def statistics(run):
    """The columns of run/statistics.csv as arrays."""
    with open(os.path.join(run, "statistics.csv")) as f:
        rows = list(csv.DictReader(f))
    return {key: np.array([float(row[key]) for row in rows]) for key in rows[0]}


def last_h5(run, prefix):
    files = sorted(glob.glob(os.path.join(run, f"{prefix}_*.h5")))
    if not files:
        raise SystemExit(f"no {prefix}_*.h5 in {run}")
    return h5py.File(files[-1], "r")


def particles(run):
    """Positions, w and damage of the last particle output of run."""
    with last_h5(run, "particles") as h5:
        return (np.asarray(h5["nodes"][:, :2]), np.asarray(h5["w"][:, 0]),
                np.asarray(h5["damage"][:, 0]))


def fe_critical_stress(results, a):
    """(S_c per level, S_c extrapolated, G per level at DELTA) of the FE runs for half length a."""
    energy, reaction = {}, {}
    for run in glob.glob(os.path.join(results, "fe_a*_l*")):
        if not os.path.isdir(run):
            continue
        fa, level = re.search(r"fe_a([0-9.]+)_l(\d+)$", run).groups()
        columns = statistics(run)
        energy[(round(float(fa), 6), int(level))] = columns["fe_strain_energy"][-1]
        reaction[(round(float(fa), 6), int(level))] = columns["reaction_grip_w"][-1]
    levels = sorted({level for (fa, level) in energy if abs(fa - a) < 1e-9})
    stress, release = [], []
    for level in levels:
        g = -(energy[(round(a + DA, 6), level)] - energy[(round(a - DA, 6), level)]) / (2 * DA)
        release.append(g)
        stress.append(reaction[(round(a, 6), level)] * math.sqrt(G_C / g) / WIDTH)
    # First order in h: Richardson with the two finest levels.
    return stress, 2 * stress[-1] - stress[-2], release


def lefm_critical_stress(a):
    return math.sqrt(2 * MU * G_C / (WIDTH * math.tan(math.pi * a / WIDTH)))


def growth(run):
    """What a gripped PD run shows: the bracket of S_c, the step in which the crack ran, the
    final reaction relative to the peak, and the damage checks."""
    columns = statistics(run)
    reaction = columns["reaction_top grip_w"] / WIDTH
    broken = columns["broken_bonds"]
    steps = len(reaction) - 1
    grip = DELTA * np.arange(steps + 1) / steps
    # The step in which the crack ran: the largest jump of broken bonds.
    jumps = np.diff(broken)
    k = int(np.argmax(jumps)) + 1
    lower = reaction[k - 1]
    upper = reaction[k - 1] * grip[k] / grip[k - 1]
    x, w, damage = particles(run)
    horizon = 3.015 * 0.01
    outside = np.abs(x[:, 1]) > horizon + 1e-9
    mirror = {(round(p[0], 6), round(p[1], 6)): d for p, d in zip(x, damage)}
    asymmetry = max(abs(d - mirror.get((round(-p[0], 6), round(p[1], 6)), d)) for p, d in zip(x, damage))
    return {"lower": lower, "upper": upper, "step": k, "final": reaction[-1] / reaction.max(),
            "outside": damage[outside].max(), "asymmetry": asymmetry, "curve": (grip, reaction)}


def paper_loading(run):
    """Broken bonds before and after, the first step with breaking, and the opening."""
    columns = statistics(run)
    broken = columns["broken_bonds"]
    # A run whose crack cut the bar stopped (no equilibrium) after its last converged step.
    with open(os.path.join(run, "..", os.path.basename(run) + ".prm")) as f:
        steps = int(re.search(r"Load steps *= *(\d+)", f.read()).group(1))
    done = len(broken) - 1
    first = next((k for k in range(1, done + 1) if broken[k] > broken[0]), None)
    result = {"precut": broken[0], "final": broken[-1], "first": first, "steps": steps,
              "done": done, "tip": None, "opening": None}
    if done == steps:
        x, w, damage = particles(run)
        result["opening"] = opening(x, w)
    return result


def opening(x, w):
    """The opening w(x, dx/2) - w(x, -dx/2) along the crack line, sorted by x."""
    upper = {round(p[0], 6): v for p, v in zip(x, w) if abs(p[1] - 0.005) < 1e-6}
    lower = {round(p[0], 6): v for p, v in zip(x, w) if abs(p[1] + 0.005) < 1e-6}
    xs = sorted(set(upper) & set(lower))
    return np.array(xs), np.array([upper[s] - lower[s] for s in xs])


def fe_opening(run):
    """2 w(x, 0.005) of the FE half bar (w is odd in y): the opening between the PD rows."""
    with last_h5(run, "solution") as h5:
        nodes, w = np.asarray(h5["nodes"][:, :2]), np.asarray(h5["w"][:, 0])
    row = np.abs(nodes[:, 1] - 0.005) < 1e-9
    xs, index = np.unique(np.round(nodes[row, 0], 9), return_index=True)
    return xs, 2 * w[row][index]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("results")
    parser.add_argument("--plot")
    parser.add_argument("--damage")
    parser.add_argument("--opening")
    args = parser.parse_args()
    results = args.results

    print("The paper's loading: total crack length 0.2, S = 12000 psi in load steps (dx = 0.01)")
    paper = {}
    for model in ("bb", "sb"):
        run = os.path.join(results, f"traction_{model}")
        if not os.path.isdir(run):
            continue
        p = paper_loading(run)
        paper[model] = p
        first = "none" if p["first"] is None else f"S = {12000 * p['first'] / p['steps']:.0f}"
        if p["done"] < p["steps"]:
            print(f"  {LABELS[model]:32s}: bonds cut {p['precut']:.0f}, first breaking at {first}; "
                  f"the crack cut the bar in load step {p['done'] + 1} (S = "
                  f"{12000 * (p['done'] + 1) / p['steps']:.0f}): no equilibrium, the run stopped")
            continue
        centre = p["opening"][1][np.argmin(np.abs(p["opening"][0]))]
        # The pre-crack of length 0.2 cuts p['precut'] bonds: that many per 0.2 of crack.
        extension = (p["final"] - p["precut"]) / 2 * 0.2 / p["precut"]
        print(f"  {LABELS[model]:32s}: bonds cut {p['precut']:.0f}, broken at S = 12000 "
              f"{p['final']:.0f} (+{p['final'] - p['precut']:.0f}: about {extension / 0.01:.1f} dx "
              f"of growth per tip, arrested), first breaking at {first}, opening at x = 0: "
              f"{centre:.4e} in")
    fe_traction = os.path.join(results, "fe_traction")
    if os.path.isdir(fe_traction):
        xs, cod = fe_opening(fe_traction)
        print(f"  FE Q2 h = 1/400: opening at x = 0 (rows y = +-0.005): {cod[np.argmin(np.abs(xs))]:.4e} in")
    print(f"  LEFM (infinite strip): G at S = 12000 is "
          f"{12000**2 * WIDTH * math.tan(math.pi * 0.1 / WIDTH) / (2 * MU):.3f} lb/in < G_IIIc = {G_C}")

    print("\nGrowth to separation under grips: far-field stress S_c = R/W at which the crack runs")
    curves = {}
    for a in (0.1, 0.2):
        try:
            levels, extrapolated, release = fe_critical_stress(results, a)
        except (KeyError, IndexError):
            continue
        print(f"  a = {a}: FE Q2 S_c = " + ", ".join(f"{s:.1f}" for s in levels) +
              f" (h = 1/100 ... 1/400) -> {extrapolated:.1f} psi; LEFM infinite strip "
              f"{lefm_critical_stress(a):.1f} psi")
        for model in ("bb", "sb"):
            run = os.path.join(results, f"grips_{model}_a{a}")
            if not os.path.isdir(run):
                continue
            g = growth(run)
            curves[(model, a)] = g["curve"]
            middle = 0.5 * (g["lower"] + g["upper"])
            print(f"    PD {LABELS[model]:32s}: runs in step {g['step']} at S in "
                  f"[{g['lower']:.0f}, {g['upper']:.0f}] psi ({100 * (g['lower'] / extrapolated - 1):+.1f} "
                  f"... {100 * (g['upper'] / extrapolated - 1):+.1f} % of FE); final R / R_max = "
                  f"{g['final']:.1e}; largest damage beyond |y| = delta: {g['outside']:.2g}; "
                  f"|damage(x) - damage(-x)| <= {g['asymmetry']:.2g}")
        curves[("fe", a)] = extrapolated
        if a != 0.2:
            continue
        for model in ("bb", "sb"):
            coupled, full = (os.path.join(results, f"{kind}_{model}" + ("" if kind == "coupled" else "_a0.2"))
                             for kind in ("coupled", "grips"))
            if not (os.path.isdir(coupled) and os.path.isdir(full)):
                continue
            g, f = growth(coupled), growth(full)
            curves[("coupled " + model, a)] = g["curve"]
            times = [float(open(os.path.join(r, "wall_time")).read()) for r in (coupled, full)]
            print(f"    coupled {LABELS[model]:27s}: runs in step {g['step']} at S in "
                  f"[{g['lower']:.0f}, {g['upper']:.0f}] psi (all-PD [{f['lower']:.0f}, {f['upper']:.0f}]); "
                  f"final R / R_max = {g['final']:.1e}; largest damage beyond |y| = delta: "
                  f"{g['outside']:.2g}; "
                  f"wall time {times[0]:.0f} s against {times[1]:.0f} s all-PD ({times[0] / times[1]:.2f})")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    if args.plot and curves:
        fig, ax = plt.subplots(figsize=(6.5, 4.5))
        colors = {0.1: "C0", 0.2: "C1"}
        for (model, a), curve in curves.items():
            if model == "fe":
                ax.axhline(curve, color=colors[a], lw=0.8, ls=":",
                           label=f"a = {a}: FE critical S_c = {curve:.0f} psi")
                continue
            grip, reaction = curve
            style = {"bb": "-", "sb": "--", "coupled bb": ":", "coupled sb": "-."}[model]
            name = LABELS[model.split()[-1]]
            ax.plot(1e4 * grip, reaction, style, color=colors[a],
                    label=f"a = {a}: {'coupled PD-FE' if 'coupled' in model else 'PD'} {name}")
        ax.set_xlabel("grip displacement Delta [1e-4 in]")
        ax.set_ylabel("far-field stress S = R / W [psi]")
        ax.set_title("Example 8.3 gripped: the crack runs to separation at S_c (dx = 0.01)")
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(args.plot, dpi=150)
        print(f"wrote {args.plot}")
    if args.damage:
        panels = [("traction_bb", "paper's loading, bond-based:\narrest at S = 12000")]
        panels += [(f"grips_{m}_a0.2", f"grips, a = 0.2, {LABELS[m].split(' ')[0]}:\ncut through")
                   for m in ("bb", "sb")]
        panels += [("coupled_bb", "coupled PD-FE, a = 0.2,\nbond-based: cut through")]
        panels = [(run, title) for run, title in panels
                  if glob.glob(os.path.join(results, run, "particles_*.h5"))]
        fig, axes = plt.subplots(1, len(panels), figsize=(3.2 * len(panels), 3.4))
        for ax, (run, title) in zip(np.atleast_1d(axes), panels):
            x, w, damage = particles(os.path.join(results, run))
            inside = (np.abs(x[:, 0]) < 0.5) & (np.abs(x[:, 1]) < 0.5)
            image = ax.scatter(x[inside, 0], x[inside, 1], c=damage[inside], s=1.2, cmap="viridis",
                               vmin=0, vmax=0.6)
            ax.set_aspect("equal")
            ax.set_title(title, fontsize=8)
            ax.set_xticks([-0.5, 0, 0.5])
            ax.set_yticks([-0.5, 0, 0.5])
        fig.colorbar(image, ax=axes, shrink=0.8, label="damage")
        fig.savefig(args.damage, dpi=150)
        print(f"wrote {args.damage}")
    if args.opening and paper:
        fig, ax = plt.subplots(figsize=(6.5, 4))
        for model, p in paper.items():
            if p["opening"] is None:
                continue
            xs, cod = p["opening"]
            ax.plot(xs, 1e4 * cod, "o" if model == "bb" else "s", ms=3, label=f"PD {LABELS[model]}")
        if os.path.isdir(fe_traction):
            xs, cod = fe_opening(fe_traction)
            ax.plot(xs, 1e4 * cod, "k-", lw=1, label="FE Q2 (pre-crack only), h = 1/400")
        ax.axvline(-0.1, color="grey", lw=0.5, ls=":")
        ax.axvline(0.1, color="grey", lw=0.5, ls=":")
        ax.set_xlabel("x [in]")
        ax.set_ylabel("w(x, dx/2) - w(x, -dx/2) [1e-4 in]")
        ax.set_title("Example 8.3, the paper's loading (S = 12000 psi): tearing opening")
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(args.opening, dpi=150)
        print(f"wrote {args.opening}")


if __name__ == "__main__":
    main()
