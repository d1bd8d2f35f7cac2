#!/usr/bin/python3
"""Convective cooling of a plate at Bi = 1 against the series solution
(doc/benchmarks/convective_cooling/README.md): PD (bond based conduction) and coupled (FE heat
with PD blended in the middle), explicit and implicit. Prints a Markdown table at Fo = 0.5
(t = 40 s) and writes cooling.png.
usage: /usr/bin/python3 doc/benchmarks/convective_cooling/study.py [path/to/perideal-solid]
"""
import math
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, ".."))
import prm_runs  # noqa: E402

solver = prm_runs.solver(sys.argv)
L, k, rho, c, h, T_i, T_inf = 0.02, 20., 8000., 500., 1000., 500., 300.
alpha, Bi = k / (rho * c), h * L / k


def series(xi, Fo):
    """(Carslaw & Jaeger 1959, sect. 3.11; Incropera & DeWitt eq. 5.42), 50 terms."""
    theta = 0.
    for n in range(1, 51):
        low, high = (n - 1) * math.pi, (n - 0.5) * math.pi
        for _ in range(100):
            middle = 0.5 * (low + high)
            if middle * math.tan(middle) < Bi:
                low = middle
            else:
                high = middle
        zeta = 0.5 * (low + high)
        C = 4. * math.sin(zeta) / (2. * zeta + math.sin(2. * zeta))
        theta += C * math.exp(-zeta * zeta * Fo) * math.cos(zeta * xi)
    return T_inf + (T_i - T_inf) * theta


def run(template, values):
    return prm_runs.run(solver, os.path.join(here, template), values)[1]


cases = []
for n in [10, 20, 40]:
    dx = L / n
    for method, step in [("explicit", "0"), ("implicit", "0.5")]:
        if method == "implicit" and n != 20:
            continue
        rows = run("plate.prm", {"DX": f"{dx:.17g}", "LAYER_DEPTH": f"{dx:.17g}",
                                 "LEFT_UPPER": f"{dx - L:.17g}, {L:.17g}",
                                 "RIGHT_LOWER": f"{L - dx:.17g}, 0", "SOLVER": method,
                                 "STEP": step,
                                 "PROBES": f"{dx / 2:.17g}, {L / 2 + dx / 2:.17g}; "
                                           f"{L - dx / 2:.17g}, {L / 2 + dx / 2:.17g}"})
        cases.append(("PD", method, n, dx, rows))
for n in [10, 20]:
    dx = L / n
    for method, step in [("explicit", "0"), ("implicit", "0.5")]:
        rows = run("coupled.prm", {"DX": f"{dx:.17g}",
                                   "GENERATOR_ARGUMENTS": f"{2 * n}, {n} : -0.02, 0 : 0.02, 0.02 : true",
                                   "SOLVER": method, "STEP": step,
                                   "PROBES": f"{dx / 2:.17g}, {L / 2 + dx / 2:.17g}"})
        cases.append(("coupled", method, n, dx, rows))

print("| model | solver | dx = h | T(mid) [K] | series | error / (T_i - T_inf) | T(face) [K] "
      "| series | error / (T_i - T_inf) | heat error / stored heat |")
print("|---|---|---|---|---|---|---|---|---|---|")
for model, method, n, dx, rows in cases:
    last = rows[-1]
    Fo = alpha * float(last["time"]) / L ** 2
    mid, mid_ref = float(last["probe1_T"]), series(0.5 * dx / L, Fo)
    line = (f"| {model} | {method} | L/{n} | {mid:.3f} | {mid_ref:.3f} "
            f"| {(mid - mid_ref) / (T_i - T_inf):+.2e} ")
    if "probe2_T" in last:
        face, face_ref = float(last["probe2_T"]), series(1. - 0.5 * dx / L, Fo)
        line += f"| {face:.3f} | {face_ref:.3f} | {(face - face_ref) / (T_i - T_inf):+.2e} "
    else:
        line += "| (FE) | | "
    stored = float(last["stored_heat"])
    line += f"| {abs(float(last['heat_error']) / stored):.1e} |"
    print(line)

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

fig, ax = plt.subplots(figsize=(5.5, 3.8))
t = [40. * i / 100 for i in range(101)]
for xi, name in [(0., "mid-plane"), (1., "face")]:
    ax.plot(t, [series(xi, alpha * s / L ** 2) for s in t], "k-", lw=1.5)
    ax.text(t[-1], series(xi, alpha * t[-1] / L ** 2), " " + name, va="center", fontsize=8)
for model, method, n, dx, rows in cases:
    if method != "explicit":
        continue
    tt = [float(r["time"]) for r in rows]
    style = "--" if model == "PD" else ":"
    ax.plot(tt, [float(r["probe1_T"]) for r in rows], style, label=f"{model}, dx = L/{n}")
    if "probe2_T" in rows[-1]:
        ax.plot(tt, [float(r["probe2_T"]) for r in rows], style, color=ax.lines[-1].get_color())
ax.set_xlabel("t [s] (Fo = 0.5 at 40 s)")
ax.set_ylabel("T [K]")
ax.set_xlim(0, 46)
ax.set_title("Convective cooling, Bi = 1: series (solid) and the probes", fontsize=9)
ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(os.path.join(here, "cooling.png"), dpi=120)
