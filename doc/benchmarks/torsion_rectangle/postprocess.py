#!/usr/bin/env python3
"""Torsion of the 1 x 2 rectangular bar (seed 000, example 8.4) against the Saint-Venant series.

usage: postprocess.py --fe RESULTS... --pd RESULTS... [--plot convergence.png]
                      [--stresses PD_RESULTS stresses.png]

For every FE run (results directory with its .prm next to it, named fe_q<p>_l<level>) and every
PD run (pd_dx<dx>) it reads the last row of statistics.csv (fe_torque, fe_torsion_energy or
pd_torque, pd_torsion_energy) and prints T/(mu psi), its error against the series and
T psi / (2E) - 1 (mu = psi = 1 in the benchmark's files). For the PD runs it also reads the last
particle output (particles_*.h5: the warping w and the particle stresses shear_stress) and prints
the largest stress error over all particles, relative to tau_max = 0.930060, the error of
tau_yz at the particle nearest to the middle of a long side (1/2 - dx/2, dx/2) and the largest
warping error (after removing the mean of both), relative to max |w| = 0.262764, each against the
series at the particles themselves.

With --plot it draws |T error| against h (FE) and dx (PD); with --stresses tau_yz along y = dx/2
and tau_xz along x = dx/2 of one PD run against the series.

Series (Timoshenko & Goodier, Theory of Elasticity, 3rd ed., 1970, sect. 109; seed note 000,
sec. 5.4), half-sides a = 1/2 (x), b = 1 (y), 200 terms.
"""
import argparse
import csv
import glob
import re

import h5py
import numpy as np

A, B = 0.5, 1.0
N = np.arange(200)
K = (2 * N + 1) * np.pi / (2 * A)
SIGN = np.where(N % 2 == 0, 1.0, -1.0)


def _ratios(y):
    """sinh(k y)/cosh(k b) and cosh(k y)/cosh(k b) per term, without overflow."""
    ay = np.abs(y)[..., None]
    e = np.exp(K * (ay - B)) / (1 + np.exp(-2 * K * B))
    s = np.sign(y)[..., None] * e * (1 - np.exp(-2 * K * ay))
    c = e * (1 + np.exp(-2 * K * ay))
    return s, c


def torque():
    n = np.arange(1, 400, 2)
    total = np.sum(np.tanh(n * np.pi * B / (2 * A)) / n**5)
    return (2 * A) ** 3 * (2 * B) / 3 * (1 - 192 / np.pi**5 * A / B * total)


def stress(x, y):
    """(tau_xz, tau_yz)/(mu psi) at the points (x, y)."""
    x = np.asarray(x, float)
    y = np.asarray(y, float)
    s, c = _ratios(y)
    coefficient = 16 * A / np.pi**2 * SIGN / (2 * N + 1) ** 2
    xz = -np.sum(coefficient * np.cos(K * x[..., None]) * s, axis=-1)
    yz = 2 * x - np.sum(coefficient * np.sin(K * x[..., None]) * c, axis=-1)
    return xz, yz


def warping(x, y):
    x = np.asarray(x, float)
    y = np.asarray(y, float)
    s, _ = _ratios(y)
    coefficient = 32 * A**2 / np.pi**3 * SIGN / (2 * N + 1) ** 3
    return x * y - np.sum(coefficient * np.sin(K * x[..., None]) * s, axis=-1)


def last_row(directory):
    with open(f"{directory}/statistics.csv") as f:
        return list(csv.DictReader(f))[-1]


