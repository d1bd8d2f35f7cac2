#!/usr/bin/env python3
"""Benchmark compact_tension: where the peak load over LEFM comes from (issue #40 part 2).

usage: measures.py RESULTS_DIR... [--tip M=R,...] [--plot FILE]

For each run (statistics.csv, run.prm and the last event's particles_*.h5 of a run of
full_pd.prm or its variants) one row of
- first/LEFM: the load of the first event (the first bond break) over ASTM E399's load;
- peak/LEFM and the event of the peak; peak/LEFM(a + da_peak): against LEFM's load at the crack
  length of the peak (the lattice tip reaches its largest resistance after part of a column);
  with --tip, the ratio over the lattice's crack-tip toughness r = K_tip/K_Ic of k_field.py for
  each m (the peak of a run whose critical stretch is s0 / r: the loads of the sequentially
  linear control are proportional to s0);
- da_peak: the crack growth at the peak, the bonds broken since the pre-crack over the bonds that
  a straight cleave of the lattice along y = 0 breaks per unit length (n_c, counted on the
  specimen's lattice in the ligament), and the crack-length measure's growth;
- G_bond/G_c: the energy of the broken bonds (the statistics' dissipated energy) per unit crack
  growth, over G_c, from the first event to the peak and over the whole run (the crack growth of
  the whole run is the ligament W - a less the bonds left intact: the cleave's count n_c (W - a)
  less the broken bonds, over n_c);
- G_rel/G_c: the energy the specimen releases per unit crack growth, over G_c: the sum over the
  events of the strain-energy drop at fixed pins when the event's bonds break, u_k^2 (1/c_k -
  1/c_{k+1}) (c the compliance u/P of a pin, u its displacement: the state is linear between
  events), which is what the load-displacement curve encloses; it exceeds the bonds' energy by
  what the specimen releases beyond them when a bond snaps (lattice trapping);
- bonds/cleave: the broken bonds of the run over those of a straight cleave of the ligament up
  to the same load-line end (1: no bond off the crack plane);
- rows: the particle rows with damage > 0 after the last event, against the 2 ceil(m - 1/2)
  rows (m = delta/dx) that a straight cleave touches.
--plot FILE draws peak/LEFM against delta, one line per m and failure law (<Material/critical
stretch/Failure law>: brittle, or linear softening with its ratio n; and the brittle runs over r
with --tip). The "whole run" columns assume a run to separation (not one that ends at a
<Separation load fraction> above 0.05); their ratio G_rel/G_bond, the energy released beyond
the bonds', holds for any run.
"""
import math
import sys

import h5py
import numpy as np

from postprocess import astm_f, entry, expand, read


def lattice(prm, dx):
    """Particle centres of the specimen box (the files' lattice: cell centres of dx)."""
    lower = [float(v) for v in entry_of(prm, "specimen", "Lower corner").split(",")]
    upper = [float(v) for v in entry_of(prm, "specimen", "Upper corner").split(",")]
    nx, ny = round((upper[0] - lower[0]) / dx), round((upper[1] - lower[1]) / dx)
    return lower[0] + dx * (np.arange(nx) + 0.5), lower[1] + dx * (np.arange(ny) + 0.5), upper[0]


def entry_of(prm, section, name):
    text = prm[prm.index(f"subsection {section}\n"):]
    return entry(text[:text.index("end")], name)


def cleave(xs, ys, delta, x_from):
    """The bonds of the lattice that cross y = 0 at x >= x_from (both ends in the body)."""
    count = 0
    n = int(math.ceil(delta / (xs[1] - xs[0])))
    dx = xs[1] - xs[0]
    below = [y for y in ys if -delta <= y < 0]
    for y0 in below:
        for b in range(1, n + 1):
            y1 = y0 + b * dx
            if y1 <= 0:
                continue
            for a in range(-n, n + 1):
                if math.hypot(a, b) * dx > delta * (1 + 1e-12):
                    continue
                for x0 in xs:
                    x1 = x0 + a * dx
                    if x1 < xs[0] - 1e-12 or x1 > xs[-1] + 1e-12:
                        continue
                    xc = x0 + (x1 - x0) * (0 - y0) / (y1 - y0)
                    if xc >= x_from - 1e-12:
                        count += 1
    return count


