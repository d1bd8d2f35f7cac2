#!/usr/bin/env python3
"""The state-based antiplane model's critical load in the gripped cracked bar against dx, and the
crack-tip toughness of the lattice under a K_III field (issue #40).

usage: convergence.py RESULTS   (the directory of convergence.sh)

RESULTS/bar_<sb|bb>_dx<dx>_a<a>: cracked_bar_grips.prm at lattice spacing dx, half crack length a,
the lattice calibration of G_IIIc, the far field S = 2 mu Delta / W raised from S0 to S1 in the
run's load steps (its grip function Delta = A + B t). The critical stress is the largest grip
reaction per unit width before the load step in which the most bonds broke (the crack ran): the
bracket [R_peak, R_peak S_next / S_peak], S the far field of the steps, is the step's width.
Against the FE's S_c (README.md) and LEFM's estimate of a crack longer by delta / 2 (the r^(1/2)
field of a tip blunted over a horizon): S_c(a + delta/2) / S_c(a) = sqrt(tan(pi a / W) /
tan(pi (a + delta/2) / W)).

RESULTS/k_field_<sb|bb>: k_field.prm (the K_III field K = lambda K_IIIc, lambda = K0 + K1 t on
the outer layers): the lambda of the first break and the lambda at which the tip passes columns
1, 2, 3 of crossing bonds (n_col bonds each), the bracket [previous step, step]; the tip moves away
from the field's centre, so the K it sees falls by a few per cent per column: r is the line
through the columns' upper values (against the column reached before the step) at column 0.
"""
import csv
import glob
import math
import os
import re
import sys

MU = 12e6
FE = {0.1: 12517.0, 0.2: 8378.0}  # README.md, FE S_c extrapolated to h = 0


def n_col(m):
    n = int(math.ceil(m))
    return sum(b for a in range(-n, n + 1) for b in range(1, n + 1) if math.hypot(a, b) <= m)


def rows(run):
    with open(os.path.join(run, "statistics.csv")) as f:
        return list(csv.DictReader(f))


def prm(run):
    with open(run + ".prm") as f:
        return f.read()


def bar(run):
    text = prm(run)
    a0, b0 = map(float, re.search(r"set Function = ([0-9.e+-]+)\+([0-9.e+-]+)\*t", text).groups())
    table = rows(run)
    far = [2 * MU * (a0 + b0 * float(r["time"])) for r in table]
    reaction = [float(r["reaction_top grip_w"]) for r in table]
    broken = [float(r["broken_bonds"]) for r in table]
    jumps = [broken[k] - broken[k - 1] for k in range(1, len(broken))]
    k = 1 + max(range(len(jumps)), key=lambda i: jumps[i])
    peak = max(range(k), key=lambda i: reaction[i])
    upper = reaction[peak] * far[peak + 1] / far[peak]
    return reaction[peak], upper, int(jumps[k - 1]), reaction[k], far[0], far[-1]


def k_field(run):
    text = prm(run)
    k0, k1 = map(float, re.search(r"\*\(([0-9.]+)\+([0-9.]+)\*t\)", text).groups())
    m = float(re.search(r"set Horizon factor *= *(\S+)", text).group(1))
    table = rows(run)
    lam = [k0 + k1 * float(r["time"]) for r in table]
    grown = [float(r["broken_bonds"]) - float(table[0]["broken_bonds"]) for r in table]
    n = n_col(m)
    first = next(s for s in range(1, len(table)) if grown[s] > 0)
    columns = []
    for j in range(1, 4):
        s = next((s for s in range(1, len(table)) if grown[s] >= j * n), None)
        if s is None:
            break
        columns.append((grown[s - 1] / n, lam[s - 1], lam[s]))
    if len(columns) >= 2:
        xs, ys = [c[0] for c in columns], [c[2] for c in columns]
        mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
        slope = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
        r = my - slope * mx
    else:
        r = float("nan")
    return m, n, (lam[first - 1], lam[first]), columns, r


def main():
    if len(sys.argv) != 2:
        raise SystemExit(__doc__)
    results = sys.argv[1]
    print("| model | a | dx | delta | S_c bracket | / FE S_c | LEFM, crack longer by delta/2 | "
          "bonds in the run | reaction after |")
    print("|---|---|---|---|---|---|---|---|---|")
    runs = glob.glob(os.path.join(results, "bar_*_dx*_a*"))
    key = lambda r: (r.split("_")[-3], float(r.split("_a")[-1]), -float(r.split("_dx")[-1].split("_")[0]))
    for run in sorted((r for r in runs if os.path.isdir(r)), key=key):
        model, dx, a = re.search(r"bar_(\w\w)_dx([0-9.]+)_a([0-9.]+)$", run).groups()
        dx, a = float(dx), float(a)
        lower, upper, bonds, after, _, _ = bar(run)
        delta = 3.015 * dx
        lefm = math.sqrt(math.tan(math.pi * a) / math.tan(math.pi * (a + delta / 2)))
        print(f"| {model} | {a} | {dx} | {delta:.4f} | [{lower:.0f}, {upper:.0f}] | "
              f"{lower / FE[a]:.3f} … {upper / FE[a]:.3f} | {lefm:.3f} | {bonds} | {after:.0f} |")
    print()
    print("| run | m | n_col | first break, K / K_IIIc | columns 1, 2, 3: K / K_IIIc | r at column 0 |")
    print("|---|---|---|---|---|---|")
    for run in sorted(glob.glob(os.path.join(results, "k_field_*"))):
        if not os.path.isdir(run):
            continue
        m, n, first, columns, r = k_field(run)
        text = ", ".join(f"[{lo:.3f}, {hi:.3f}]" for _, lo, hi in columns)
        print(f"| {os.path.basename(run)} | {m} | {n} | [{first[0]:.3f}, {first[1]:.3f}] | "
              f"{text} | {r:.3f} |")


if __name__ == "__main__":
    main()
