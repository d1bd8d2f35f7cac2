"""Errors of one run of the thermal-stress disk (README.md) against the closed form
u = alpha DeltaT0 (5/6 - r^2 / (3 b^2)) r: the largest and the root-mean-square displacement
error over the particles and over the FE nodes outside the PD-only core (r >= 20 mm, where the
FE field carries the body; inside it the FE nodes of the cells that reach beta = 1 have almost
no weight and no meaning), each relative to the largest exact displacement. Prints
'particle_max,particle_rms,fe_max,fe_rms' (empty FE columns without an FE region)."""
import glob
import sys

import h5py
import numpy as np

b, scale, core = 0.05, 1e-3, 0.02
largest = scale * (5 / 6 - 1 / 3) * b


def errors(filename, mask=None):
    with h5py.File(filename, "r") as h:
        x, u = h["nodes"][:, :2], h["displacement"][:, :2]
    r = np.hypot(x[:, 0], x[:, 1])
    exact = (scale * (5 / 6 - r**2 / (3 * b * b)))[:, None] * x
    e = np.linalg.norm(u - exact, axis=1)
    if mask is not None:
        e = e[mask(r)]
    return e.max() / largest, np.sqrt(np.mean(e**2)) / largest


directory = sys.argv[1]
pd = errors(sorted(glob.glob(directory + "/particles_0*.h5"))[-1])
fe_files = sorted(glob.glob(directory + "/solution_0*.h5"))
fe = errors(fe_files[-1], lambda r: r >= core) if fe_files else ("", "")
print(",".join(str(v) for v in (*pd, *fe)))
