#!/usr/bin/env python3
"""Cracked plate, coupled FE-PD against full PD: crack opening and far field.

usage: postprocess.py RESULTS_COUPLED RESULTS_FULL_PD [--plot cod_profile.png] [--no-crack]

Reads the final particle output (particles_*.h5) of both runs, the FE output (solution_*.h5) of
the coupled run and the last row of both statistics.csv files, and prints

- the crack-opening displacement COD(x) = u_y(x, y_c + dx/2) - u_y(x, y_c - dx/2) of the particle
  rows next to the crack line y_c, coupled against full PD, over the crack faces |x - x_c| < a:
  the largest and the L2 difference relative to the largest full-PD COD, and the largest at equal
  load (the coupled COD scaled by the ratio of the top reactions, full PD over coupled);
- the far field: at every full-PD particle of the plate where the coupled run has no particle
  (FE only), the coupled FE field (Q1 on the structured mesh, interpolated bilinearly) against
  the full-PD displacement: largest |du| over the largest |u| there, and the L2 ratio; the same
  over the interior (points at least 10 mm from the plate's edges), and on the two free lateral
  edges (particle columns x = dx/2 and W - dx/2) for u_x;
- the reaction on the top edge of both runs.

--no-crack leaves out the crack opening (runs without the pre-crack, for the far-field floor).

With --plot it draws both COD profiles and the LEFM opening of a central crack of half-length a
in an infinite plate under the remote stress sigma = reaction / (W t), plane stress:
COD(x) = 4 sigma / E sqrt(a^2 - (x - x_c)^2) (Tada, Paris & Irwin, The Stress Analysis of Cracks
Handbook, 3rd ed., 2000, sec. 5.1). The finite plate with clamped grips is not that problem: the
curve is a reference for the shape and the magnitude, not an exact solution.
"""
import argparse
import csv
import glob

import h5py
import numpy as np

# The geometry and material of coupled.prm and full_pd.prm.
WIDTH, THICKNESS, YOUNG = 0.1, 1e-3, 200e9
DX = 1e-3
X_CENTRE, Y_CRACK, HALF_LENGTH = 0.05, 0.05, 0.0102


def last_h5(directory, stem):
    """Nodes and displacement (2 components) of the last output step named stem_*.h5."""
    files = sorted(glob.glob(f"{directory}/{stem}_*.h5"))
    if not files:
        raise SystemExit(f"no {stem}_*.h5 in {directory}: run with <Output/Write HDF5> = true")
    with h5py.File(files[-1], "r") as h5:
        return np.asarray(h5["nodes"][:, :2], float), np.asarray(h5["displacement"][:, :2], float)


def reaction_top(directory):
    with open(f"{directory}/statistics.csv") as f:
        rows = list(csv.DictReader(f))
    return float(rows[-1]["reaction_top_y"])


def lattice_key(x, y):
    """Integer key of a point in half lattice spacings (particles sit at odd multiples)."""
    return int(round(x / DX * 2)), int(round(y / DX * 2))


def crack_opening(points, u):
    """x and COD of every particle column that has particles on both sides of the crack line."""
    by_key = {lattice_key(*p): v[1] for p, v in zip(points, u)}
    j_above, j_below = lattice_key(0, Y_CRACK + DX / 2)[1], lattice_key(0, Y_CRACK - DX / 2)[1]
    xs, cod = [], []
    for (i, j), uy in sorted(by_key.items()):
        if j == j_above and (i, j_below) in by_key:
            xs.append(i * DX / 2)
            cod.append(uy - by_key[(i, j_below)])
    return np.array(xs), np.array(cod)


def fe_field(nodes, u):
    """The cell size h of the structured FE mesh (uniform, square cells) and its nodal values as
    a dict (i, j) -> u."""
    h = np.diff(np.unique(np.round(nodes[:, 0], 9))).min()
    return h, {(int(round(p[0] / h)), int(round(p[1] / h))): v for p, v in zip(nodes, u)}


