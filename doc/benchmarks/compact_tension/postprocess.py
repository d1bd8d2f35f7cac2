#!/usr/bin/env python3
"""Benchmark compact_tension: the peak load of each run against LEFM from the same G_c.

usage: postprocess.py RESULTS_DIR... [--plot PREFIX]

Each RESULTS_DIR holds statistics.csv and run.prm (the parameter file of the run). The LEFM
peak load is ASTM E399's P = K_Ic B sqrt(W) / f(a/W), f(alpha) = (2 + alpha)(0.886 + 4.64 alpha
- 13.32 alpha^2 + 14.72 alpha^3 - 5.6 alpha^4) / (1 - alpha)^1.5, K_Ic = sqrt(E' G_c), E' = E
(plane stress), with the load line at the particle column x = dx/2 of the files: W = the back
edge (the specimen's upper corner) - dx/2, a = the pre-crack's end - dx/2 (40 mm - dx/2 and
20 mm - dx/2 in full_pd.prm). Prints one line per run; the last line is the ratio of the first run.
With --plot, PREFIX_load.png (load against load-line displacement, twice the load point's mean
displacement by symmetry) and PREFIX_crack.png (crack growth against load).
"""
import csv
import math
import re
import sys


def astm_f(alpha):
    return ((2 + alpha) * (0.886 + 4.64 * alpha - 13.32 * alpha**2 + 14.72 * alpha**3
                           - 5.6 * alpha**4) / (1 - alpha)**1.5)


def entry(text, name):
    """The last value of 'set NAME = value' in a parameter file."""
    values = re.findall(r"set\s+" + re.escape(name) + r"\s*=\s*([^\n#]+)", text)
    if not values:
        raise SystemExit(f"postprocess.py: no entry '{name}'")
    return values[-1].strip()


def expand(path):
    """The text of a parameter file with its 'include FILE' lines replaced by the files (paths
    relative to the working directory, as perideal-solid reads them)."""
    with open(path) as f:
        text = f.read()
    return re.sub(r"^\s*include\s+(\S+)\s*$", lambda m: expand(m.group(1)), text,
                  flags=re.MULTILINE)


def read(directory):
    prm = expand(f"{directory}/run.prm")
    with open(f"{directory}/statistics.csv") as f:
        rows = list(csv.DictReader(f))
    dx = float(entry(prm, "Lattice spacing"))
    E = float(entry(prm, "Young's modulus"))
    G = float(entry(prm, "Fracture energy"))
    B = float(entry(prm, "Thickness"))
    delta = float(entry(prm, "Horizon factor")) * dx
    # The load line is the pin column x = dx/2; the back edge and the notch tip from the file.
    specimen = prm[prm.index("subsection specimen\n"):]
    back = float(entry(specimen[:specimen.index("end")], "Upper corner").split(",")[0])
    tip = float(entry(prm, "Cracks").split(":")[1].split(",")[0])
    W, a = back - dx / 2, tip - dx / 2
    lefm = math.sqrt(E * G) * B * math.sqrt(W) / astm_f(a / W)
    load = [abs(float(r["load"])) for r in rows]
    return {
        "name": directory.rstrip("/").split("/")[-1], "dx": dx, "delta": delta, "W": W, "a": a,
        "lefm": lefm, "load": load,
        "opening": [2 * float(r["load_point_displacement"]) for r in rows],
        "crack": [float(r["crack_length"]) - float(rows[0]["crack_length"]) for r in rows],
        "factor": [float(r["time"]) for r in rows], "peak": max(load),
    }


def main():
    args = sys.argv[1:]
    prefix = None
    if "--plot" in args:
        prefix = args[args.index("--plot") + 1]
        del args[args.index("--plot"):args.index("--plot") + 2]
    if not args:
        raise SystemExit(__doc__)
    runs = [read(d) for d in args]
    print(f"{'run':<16} {'dx [mm]':>8} {'delta [mm]':>10} {'events':>7} {'peak [N]':>10} "
          f"{'LEFM [N]':>10} {'PD/LEFM':>8} {'falls':>6}")
    for r in runs:
        peak_at = r["load"].index(r["peak"])
        falls = sum(1 for k in range(peak_at + 1, len(r["factor"]))
                    if r["factor"][k] < r["factor"][k - 1])
        print(f"{r['name']:<16} {r['dx'] * 1e3:8.2f} {r['delta'] * 1e3:10.3f} "
              f"{len(r['load']) - 1:7d} {r['peak']:10.2f} {r['lefm']:10.2f} "
              f"{r['peak'] / r['lefm']:8.4f} {falls:6d}")
    if prefix:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6, 4.5))
        for r in runs:
            ax.plot([u * 1e6 for u in r["opening"]], r["load"], lw=1, label=r["name"])
        ax.axhline(runs[0]["lefm"], color="k", ls="--", lw=0.8, label="LEFM peak (ASTM E399)")
        ax.set_xlabel("load-line displacement [um]")
        ax.set_ylabel("load [N]")
        ax.set_title("Compact tension, sequentially linear control")
        ax.legend()
        fig.tight_layout()
        fig.savefig(f"{prefix}_load.png", dpi=120)
        fig, ax = plt.subplots(figsize=(6, 4.5))
        for r in runs:
            ax.plot(r["load"], [c * 1e3 for c in r["crack"]], lw=1, label=r["name"])
        ax.axhline((runs[0]["W"] - runs[0]["a"]) * 1e3, color="k", ls=":", lw=0.8,
                   label="ligament W - a")
        ax.axvline(runs[0]["lefm"], color="k", ls="--", lw=0.8, label="LEFM peak")
        ax.set_xlabel("load [N]")
        ax.set_ylabel("crack growth (crack-length measure) [mm]")
        ax.legend()
        fig.tight_layout()
        fig.savefig(f"{prefix}_crack.png", dpi=120)
    print(f"peak load ratio (PD/LEFM): {runs[0]['peak'] / runs[0]['lefm']:.4f}")


if __name__ == "__main__":
    main()
