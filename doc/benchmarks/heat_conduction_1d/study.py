#!/usr/bin/python3
"""1D transient conduction in a thin bar: PD (bond based conduction) against the classical and
the peridynamic series (doc/benchmarks/heat_conduction_1d/README.md).

For dx = L/20, L/40, L/80 at m = 3.015 (strip width W = 0.15 L fixed) runs bar.prm with
perideal-solid, with and without the surface correction, the end layers holding the odd
continuation sin(pi x) exp(-lambda t) of the PD series; reads the probe at the strip's centre,
prints a Markdown table at t = 0.1 and writes decay.png and convergence.png.
usage: /usr/bin/python3 doc/benchmarks/heat_conduction_1d/study.py [path/to/perideal-solid]
"""
import math
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, ".."))
import prm_runs  # noqa: E402

solver = prm_runs.solver(sys.argv)
m, W, T_END = 3.015, 0.15, 0.1
K = math.pi  # the mode sin(pi x / L), L = 1, k = rho = c = 1


def pd_rate(dx, corrected):
    """lambda of the PD series on the 2D lattice (doc/theory/heat_conduction.md): with the
    interior surface-correction factor the lattice-exact 2 k sum (1 - cos K xi_x)/|xi| /
    sum xi_x^2/|xi|; without it kappa dx^2 sum (1 - cos K xi_x)/|xi|, kappa = 6 k / (pi delta^3)."""
    delta, reach = m * dx, int(math.floor(m))
    mode = moment = 0.
    for i in range(-reach, reach + 1):
        for j in range(-reach, reach + 1):
            r = math.hypot(i, j) * dx
            if 0. < r <= delta * (1. + 1e-12):
                mode += (1. - math.cos(K * i * dx)) / r
                moment += (i * dx) ** 2 / r
    if corrected:
        return 2. * mode / moment
    return 6. / (math.pi * delta ** 3) * mode * dx * dx


def run(dx, corrected):
    rate = pd_rate(dx, corrected)
    depth = 3 * dx
    n_across = round(W / dx)
    x_probe = 0.5 - dx / 2
    y_probe = (n_across // 2 + 0.5) * dx
    values = {"DX": f"{dx:.17g}", "BAR_UPPER": f"1, {W:.17g}",
              "LEFT_LOWER": f"{-depth:.17g}, 0", "LEFT_UPPER": f"0, {W:.17g}",
              "RIGHT_UPPER": f"{1 + depth:.17g}, {W:.17g}", "DEPTH": f"{depth:.17g}",
              "LAYERS": f"sin(pi*x) * exp(-{rate:.17g} * t)",
              "CORRECTION": "true" if corrected else "false", "SOLVER": "explicit",
              "STEP": "0", "PROBE": f"{x_probe:.17g}, {y_probe:.17g}"}
    log, rows = prm_runs.run(solver, os.path.join(here, "bar.prm"), values)
    x = float(re.search(r"particle at \(([0-9.e+-]+) ", log).group(1))
    t = [float(r["time"]) for r in rows]
    A = [float(r["probe1_T"]) / math.sin(K * x) for r in rows]
    balance = max(abs(float(r["heat_error"])) for r in rows)
    stored = max(abs(float(r["stored_heat"])) for r in rows)
    return rate, t, A, balance / stored


table = []
series = {}
for dx in [0.05, 0.025, 0.0125]:
    for corrected in [True, False]:
        rate, t, A, balance = run(dx, corrected)
        series[(dx, corrected)] = (t, A)
        classical = math.exp(-K * K * T_END)
        pd = math.exp(-rate * T_END)
        table.append((dx, corrected, rate / K ** 2, A[-1] / pd - 1., A[-1] / classical - 1.,
                      balance))

print(f"| dx | particles across | surface correction | lambda / (k pi^2) | T(L/2) / PD series - 1 "
      f"| T(L/2) / classical - 1 | max heat error / stored heat |")
print("|---|---|---|---|---|---|---|")
for dx, corrected, ratio, e_pd, e_cl, balance in table:
    print(f"| L/{round(1 / dx)} | {round(W / dx)} | {'on' if corrected else 'off'} | {ratio:.5f} "
          f"| {e_pd:+.3e} | {e_cl:+.3e} | {balance:.1e} |")

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

fig, ax = plt.subplots(figsize=(5.5, 3.8))
tt = [T_END * i / 100 for i in range(101)]
ax.plot(tt, [math.exp(-K * K * s) for s in tt], "k-", lw=2, label="classical series")
for (dx, corrected), (t, A) in series.items():
    if corrected:
        ax.plot(t, A, "--", label=f"PD, dx = L/{round(1 / dx)}")
prm_runs.finish(fig, ax, os.path.join(here, "decay.png"), "t [L^2 rho c / k]",
                "T(L/2, t) / sin(pi x_probe / L)", "Thin bar, insulated sides, surface correction on")

fig, ax = plt.subplots(figsize=(5.5, 3.8))
for corrected, marker in [(True, "o-"), (False, "s-")]:
    rows = [r for r in table if r[1] == corrected]
    dxs = [r[0] for r in rows]
    ax.loglog(dxs, [abs(r[4]) for r in rows], marker,
              label=f"|error| vs classical, correction {'on' if corrected else 'off'}")
    ax.loglog(dxs, [abs(r[3]) for r in rows], marker.replace("-", ":"),
              label=f"|error| vs PD series, correction {'on' if corrected else 'off'}")
ref = [r for r in table if r[1]]
ax.loglog([r[0] for r in ref], [abs(ref[0][4]) * r[0] / ref[0][0] for r in ref], "k--",
          label="first order")
ax.set_xlabel("dx / L (m = 3.015, W = 0.15 L)")
ax.set_title("T(L/2, t = 0.1): convergence in dx at fixed m", fontsize=9)
ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(os.path.join(here, "convergence.png"), dpi=120)
