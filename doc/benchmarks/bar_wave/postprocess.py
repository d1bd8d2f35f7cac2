#!/usr/bin/env python3
"""Post-processing of the bar_wave benchmark: the speed of the right-going pulse.

Reads the first and the last particle file of a result directory (HDF5 written by deal.II:
'nodes' are the reference positions, 'displacement' is padded to 3 components) and the end time
from statistics.csv. Two estimates of the PD bar speed c relative to c0 = sqrt(E/rho):

  centroid:  c/c0 = (X(T) - x0) / (c0 T), X the centroid of u_x over the particles with
             x > x0 + c0 T/2 (the right-going pulse). For any linear dispersion relation the
             centroid of a one-directional pulse moves at d omega/dk (k = 0), the long-wave
             speed: lattice and horizon dispersion do not bias it.
  amplitude: the initial state, built with c0, splits into a right-going part (1 + c0/c)/2 and
             a left-going part (1 - c0/c)/2 of the pulse; with R = sum u_x(T) (window) / sum
             u_x(0), c/c0 = 1/(2R - 1).

Usage: postprocess.py DIR [--x0 0.18] [--c0 5000]
Needs numpy and h5py (Debian: python3-numpy python3-h5py).
"""

import argparse
import glob
import os
import re

import h5py
import numpy as np


def particle_files(directory):
    files = glob.glob(os.path.join(directory, "particles_*.h5"))
    return sorted(files, key=lambda f: int(re.findall(r"(\d+)\.h5$", f)[0]))


def speed_ratios(directory, x0=0.18, c0=5000.0):
    """(centroid estimate, amplitude estimate, right-going part R, end time)."""
    files = particle_files(directory)
    with h5py.File(files[0], "r") as f:
        u0 = f["displacement"][:, 0]
    with h5py.File(files[-1], "r") as f:
        x = f["nodes"][:, 0]
        u = f["displacement"][:, 0]
    end_time = np.genfromtxt(os.path.join(directory, "statistics.csv"), delimiter=",", names=True)["time"][-1]
    window = x > x0 + 0.5 * c0 * end_time
    centroid = np.sum(x[window] * u[window]) / np.sum(u[window])
    right = np.sum(u[window]) / np.sum(u0)
    return (centroid - x0) / (c0 * end_time), 1.0 / (2.0 * right - 1.0), right, end_time


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("directory")
    parser.add_argument("--x0", type=float, default=0.18, help="initial pulse centre [m]")
    parser.add_argument("--c0", type=float, default=5000.0, help="sqrt(E/rho) [m/s]")
    args = parser.parse_args()
    centroid, amplitude, right, end_time = speed_ratios(args.directory, args.x0, args.c0)
    print(f"end time {end_time:.4e} s, right-going part of the pulse {right:.5f}")
    print(f"speed / sqrt(E/rho): centroid {centroid:.4f}, amplitude split {amplitude:.4f}")
    print(f"within 2 %: {'yes' if abs(centroid - 1) < 0.02 and abs(amplitude - 1) < 0.02 else 'NO'}")


if __name__ == "__main__":
    main()
