#!/usr/bin/env python3
"""Width and model study of the bar_wave benchmark (the table of README.md).

Writes a parameter file per case (the set-up of bar_wave.prm with another model, strip width,
lattice spacing, pulse width or surface correction), runs perideal-solid on it in
WORKDIR/<case>/ and prints the two speed estimates of postprocess.py. About 1 min per 10^4
particle-steps x 10^3 on one core; all cases together take about 2 min, lps_W80 alone about 80 s.

Usage: study.py [--bin PATH/perideal-solid] [--workdir DIR] [--only NAME,...]
"""

import argparse
import os
import subprocess

import numpy as np

from postprocess import speed_ratios

E, RHO, A, HORIZON_FACTOR, END_TIME = 200e9, 8000.0, 1e-6, 3.015, 6e-5
C0 = np.sqrt(E / RHO)

# name: model, Poisson ratio, dx [m], strip width W [m], pulse width w [m], surface correction
CASES = {
    "pmb_W10": ("bond based", 1 / 3, 1e-3, 0.01, 0.06, True),
    "pmb_W20": ("bond based", 1 / 3, 1e-3, 0.02, 0.06, True),
    "pmb_W20_w30": ("bond based", 1 / 3, 1e-3, 0.02, 0.03, True),
    "pmb_W40": ("bond based", 1 / 3, 0.5e-3, 0.02, 0.06, True),
    "pmb_W20_no_correction": ("bond based", 1 / 3, 1e-3, 0.02, 0.06, False),
    "lps_W10": ("linear peridynamic solid", 0.3, 1e-3, 0.01, 0.06, True),
    "lps_W20": ("linear peridynamic solid", 0.3, 1e-3, 0.02, 0.06, True),
    "lps_W40": ("linear peridynamic solid", 0.3, 0.5e-3, 0.02, 0.06, True),
    "lps_W80": ("linear peridynamic solid", 0.3, 0.25e-3, 0.02, 0.06, True),
    "lps_W20_no_correction": ("linear peridynamic solid", 0.3, 1e-3, 0.02, 0.06, False),
}


def parameter_file(model, nu, dx, width, w, correction):
    x0 = 3 * w
    length = x0 + C0 * END_TIME + 3.5 * w
    yc = width / 2
    g = f"exp(-((x-{x0})/{w})^2)"
    dg = f"(-2*(x-{x0})/{w}^2*{g})"
    ddg = f"(-(2/{w}^2)*(1-2*((x-{x0})/{w})^2)*{g})"
    return f"""set Dimension = 2
subsection Discretization
  set Lattice spacing = {dx}
  set Horizon factor = {HORIZON_FACTOR}
  set Thickness = 1e-3
  set Surface correction = {'true' if correction else 'false'}
  set Body = bar
end
subsection Regions
  set Names = bar
  subsection bar
    set Lower corner = 0, 0
    set Upper corner = {length:.6f}, {width}
  end
end
subsection Material
  set Model = {model}
  set Density = {RHO}
  subsection bond based
    set Young's modulus = {E}
  end
  subsection linear peridynamic solid
    set Young's modulus = {E}
    set Poisson's ratio = {nu}
  end
end
subsection Initial conditions
  set Displacement = {A}*{g}; -{nu}*{A}*{dg}*(y-{yc})
  set Velocity = -{C0}*{A}*{dg}; {nu}*{C0}*{A}*{ddg}*(y-{yc})
end
subsection Time stepping
  set End time = {END_TIME}
end
subsection Output
  set Directory = .
  set Statistics interval = 100
  set Progress = false
end
""", x0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bin", default="perideal-solid")
    parser.add_argument("--workdir", default="bar_wave_study")
    parser.add_argument("--only", default=None)
    args = parser.parse_args()
    names = args.only.split(",") if args.only else list(CASES)
    print("| case | model | W/delta | w/delta | surface correction | c/c0 (centroid) | c/c0 (amplitude) |")
    print("|---|---|---|---|---|---|---|")
    for name in names:
        model, nu, dx, width, w, correction = CASES[name]
        text, x0 = parameter_file(model, nu, dx, width, w, correction)
        directory = os.path.join(args.workdir, name)
        os.makedirs(directory, exist_ok=True)
        with open(os.path.join(directory, "bar.prm"), "w") as f:
            f.write(text)
        subprocess.run([args.bin, "bar.prm"], cwd=directory, check=True, stdout=subprocess.DEVNULL)
        centroid, amplitude, _, _ = speed_ratios(directory, x0, C0)
        delta = HORIZON_FACTOR * dx
        print(f"| {name} | {model}, nu = {nu:.3g} | {width / delta:.1f} | {w / delta:.1f} | "
              f"{'on' if correction else 'off'} | {centroid:.4f} | {amplitude:.4f} |", flush=True)


if __name__ == "__main__":
    main()