def interpolate(field, p):
    """The Q1 field of the structured mesh at p (bilinear in the cell that contains p)."""
    h, grid = field
    i, j = int(p[0] // h), int(p[1] // h)
    s, t = p[0] / h - i, p[1] / h - j
    return ((1 - s) * (1 - t) * grid[(i, j)] + s * (1 - t) * grid[(i + 1, j)]
            + (1 - s) * t * grid[(i, j + 1)] + s * t * grid[(i + 1, j + 1)])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("coupled")
    parser.add_argument("full_pd")
    parser.add_argument("--plot", help="write the COD profiles to this PNG file")
    parser.add_argument("--no-crack", action="store_true", help="far field and reactions only")
    args = parser.parse_args()

    xc, uc = last_h5(args.coupled, "particles")
    xp, up = last_h5(args.full_pd, "particles")
    xf, uf = last_h5(args.coupled, "solution")
    r_c, r_p = reaction_top(args.coupled), reaction_top(args.full_pd)
    print(f"top reaction: coupled {r_c:.6e} N, full PD {r_p:.6e} N, "
          f"relative difference {(r_c - r_p) / r_p:.3e}")
    far_field(xc, xp, up, xf, uf)
    if not args.no_crack:
        crack(xc, uc, xp, up, r_c, r_p, args.plot)


def crack(xc, uc, xp, up, r_c, r_p, plot):
    """Print the crack-opening differences; draw the profiles to the file plot if given."""
    x_cod_c, cod_c = crack_opening(xc, uc)
    x_cod_p, cod_p = crack_opening(xp, up)
    faces = lambda xs: np.abs(xs - X_CENTRE) < HALF_LENGTH
    pd_by_x = dict(zip(np.round(x_cod_p / DX * 2).astype(int), cod_p))
    on_faces = x_cod_c[faces(x_cod_c)]
    reference = np.array([pd_by_x[int(round(x / DX * 2))] for x in on_faces])
    difference = cod_c[faces(x_cod_c)] - reference
    print(f"COD points on the crack faces: {len(on_faces)}")
    print(f"COD at the centre: coupled {np.interp(X_CENTRE, x_cod_c, cod_c):.6e} m, "
          f"full PD {np.interp(X_CENTRE, x_cod_p, cod_p):.6e} m")
    print(f"COD difference, largest / largest full-PD COD: "
          f"{np.abs(difference).max() / np.abs(reference).max():.3e}")
    print(f"COD difference, L2 / L2 of the full-PD COD: "
          f"{np.linalg.norm(difference) / np.linalg.norm(reference):.3e}")
    equal_load = cod_c[faces(x_cod_c)] * r_p / r_c - reference
    print(f"COD difference at equal load, largest / largest full-PD COD: "
          f"{np.abs(equal_load).max() / np.abs(reference).max():.3e}")
    if plot:
        draw(x_cod_c, cod_c, x_cod_p, cod_p, r_p, plot)


def far_field(xc, xp, up, xf, uf):
    """Print the far-field differences: full-PD particles where the coupled run is FE only."""
    coupled_particles = {lattice_key(*p) for p in xc}
    grid = fe_field(xf, uf)
    in_plate = (xp[:, 1] > 0) & (xp[:, 1] < WIDTH)
    far = np.array([in_plate[k] and lattice_key(*xp[k]) not in coupled_particles
                    for k in range(len(xp))])
    u_fe = np.array([interpolate(grid, p) for p in xp[far]])
    du = np.linalg.norm(u_fe - up[far], axis=1)
    u_ref = np.linalg.norm(up[far], axis=1)
    print(f"far-field points: {far.sum()}")
    print(f"far-field difference, largest |du| / largest |u|: {du.max() / u_ref.max():.3e}")
    print(f"far-field difference, L2 / L2 of |u|: {np.linalg.norm(du) / np.linalg.norm(u_ref):.3e}")
    p = xp[far]
    inner = np.all((p > 0.01) & (p < WIDTH - 0.01), axis=1)
    print(f"interior far field (>= 10 mm from the edges), points: {inner.sum()}; largest |du| / "
          f"largest |u|: {du[inner].max() / u_ref.max():.3e}; L2 / L2 of |u|: "
          f"{np.linalg.norm(du[inner]) / np.linalg.norm(u_ref[inner]):.3e}")
    edges = far & ((np.abs(xp[:, 0] - DX / 2) < DX / 4) | (np.abs(xp[:, 0] - WIDTH + DX / 2) < DX / 4))
    ux_fe = np.array([interpolate(grid, p)[0] for p in xp[edges]])
    ux_pd = up[edges, 0]
    print(f"lateral edges, largest |u_x| (full PD): {np.abs(ux_pd).max():.6e} m; difference "
          f"largest / largest: {np.abs(ux_fe - ux_pd).max() / np.abs(ux_pd).max():.3e}")


def draw(x_cod_c, cod_c, x_cod_p, cod_p, r_p, plot):
    """Both COD profiles and the LEFM opening at the full-PD run's remote stress."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    sigma = r_p / (WIDTH * THICKNESS)
    xs = np.linspace(X_CENTRE - HALF_LENGTH, X_CENTRE + HALF_LENGTH, 401)
    lefm = 4 * sigma / YOUNG * np.sqrt(np.maximum(HALF_LENGTH**2 - (xs - X_CENTRE) ** 2, 0))
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.plot(x_cod_p * 1e3, cod_p * 1e6, "o", ms=3, label="full PD")
    ax.plot(x_cod_c * 1e3, cod_c * 1e6, "x", ms=4, label="coupled FE-PD")
    ax.plot(xs * 1e3, lefm * 1e6, "-", lw=1,
            label=f"LEFM, infinite plate, $\\sigma$ = {sigma / 1e6:.1f} MPa")
    ax.set_xlim((X_CENTRE - 2 * HALF_LENGTH) * 1e3, (X_CENTRE + 2 * HALF_LENGTH) * 1e3)
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("u_y(y = 50.5 mm) - u_y(y = 49.5 mm) [um]")
    ax.set_title("Crack opening, central crack 2a = 20.4 mm, plate 100 mm x 100 mm")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(plot, dpi=120)
    print(f"plot: {plot}")


if __name__ == "__main__":
    main()