def particles(directory):
    files = sorted(glob.glob(f"{directory}/particles_*.h5"))
    if not files:
        raise SystemExit(f"no particles_*.h5 in {directory}")
    with h5py.File(files[-1], "r") as h5:
        nodes = np.asarray(h5["nodes"][:, :2], float)
        w = np.asarray(h5["w"][:, 0], float)
        tau = np.asarray(h5["shear_stress"][:, :2], float)
    return nodes, w, tau


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--fe", nargs="*", default=[])
    parser.add_argument("--pd", nargs="*", default=[])
    parser.add_argument("--plot")
    parser.add_argument("--stresses", nargs=2)
    args = parser.parse_args()
    T = torque()
    tau_max = stress(0.5, 0.0)[1]
    print(f"Saint-Venant: T/(mu psi) = {T:.6f} (k1 = {T / 2:.6f}), tau_max/(mu psi) = {tau_max:.6f}")

    fe = {}
    print("\nFE        h        T/(mu psi)  error       T psi/(2E) - 1")
    for run in args.fe:
        degree, level = map(int, re.search(r"fe_q(\d)_l(\d+)", run).groups())
        row = last_row(run)
        t, e = float(row["fe_torque"]), float(row["fe_torsion_energy"])
        h = 1.0 / 2**level
        fe.setdefault(degree, []).append((h, t / T - 1))
        print(f"Q{degree}  1/{2**level:<4d}  {t:.6f}   {100 * (t / T - 1):+.4f} %  {t / (2 * e) - 1:+.1e}")

    pd = []
    print("\nPD  dx      particles  T/(mu psi)  error      T psi/(2E)-1  max|tau err| (> delta "
          "inside)  tau_yz(1/2-dx/2,dx/2) err  max|w err|")
    for run in args.pd:
        dx = float(re.search(r"pd_dx([0-9.]+)", run).group(1))
        row = last_row(run)
        t, e = float(row["pd_torque"]), float(row["pd_torsion_energy"])
        nodes, w, tau = particles(run)
        xz, yz = stress(nodes[:, 0], nodes[:, 1])
        error = np.hypot(tau[:, 0] - xz, tau[:, 1] - yz) / tau_max
        tau_error = np.max(error)
        # Particles at least one horizon (3.015 dx) inside the section.
        inner = (np.abs(nodes[:, 0]) < A - 3.015 * dx) & (np.abs(nodes[:, 1]) < B - 3.015 * dx)
        tau_inner = np.max(error[inner])
        side = np.argmin(np.hypot(nodes[:, 0] - (0.5 - dx / 2), nodes[:, 1] - dx / 2))
        side_error = tau[side, 1] / yz[side] - 1
        exact_w = warping(nodes[:, 0], nodes[:, 1])
        w_error = np.max(np.abs((w - w.mean()) - (exact_w - exact_w.mean()))) / np.max(np.abs(exact_w))
        pd.append((dx, t / T - 1, tau_error, side_error, w_error, tau_inner))
        print(f"    {dx:<7g} {len(w):9d}  {t:.6f}   {100 * (t / T - 1):+.3f} %  {t / (2 * e) - 1:+.2e}"
              f"     {100 * tau_error:5.2f} % ({100 * tau_inner:.2f} %)    {100 * side_error:+.2f} %                   "
              f"{100 * w_error:.2f} %")

    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6, 4.5))
        for degree, values in sorted(fe.items()):
            h, err = np.array(values).T
            ax.loglog(h, np.abs(err), "o-", label=f"FE Q{degree}: |T error| vs h")
        if pd:
            values = np.array(pd)
            ax.loglog(values[:, 0], np.abs(values[:, 1]), "s-", label="PD bond-based: |T error| vs dx")
            ax.loglog(values[:, 0], values[:, 2], "^--", label="PD: max |tau error| / tau_max vs dx")
        ax.set_xlabel("h (FE), dx (PD)")
        ax.set_ylabel("relative error")
        ax.set_title("Rectangular bar 1 x 2 under torsion: torque vs Saint-Venant")
        ax.grid(True, which="both", lw=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(args.plot, dpi=120)
        print(f"\nwrote {args.plot}")

    if args.stresses:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        run, output = args.stresses
        dx = float(re.search(r"pd_dx([0-9.]+)", run).group(1))
        nodes, w, tau = particles(run)
        fig, axes = plt.subplots(1, 2, figsize=(10, 4))
        row = np.abs(nodes[:, 1] - dx / 2) < 1e-9
        order = np.argsort(nodes[row, 0])
        x = np.linspace(-0.5, 0.5, 201)
        axes[0].plot(x, stress(x, np.full_like(x, dx / 2))[1], "k-", label="Saint-Venant")
        axes[0].plot(nodes[row, 0][order], tau[row, 1][order], "o", ms=3, label="PD bond-based")
        axes[0].set_xlabel("x")
        axes[0].set_ylabel("tau_yz / (mu psi)")
        axes[0].set_title(f"along y = dx/2 (dx = {dx:g})")
        column = np.abs(nodes[:, 0] - dx / 2) < 1e-9
        order = np.argsort(nodes[column, 1])
        y = np.linspace(-1, 1, 401)
        axes[1].plot(y, stress(np.full_like(y, dx / 2), y)[0], "k-", label="Saint-Venant")
        axes[1].plot(nodes[column, 1][order], tau[column, 0][order], "o", ms=3, label="PD bond-based")
        axes[1].set_xlabel("y")
        axes[1].set_ylabel("tau_xz / (mu psi)")
        axes[1].set_title(f"along x = dx/2 (dx = {dx:g})")
        for ax in axes:
            ax.grid(True, lw=0.3)
            ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(output, dpi=120)
        print(f"wrote {output}")


if __name__ == "__main__":
    main()
