#!/usr/bin/env python3
"""Torsion of the 1 x 2 bar with an edge crack (seed 000, example 8.5): torque against crack length.

usage: postprocess.py RESULTS... [--plot torque.png] [--stresses BOND_RUN STATE_RUN stresses.png]

RESULTS are the directories of run.sh, named fe_a<a>_l<level> (FE, Q2, h = 1/(16 2^level)),
pd_<bond|state>_a<a>_dx<dx> (PD) and coupled_<bond|state>_a<a>_dx<dx> (PD around the crack, FE
elsewhere). For each crack length a it reads the torque T/(mu psi) from the last row of
statistics.csv (fe_torque, pd_torque; total_torque = fe_torque + pd_torque of a coupled run),
extrapolates the FE torques to h = 0 (the
energy of the cracked section converges like h: the r^(1/2) tip field; like h^4 without a crack,
where the finest value is taken) and prints every torque with its difference from the
extrapolated FE value, and the median and largest |tau_yz| of the particles next to the crack
faces (y = +-dx/2, two horizons or more behind the tip), which the traction-free faces make
small. PD stresses (--stresses): |tau| = sqrt(tau_xz^2 + tau_yz^2) near the crack of two PD runs
(bond-based, state-based; the seed's Figs. 20/21). Coupled runs: their torque against the all-PD
run of the same a, model and dx and against the FE value, with the wall times of both that run.sh
wrote (RESULT.time: 2 ranks; RESULT.time1: one core, where measured).
"""
import argparse
import csv
import glob
import re

import h5py
import numpy as np

SAINT_VENANT = 0.457363  # T/(mu psi) of the uncracked 1 x 2 section (torsion_rectangle)
TAU_MAX = 0.930060  # the uncracked section's largest stress / (mu psi)


def last_row(directory):
    with open(f"{directory}/statistics.csv") as f:
        return list(csv.DictReader(f))[-1]


def particles(directory):
    files = sorted(glob.glob(f"{directory}/particles_*.h5"))
    if not files:
        raise SystemExit(f"no particles_*.h5 in {directory}")
    with h5py.File(files[-1], "r") as h5:
        return np.asarray(h5["nodes"][:, :2], float), np.asarray(h5["shear_stress"][:, :2], float)


def wall_time(run, suffix):
    try:
        with open(f"{run}.{suffix}") as f:
            return float(f.read())
    except FileNotFoundError:
        return float("nan")


def crack_length(run):
    return float(re.search(r"_a([0-9.]+)", run).group(1))