def measure(directory):
    run = read(directory)
    prm = expand(f"{directory}/run.prm")
    import csv
    with open(f"{directory}/statistics.csv") as f:
        rows = list(csv.DictReader(f))[1:]
    dx, delta = run["dx"], run["delta"]
    G_c, B = float(entry(prm, "Fracture energy")), float(entry(prm, "Thickness"))
    xs, ys, back = lattice(prm, dx)
    tip = float(entry(prm, "Cracks").split(":")[1].split(",")[0])
    ligament = cleave(xs, ys, delta, tip)
    n_c = ligament / (back - tip)                      # bonds per unit crack length
    load = np.array([abs(float(r["load"])) for r in rows])
    u = np.array([float(r["load_point_displacement"]) for r in rows])
    broken = np.array([float(r["broken_bonds"]) for r in rows])
    dissipated = np.array([float(r["dissipated_energy"]) for r in rows])
    measure_ = np.array([float(r["crack_length"]) for r in rows])
    k = int(np.argmax(load))
    grown = broken - broken[0]
    law = "brittle"
    if "Failure law" in prm and entry(prm, "Failure law") == "linear softening":
        ratio = entry(prm, "Softening ratio") if "Softening ratio" in prm else "4"
        teeth = entry(prm, "Softening teeth") if "Softening teeth" in prm else "8"
        law = f"softening n = {float(ratio):g}, N = {int(teeth)}"
    # Energy released at fixed pins by event j's breaks: both pins, U = P u.
    c = u / load
    released = u[:-1] ** 2 * (1 / c[:-1] - 1 / c[1:])
    da_end = back - tip
    bond_energy_to_peak = dissipated[k + 1] if k + 1 < len(rows) else dissipated[-1]
    # A run stopped from outside wrote no fields: no rows then (-1).
    h5 = sorted(__import__("glob").glob(f"{directory}/particles_*.h5"))
    rows_damaged = -1
    if h5:
        with h5py.File(h5[-1]) as f:
            y = np.array(f["nodes"])[:, 1]
            damage = np.array(f["damage"])[:, 0]
        rows_damaged = len(set(np.round(y[damage > 1e-12] / dx, 3)))
    return {
        "name": run["name"], "m": delta / dx, "dx": dx,
        "first": load[0] / run["lefm"], "peak": load[k] / run["lefm"], "event": k + 1,
        "peak_grown": load[k] / run["lefm"] * astm_f((run["a"] + grown[k] / n_c) / run["W"])
        / astm_f(run["a"] / run["W"]), "delta": delta,
        "da_peak": grown[k] / n_c, "measure_peak": measure_[k] - measure_[0],
        # The bonds that break at the peak event are part of the growth up to it.
        "G_bond_peak": (bond_energy_to_peak / (B * (grown[min(k + 1, len(rows) - 1)] / n_c))
                        / G_c if grown[min(k + 1, len(rows) - 1)] > 0 else float("nan")),
        "G_rel_peak": released[:k + 1].sum() / (B * grown[min(k + 1, len(rows) - 1)] / n_c) / G_c
        if grown[min(k + 1, len(rows) - 1)] > 0 else float("nan"),
        "G_bond": dissipated[-1] / (B * da_end) / G_c,
        "G_rel": released.sum() / (B * da_end) / G_c,
        "bonds_cleave": grown[-1] / ligament, "rows": rows_damaged,
        "rows_cleave": 2 * math.ceil(delta / dx - 0.5), "events": len(rows), "law": law,
    }


def main():
    args = sys.argv[1:]
    options = {}
    for name in ("--tip", "--plot"):
        if name in args:
            options[name] = args[args.index(name) + 1]
            del args[args.index(name):args.index(name) + 2]
    if not args:
        raise SystemExit(__doc__)
    tip = {float(m): float(r) for m, r in
           (item.split("=") for item in options.get("--tip", "").split(",") if item)}
    print("| run | dx [mm] | m | events | first/LEFM | peak/LEFM | event | da_peak [mm] "
          "(measure) | peak/LEFM(a + da_peak) | peak/(r LEFM) | G_bond/G_c to peak | "
          "G_rel/G_c to peak | G_bond/G_c | G_rel/G_c | bonds/cleave | rows (cleave) |")
    print("|---" * 16 + "|")
    runs = [measure(d) for d in args]
    for r in runs:
        r["r"] = tip.get(round(r["m"], 3), float("nan"))
        print(f"| {r['name']} | {r['dx'] * 1e3:g} | {r['m']:.3f} | {r['events']} | "
              f"{r['first']:.4f} | {r['peak']:.4f} | {r['event']} | {r['da_peak'] * 1e3:.2f} "
              f"({r['measure_peak'] * 1e3:.2f}) | {r['peak_grown']:.4f} | "
              f"{r['peak'] / r['r']:.4f} | {r['G_bond_peak']:.3f} | {r['G_rel_peak']:.3f} | "
              f"{r['G_bond']:.3f} | {r['G_rel']:.3f} | {r['bonds_cleave']:.3f} | "
              f"{r['rows']} ({r['rows_cleave']}) |")
    if "--plot" in options:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6, 4.5))
        for m, law in sorted({(round(r["m"], 3), r["law"]) for r in runs}):
            group = sorted((r for r in runs if round(r["m"], 3) == m and r["law"] == law),
                           key=lambda r: r["delta"])
            d = [r["delta"] * 1e3 for r in group]
            line, = ax.plot(d, [r["peak"] for r in group], "o-" if law == "brittle" else "^:",
                            label=f"m = {m}, {law}")
            if m in tip and law == "brittle":
                ax.plot(d, [r["peak"] / tip[m] for r in group], "s--", color=line.get_color(),
                        label=f"m = {m}, s0 / r (r = {tip[m]:.3f})")
        ax.axhline(1, color="k", lw=0.8)
        ax.axhspan(0.95, 1.05, color="0.9")
        ax.set_xlabel("horizon delta [mm]")
        ax.set_ylabel("peak load / LEFM (ASTM E399)")
        ax.set_title("Compact tension, all-PD: convergence with delta")
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(options["--plot"], dpi=120)


if __name__ == "__main__":
    main()
