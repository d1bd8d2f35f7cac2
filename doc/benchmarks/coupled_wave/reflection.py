#!/usr/bin/env python3
"""Reflection of the blended overlap: the coupled strip's displacement at the last output minus
the FE-only reference's, in the region x < 60 mm that only reflected waves can reach.

usage: reflection.py RESULTS_COUPLED RESULTS_FE_REFERENCE
Prints the largest difference against the incident amplitude (1 um) and the ratio of the sums of
squares (difference over the incident pulse at t = 0), an energy-like reflected fraction.
"""
import glob
import sys

import h5py
import numpy as np


def step(directory, index):
    with h5py.File(sorted(glob.glob(directory + "/solution_*.h5"))[index], "r") as h5:
        return h5["nodes"][:], h5["displacement"][:]


coupled, reference = sys.argv[1], sys.argv[2]
xc, uc = step(coupled, -1)
xr, ur = step(reference, -1)
key = lambda p: (round(float(p[0]), 7), round(float(p[1]), 7))
by_point = {key(p): v for p, v in zip(xr, ur)}
du = np.array([v - by_point[key(p)] for p, v in zip(xc, uc) if p[0] < 0.06])
_, u0 = step(reference, 0)
print(f"nodes compared (x < 60 mm): {len(du)}")
print(f"reflected amplitude / incident amplitude: {np.abs(du).max() / 1e-6:.4f}")
print(f"reflected fraction (sum du^2 / sum u0^2): {(du ** 2).sum() / (u0 ** 2).sum():.2e}")
