#!/usr/bin/env python3
"""Benchmark compact_tension: the LEFM load of the PD specimen itself, from its compliance.

usage: compliance.py MINUS ZERO PLUS [MINUS ZERO PLUS ...] [--peaks RUN... [--plot FILE [--law LAW]]]
       compliance.py --table OUTPUT.md --plot FILE [--law LAW]

Each triple is three runs of full_pd.prm (or a variant) that stop after the first event
(<Solver/Control/Maximum events> = 1) with the pre-crack's end at a - dx, a and a + dx (one
column of crossing bonds fewer and more). The first event's state is linear in the load, so
C = (2 u_pin) / P, the load-line opening over the pin load, is the compliance of the PD specimen
with that pre-crack. Its energy release rate at the load P is G = P^2 / (2 B) dC/da, dC/da by
the central difference over +-dx: exactly the strain energy the lattice releases at a fixed load
when the column of bonds ahead of the tip is cut, per unit crack growth. So
P_PD = sqrt(2 B G_c / (dC/da)) is the LEFM load of the discrete specimen (its own elasticity, its
notch, its pins; G_c dissipated per unit growth, as the lattice does with <Fracture energy
calibration> = lattice), against ASTM E399's P for W = back edge - dx/2 and a = tip - dx/2; the ratio
of a peak to P_PD is the peak over the LEFM of the body actually modelled.

The pre-crack cuts the bonds whose crossing of its line lies before its end. A notch tip midway
between two particle columns (x = 20 mm in full_pd.prm) is a tie: the mirror pairs of bonds
(x_t - d, -/+y) -- (x_t + d, +/-y) cross the line exactly at the tip (6 bonds for m = 3, 10 for
m = 4). Round-off used to decide which of them the pre-crack cut (measured: all, none or some,
mirror-asymmetric, depending on dx and m); since the pre-crack rule (doc/theory/models.md,
"Pre-cracks") they stay intact, as with the tip at x_t - 0.001 dx. The triples move the tip off
the tie by a small fraction of dx (the tables of the README: -0.001 dx, the ties intact, and
+0.001 dx, cut);
each step of the triple then cuts exactly one column (18 bonds for m = 3, 40 for m = 4).
The compliance itself is printed, to compare with fe_check.py's FE compliance of the geometry.

--peaks RUN...: runs of the same specimens (dx and m of a triple; the notch as the triple's
middle run) whose peak load is compared with ASTM's and with P_PD; --plot FILE draws both ratios
against the horizon delta, one line per m and failure law (the convergence plot of the README).
--table OUTPUT.md: the plot from the peak table of an earlier output of this script (the rows
of compact_tension_lefm_runs.md), without the runs.
--law LAW: plot only the runs of that failure law (as the tables print it, e.g. "softening n = 2,
N = 8", the shipped law).
"""
import math
import sys

from postprocess import astm_f, entry, expand, read


def compliance(directory):
    run = read(directory)
    # The first event: the load and the load-line opening (twice the top pin's displacement).
    return run, run["opening"][1] / run["load"][1]


def law_of(prm):
    if "Failure law" not in prm or entry(prm, "Failure law") != "linear softening":
        return "brittle"
    n = entry(prm, "Softening ratio") if "Softening ratio" in prm else "4"
    teeth = entry(prm, "Softening teeth") if "Softening teeth" in prm else "8"
    return f"softening n = {float(n):g}, N = {int(teeth)}"


def table_rows(path):
    """The peak rows (m, law, delta, peak/ASTM, peak/P_PD, stopped) of an earlier output's peak
    table; stopped: the run was stopped before its end, its peak the largest load so far."""
    rows = []
    for line in open(path):
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) != 9 or not cells[1].replace(".", "", 1).isdigit():
            continue
        dx, delta = float(cells[1]), float(cells[2])
        # m to the 0.005 of the horizon factors (delta is printed to 1 um).
        rows.append((round(round(delta / dx / 0.005) * 0.005, 3), cells[3], delta * 1e-3,
                     float(cells[7]), float(cells[8]), "stopped" in cells[4]))
    return rows


