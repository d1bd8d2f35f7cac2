#!/usr/bin/env python3
"""Benchmark compact_tension: the crack-tip toughness of the PMB lattice, K_tip / K_Ic.

usage: k_field.py RESULTS_DIR...   (runs of k_field.prm and its variants)

k_field.prm loads a straight lattice crack by Williams' mode-I field of K = 10 K_Ic on the outer
layers of a square; under the sequentially linear control the K of event k is 10 K_Ic times its
load factor. The crack advances column by column: a column of the square lattice is crossed by
n_col = sum over the family's bonds (a, b), b > 0, of b bonds; the events whose bonds complete
column j form its period. Per run: the K of the first break, the largest K of each period (the
K that pushes the tip through the column: what a specimen's peak load follows) and where in the
column it comes (the bonds broken by then over n_col), and r = the straight line through the
periods' largest K against that position, at position 0: the prescribed field is centred on the
pre-crack's tip, so the K the moving tip sees falls by a few per cent per column in a square of
40 dx (the line removes this drift). LEFM's load is r times too low for a lattice crack tip.

The second table predicts the compact-tension peak over ASTM E399's load from these events alone:
at dx = 2, 1.5, 1, 0.5 mm (W = 40 mm - dx/2, a = 20 mm - dx/2), the largest over the events of
the first two columns of K_k / K_Ic (drift removed with the line's slope) times f(a/W) / f((a +
da_k)/W), da_k = dx times the event's position in the columns: the specimen's load for a given K
falls as the crack grows, so the coarser the lattice, the less of the column's resistance the
peak sees.
"""
import csv
import math
import re
import sys

from postprocess import astm_f


def n_col(m):
    n = int(math.ceil(m))
    return sum(b for a in range(-n, n + 1) for b in range(1, n + 1) if math.hypot(a, b) <= m)


def analyse(directory, periods=3):
    with open(f"{directory}/run.prm") as f:
        m = float(re.findall(r"set\s+Horizon factor\s*=\s*(\S+)", f.read())[-1])
    with open(f"{directory}/statistics.csv") as f:
        rows = list(csv.DictReader(f))[1:]
    k = [10 * float(r["time"]) for r in rows]
    grown = [float(r["broken_bonds"]) - float(rows[0]["broken_bonds"]) for r in rows]
    n = n_col(m)
    maxima = []
    for j in range(periods):
        events = [e for e in range(len(rows)) if j * n <= grown[e] < (j + 1) * n]
        # A period counts only when the run went on past it.
        if not events or grown[-1] < (j + 1) * n:
            break
        e = max(events, key=lambda e: k[e])
        maxima.append((grown[e] / n, k[e], e + 1))
    if len(maxima) >= 2:
        xs, ys = [p for p, _, _ in maxima], [v for _, v, _ in maxima]
        mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
        slope = (sum((x - mx) * (y - my) for x, y in zip(xs, ys))
                 / sum((x - mx) ** 2 for x in xs))
        r = my - slope * mx
    else:
        r, slope = float("nan"), 0.
    predicted = {}
    for dx in (2., 1.5, 1., 0.5):
        W, a = 40 - dx / 2, 20 - dx / 2
        predicted[dx] = max((k[e] - slope * grown[e] / n) * astm_f(a / W)
                            / astm_f((a + grown[e] / n * dx) / W)
                            for e in range(len(rows)) if grown[e] < 2 * n)
    return m, n, k[0], maxima, r, predicted


def main():
    if len(sys.argv) < 2:
        raise SystemExit(__doc__)
    print("| m | n_col | K_first / K_Ic | largest K / K_Ic per column (position, event) | "
          "r = K_tip / K_Ic |")
    print("|---|---|---|---|---|")
    results = [analyse(d) for d in sys.argv[1:]]
    for m, n, first, maxima, r, _ in results:
        columns = ", ".join(f"{v:.4f} ({p:.2f}, {e})" for p, v, e in maxima)
        print(f"| {m} | {n} | {first:.4f} | {columns} | {r:.4f} |")
    print("\n| m | CT peak / LEFM predicted at dx = 2, 1.5, 1, 0.5 mm |")
    print("|---|---|")
    for m, _, _, _, _, predicted in results:
        print(f"| {m} | " + ", ".join(f"{v:.3f}" for v in predicted.values()) + " |")


if __name__ == "__main__":
    main()