def face_stress(run):
    """Median and largest |tau_yz| / tau_max on the rows next to the crack faces (y = +-dx/2),
    two horizons or more behind the tip (closer, the tip's singular field dominates)."""
    dx = float(re.search(r"dx([0-9.]+)", run).group(1))
    tip = -0.5 + crack_length(run)
    nodes, tau = particles(run)
    rows = (np.abs(np.abs(nodes[:, 1]) - dx / 2) < 1e-9) & (nodes[:, 0] < tip - 2 * 3.015 * dx)
    if not rows.any():
        return float("nan"), float("nan")
    values = np.abs(tau[rows, 1]) / TAU_MAX
    return np.median(values), np.max(values)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--plot")
    parser.add_argument("--stresses", nargs=3)
    args = parser.parse_args()

    fe, pd, coupled = {}, {}, {}
    for run in args.runs:
        a = crack_length(run)
        if "/fe_" in run or run.startswith("fe_"):
            level = int(re.search(r"_l(\d+)", run).group(1))
            fe.setdefault(a, []).append((1.0 / (16 * 2**level), float(last_row(run)["fe_torque"])))
        elif "coupled_" in run:
            model = re.search(r"coupled_(bond|state)", run).group(1)
            dx = float(re.search(r"dx([0-9.]+)", run).group(1))
            row = last_row(run)
            coupled[(a, model, dx)] = (float(row["total_torque"]), float(row["fe_torque"]),
                                       float(row["pd_torque"]), run)
        else:
            model = re.search(r"pd_(bond|state)", run).group(1)
            dx = float(re.search(r"dx([0-9.]+)", run).group(1))
            pd.setdefault(a, []).append((model, dx, float(last_row(run)["pd_torque"]), run))

    reference = {}
    print("FE (Q2 on the slit mesh): T/(mu psi) per h, extrapolated to h = 0")
    for a in sorted(fe):
        values = sorted(fe[a], reverse=True)
        if a > 0 and len(values) >= 2:
            # Error ~ h: T(0) = 2 T(h/2) - T(h) from the two finest meshes.
            reference[a] = 2 * values[-1][1] - values[-2][1]
        else:
            reference[a] = values[-1][1]
        text = ", ".join(f"h = 1/{round(1 / h)}: {t:.6f}" for h, t in values)
        print(f"  a = {a:<5g} {text}; extrapolated {reference[a]:.6f}")
    print(f"  (Saint-Venant, a = 0: {SAINT_VENANT:.6f})")

    print("\nPD against the extrapolated FE torque")
    print("  a      model  dx      T/(mu psi)  difference   |tau_yz|/tau_max on the crack faces "
          "(median, max; >= 2 delta behind the tip)")
    for a in sorted(pd):
        for model, dx, t, run in sorted(pd[a]):
            difference = 100 * (t / reference[a] - 1) if a in reference else float("nan")
            faces = "-"
            if a > 0:
                median, largest = face_stress(run)
                faces = f"{100 * median:.2f} %, {100 * largest:.2f} %"
            print(f"  {a:<6g} {model:<6s} {dx:<7g} {t:.6f}    {difference:+.2f} %     {faces}")

    if coupled:
        print("\nCoupled (PD around the crack, FE Q2 elsewhere) against all-PD at the same dx "
              "and against FE; wall times in s, 2 ranks (one core)")
        print("  a      model  dx      coupled T (FE + PD)           all-PD T    difference  "
              "vs FE     wall all-PD     wall coupled")
        all_pd = {(a, m, d): (t, r) for a in pd for m, d, t, r in pd[a]}
        for key in sorted(coupled):
            a, model, dx = key
            t, t_fe, t_pd, run = coupled[key]
            t_all, run_all = all_pd.get(key, (float("nan"), None))
            difference = 100 * (t / t_all - 1)
            against_fe = 100 * (t / reference[a] - 1) if a in reference else float("nan")
            times = []
            for r in (run_all, run):
                one = wall_time(r, "time1") if r else float("nan")
                text = f"{wall_time(r, 'time'):.1f}" if r else "-"
                times.append(text + (f" ({one:.1f})" if one == one else ""))
            print(f"  {a:<6g} {model:<6s} {dx:<7g} {t:.6f} ({t_fe:.6f} + {t_pd:.6f})  "
                  f"{t_all:.6f}    {difference:+.2f} %     {against_fe:+.2f} %   "
                  f"{times[0]:<15s} {times[1]}")

    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6, 4.5))
        lengths = sorted(reference)
        ax.plot(lengths, [reference[a] for a in lengths], "k-o", label="FE, slit mesh (h -> 0)")
        for model, marker in (("bond", "s"), ("state", "^")):
            for dx, style in ((0.02, "--"), (0.01, ":")):
                points = [(a, t) for a in sorted(pd) for m, d, t, _ in pd[a] if m == model and d == dx]
                if points:
                    x, y = np.array(points).T
                    ax.plot(x, y, marker + style, label=f"PD {model}-based, dx = {dx:g}")
                points = [(a, coupled[(a, m, d)][0]) for a, m, d in sorted(coupled)
                          if m == model and d == dx]
                if points:
                    x, y = np.array(points).T
                    ax.plot(x, y, marker, mfc="none", ms=9,
                            label=f"coupled {model}-based, dx = {dx:g}")
        ax.set_xlabel("crack length a/b (b = 1, the short side)")
        ax.set_ylabel("torque T / (mu psi)")
        ax.set_title("1 x 2 bar with an edge crack under torsion")
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(args.plot, dpi=120)
        print(f"\nwrote {args.plot}")

    if args.stresses:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        *runs, output = args.stresses
        fig, axes = plt.subplots(1, len(runs), figsize=(5 * len(runs), 7.5))
        for ax, run in zip(np.atleast_1d(axes), runs):
            nodes, tau = particles(run)
            magnitude = np.hypot(tau[:, 0], tau[:, 1])
            image = ax.scatter(nodes[:, 0], nodes[:, 1], c=magnitude, s=2, cmap="viridis",
                               vmin=0, vmax=1.2)
            tip = -0.5 + crack_length(run)
            ax.plot([-0.5, tip], [0, 0], "w-", lw=1)
            ax.set_aspect("equal")
            model = re.search(r"pd_(bond|state)", run).group(1)
            ax.set_title(f"|tau| / (mu psi), PD {model}-based, a = {crack_length(run):g}")
            fig.colorbar(image, ax=ax, shrink=0.6)
        fig.tight_layout()
        fig.savefig(output, dpi=120)
        print(f"wrote {output}")


if __name__ == "__main__":
    main()