def plot_rows(rows, plot, law=None):
    rows = [row for row in rows if law is None or row[1] == law]
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(9.5, 4.8))
    ax.set_prop_cycle(color=[plt.cm.tab20(2 * k % 20 + 2 * k // 20) for k in range(20)])
    for m, law in sorted({(row[0], row[1]) for row in rows}):
        group = sorted((row for row in rows if row[:2] == (m, law)), key=lambda row: row[2])
        d = [row[2] * 1e3 for row in group]
        line, = ax.plot(d, [row[4] for row in group], "o-", label=f"m = {m}, {law}: / P_PD")
        ax.plot(d, [row[3] for row in group], "^:", color=line.get_color(),
                label=f"m = {m}, {law}: / ASTM")
        stopped = [row for row in group if len(row) > 5 and row[5]]
        for row in stopped:
            ax.plot([row[2] * 1e3] * 2, [row[4], row[3]], "o", mfc="none", ms=13,
                    color=line.get_color())
    ax.axhline(1, color="k", lw=0.8)
    ax.axhspan(0.95, 1.05, color="0.9")
    ax.set_xlabel("horizon delta [mm]")
    ax.set_ylabel("peak load / LEFM load")
    ax.set_title("Compact tension, all-PD, G_c on the lattice, tie-free notch" +
                 (f"\n{law}" if law else ""))
    if any(len(row) > 5 and row[5] for row in rows):
        ax.plot([], [], "o", mfc="none", ms=13, color="0.4",
                label="run stopped: its largest load so far")
    ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    fig.tight_layout()
    fig.savefig(plot, dpi=110)


def main():
    args = sys.argv[1:]
    peaks, plot = [], None
    if "--plot" in args:
        plot = args[args.index("--plot") + 1]
        del args[args.index("--plot"):args.index("--plot") + 2]
    law = None
    if "--law" in args:
        law = args[args.index("--law") + 1]
        del args[args.index("--law"):args.index("--law") + 2]
    if "--table" in args and plot:
        plot_rows(table_rows(args[args.index("--table") + 1]), plot, law)
        return
    if "--peaks" in args:
        peaks = args[args.index("--peaks") + 1:]
        args = args[:args.index("--peaks")]
    if not args or len(args) % 3:
        raise SystemExit(__doc__)
    print("| dx [mm] | m | a/W | C(a) [m/N] | dC/da [1/N] | P_PD [N] | P_ASTM [N] | P_PD / P_ASTM |")
    print("|---|---|---|---|---|---|---|---|")
    reference = {}
    for k in range(0, len(args), 3):
        (r0, c0), (r1, c1), (r2, c2) = (compliance(d) for d in args[k:k + 3])
        prm = expand(f"{args[k + 1]}/run.prm")
        B = float(entry(prm, "Thickness"))
        G = float(entry(prm, "Fracture energy"))
        m = float(entry(prm, "Horizon factor"))
        dx = r1["dx"]
        dcda = (c2 - c0) / (r2["a"] - r0["a"])
        p_pd = math.sqrt(2 * B * G / dcda)
        reference[(round(dx * 1e6), round(m, 3))] = p_pd
        print(f"| {dx * 1e3:g} | {m:g} | {r1['a'] / r1['W']:.4f} | {c1:.6e} | {dcda:.6e} | "
              f"{p_pd:.2f} | {r1['lefm']:.2f} | {p_pd / r1['lefm']:.4f} |")
    if not peaks:
        return
    print()
    print("| run | dx [mm] | delta [mm] | law | events | first [N] | peak [N] (event) | "
          "peak/ASTM | peak/P_PD |")
    print("|---|---|---|---|---|---|---|---|---|")
    rows = []
    for d in peaks:
        r = read(d)
        prm = expand(f"{d}/run.prm")
        m = round(float(entry(prm, "Horizon factor")), 3)
        p_pd = reference[(round(r["dx"] * 1e6), m)]
        k = r["load"].index(r["peak"])
        rows.append((m, law_of(prm), r["delta"], r["peak"] / r["lefm"], r["peak"] / p_pd))
        print(f"| {r['name']} | {r['dx'] * 1e3:g} | {r['delta'] * 1e3:.3f} | {rows[-1][1]} | "
              f"{len(r['load']) - 1} | {r['load'][1]:.2f} | {r['peak']:.2f} ({k}) | "
              f"{rows[-1][3]:.4f} | {rows[-1][4]:.4f} |")
    if plot:
        plot_rows(rows, plot, law)


if __name__ == "__main__":
    main()
