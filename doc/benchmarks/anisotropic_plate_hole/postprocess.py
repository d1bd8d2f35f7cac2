#!/usr/bin/env python3
"""Anisotropic plate with a hole: PD generalized plane stress against plane-stress FE.

usage: postprocess.py RESULTS_DIR [--plot-dir DIR] [--fe fe_r2]

Reads, for every material of materials.MATERIALS found in RESULTS_DIR, the last particle output
(particles_*.h5) of each pd_* run and the FE output (solution_*.h5) of the FE run (--fe), and
prints (as Markdown tables):

- per PD run, the displacement of the plate's particles (the layers excluded) against the FE
  field interpolated there (linear on the FE output's vertices, split into triangles; Q2 vertex
  values on a mesh of 0.25 mm at the hole): the relative L2 difference ||u_PD - u_FE|| / ||u_FE||
  over all particles and over the interior (particles at least one horizon from the free edges,
  the hole and the loaded edges), the same relative to the hole's perturbation of the far field,
  ||u_PD - u_FE|| / ||u_FE - u_far|| (u_far = eps . (x - c), the prescribed uniform field), the
  largest |u_PD - u_FE| over the largest |u_FE|, the out-of-plane strain eps_33 of the model
  (-A) against -C_33ab eps_ab / C_3333 of the FE strain (relative L2, interior), and the x
  reaction of the right layer against the FE reaction on the right edge;
- per pd_*_nohole run, the particle displacement of the plate without the hole against u_far
  (the exact solution): the floor the free edges and the layers leave;
- the hoop stress sigma_tt / sigma at the hole: the FE's own stress at the hole's vertices, the
  same estimate (a quadratic least-squares fit of u over the particles within 3 dx of the hole
  point, sigma_tt = eps_tt E_t with E_t the reduced Young's modulus along the tangent, exact on a
  traction-free boundary) from the PD displacement and from the FE displacement at the same
  particles, and Lekhnitskii's infinite plate; the largest value and its angle (the fits
  averaged over 9 degrees first).

Plots (into --plot-dir, default the directory of this script): lines.png (u_x - u_far,x on the
horizontal line through the centre, u_y - u_far,y on the vertical line, PD dx = 1 and 0.5 mm
against FE), contours.png (u_x and u_y, FE solid and PD dx = 0.5 mm dashed, every material),
fields.png (the main case at dx = 0.5 mm: perturbation fields PD, FE and PD - FE), hoop.png (the
fits averaged over 9 degrees).

Diagnostic: fe_r*_a<mm> runs (FE with another hole radius) against every PD run, over the
particles outside that hole: the PD runs match an FE hole about 0.4 dx larger.
Needs numpy, scipy, h5py, matplotlib (/usr/bin/python3).
"""
import argparse
import csv
import glob
import math
import os
import re
import sys

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import materials  # noqa: E402
from cases import A, CENTRE, L, REMOTE_STRESS  # noqa: E402

HORIZON_FACTOR = 3.015   # <Discretization/Horizon factor> of plate_hole_pd.prm
THICKNESS = 5e-4         # <Discretization/Thickness> [m]
MAIN = "orthotropic_30"


def last_h5(directory, stem):
    files = sorted(glob.glob(os.path.join(directory, f"{stem}_*.h5")))
    if not files:
        raise SystemExit(f"postprocess.py: no {stem}_*.h5 in {directory}")
    with h5py.File(files[-1], "r") as h5:
        return {k: np.asarray(h5[k]) for k in h5}


def statistics(directory):
    with open(os.path.join(directory, "statistics.csv")) as f:
        return list(csv.DictReader(f))[-1]


def far_field(entries, x):
    exx, eyy, exy = materials.far_strain(entries, REMOTE_STRESS)
    X, Y = x[:, 0] - CENTRE, x[:, 1] - CENTRE
    return np.column_stack([exx * X + exy * Y, exy * X + eyy * Y])


class FEField:
    """The FE output as a linear interpolant on its vertices (quads split into triangles)."""

    def __init__(self, directory):
        import matplotlib.tri as mtri
        from scipy.spatial import cKDTree
        d = last_h5(directory, "solution")
        nodes = d["nodes"][:, :2]
        # Vertices shared by the ranks' outputs appear once per rank: merge them.
        keys = np.round(nodes / 1e-9).astype(np.int64)
        _, first, inverse = np.unique(keys, axis=0, return_index=True, return_inverse=True)
        inverse = inverse.ravel()
        self.nodes = nodes[first]
        self.values = {k: (v[first] if v.ndim == 1 else v[first]) for k, v in d.items()
                       if k not in ("nodes", "cells") and len(v) == len(nodes)}
        quads = inverse[d["cells"].astype(np.int64)]
        triangles = np.vstack([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
        self.triangulation = mtri.Triangulation(self.nodes[:, 0], self.nodes[:, 1], triangles)
        self.finder = self.triangulation.get_trifinder()
        self.tree = cKDTree(self.nodes)
        self.interpolators = {}

    def __call__(self, name, x, component=0):
        import matplotlib.tri as mtri
        v = self.values[name]
        v = v[:, component] if v.ndim > 1 else v
        key = (name, component)
        if key not in self.interpolators:
            self.interpolators[key] = mtri.LinearTriInterpolator(self.triangulation, v,
                                                                 trifinder=self.finder)
        out = np.asarray(self.interpolators[key](x[:, 0], x[:, 1]))
        out = np.ma.filled(np.ma.masked_invalid(out), np.nan)
        missing = np.isnan(out)
        if missing.any():  # a particle a hair outside the polygon of the curved hole
            out[missing] = v[self.tree.query(x[missing])[1]]
        return out

    def displacement(self, x):
        return np.column_stack([self("displacement", x, 0), self("displacement", x, 1)])


def lattice_grid(pd, values):
    """The particle values on the lattice as a 2D array (NaN where there is no particle) and
    the extent of its cells [mm], for imshow and contour."""
    i = np.round(pd.x[:, 0] / pd.dx - 0.5).astype(int)
    j = np.round(pd.x[:, 1] / pd.dx - 0.5).astype(int)
    grid = np.full((j.max() + 1, i.max() + 1), np.nan)
    grid[j, i] = values
    return grid, (0, (i.max() + 1) * pd.dx * 1e3, 0, (j.max() + 1) * pd.dx * 1e3)


class PDRun:
    def __init__(self, directory):
        d = last_h5(directory, "particles")
        x = d["nodes"][:, :2]
        plate = (x[:, 0] > 0) & (x[:, 0] < L)  # the layers lie outside [0, L]
        self.x, self.u = x[plate], d["displacement"][plate, :2]
        self.eps33 = d["out_of_plane_strain"].ravel()[plate]
        xs = np.unique(np.round(self.x[:, 0], 10))
        self.dx = float(np.min(np.diff(xs)))
        self.horizon = HORIZON_FACTOR * self.dx
        self.stats = statistics(directory)

    def interior(self, hole=True):
        x, d = self.x, self.horizon
        r = np.hypot(x[:, 0] - CENTRE, x[:, 1] - CENTRE)
        keep = (x[:, 0] > d) & (x[:, 0] < L - d) & (x[:, 1] > d) & (x[:, 1] < L - d)
        return keep & (r > A + d) if hole else keep


def rel(a, b):
    return float(np.linalg.norm(a) / np.linalg.norm(b))


def fe_eps33(fe, entries, x):
    C = materials.global_tensor(entries)
    e11, e22, e12 = fe("strain_xx", x), fe("strain_yy", x), fe("strain_xy", x)
    return -(C[2, 2, 0, 0] * e11 + C[2, 2, 1, 1] * e22 + 2 * C[2, 2, 0, 1] * e12) / C[2, 2, 2, 2]


def compare(pd, fe, entries):
    u_fe = fe.displacement(pd.x)
    du = pd.u - u_fe
    pert = u_fe - far_field(entries, pd.x)
    inner = pd.interior()
    e33 = fe_eps33(fe, entries, pd.x)
    return {
        "n": len(pd.x),
        "l2": rel(du, u_fe), "l2_in": rel(du[inner], u_fe[inner]),
        "pert": rel(du, pert), "pert_in": rel(du[inner], pert[inner]),
        "max": float(np.abs(du).max() / np.abs(u_fe).max()),
        "e33_in": rel(pd.eps33[inner] - e33[inner], e33[inner]),
        "e33_all": rel(pd.eps33 - e33, e33),
        "reaction": float(pd.stats["reaction_right_x"]),
    }


def hoop_fit(x, u, dx, entries, angles):
    """sigma_tt / sigma at the hole points of the angles from a quadratic fit of u."""
    r = np.hypot(x[:, 0] - CENTRE, x[:, 1] - CENTRE)
    ring = r < A + 3.5 * dx
    x, u = x[ring], u[ring]
    out = []
    for theta in angles:
        n = np.array([math.cos(theta), math.sin(theta)])
        p = np.array([CENTRE, CENTRE]) + A * n
        d = x - p
        near = np.hypot(d[:, 0], d[:, 1]) < 3 * dx
        X, Y = d[near, 0] / dx, d[near, 1] / dx
        M = np.column_stack([np.ones_like(X), X, Y, X * X, X * Y, Y * Y])
        coef = np.linalg.lstsq(M, u[near], rcond=None)[0]
        G = coef[1:3].T / dx  # G[i, j] = du_i/dx_j
        t = np.array([-n[1], n[0]])
        eps_tt = t @ G @ t
        out.append(eps_tt / materials.hoop_compliance(entries, theta) / REMOTE_STRESS)
    return np.array(out)


def fe_hoop(fe, entries):
    p = fe.nodes - CENTRE
    r = np.hypot(p[:, 0], p[:, 1])
    on = np.abs(r - A) < 1e-7
    theta = np.mod(np.arctan2(p[on, 1], p[on, 0]), 2 * math.pi)
    s, c = np.sin(theta), np.cos(theta)
    sxx, syy, sxy = (fe.values[k].ravel()[on] for k in ("stress_xx", "stress_yy", "stress_xy"))
    stt = sxx * s * s + syy * c * c - 2 * sxy * s * c
    order = np.argsort(theta)
    return theta[order], stt[order] / REMOTE_STRESS


def smooth(values, width=9):
    """Circular moving average over `width` samples (degrees here): the fits see a staircase
    of particles that changes from angle to angle."""
    kernel = np.ones(width) / width
    padded = np.concatenate([values[-(width // 2):], values, values[:width // 2]])
    return np.convolve(padded, kernel, mode="valid")


def peak(theta, values):
    i = int(np.argmax(values))
    return values[i], math.degrees(theta[i]) % 180


def pd_runs(results, material):
    runs = {}
    for path in glob.glob(os.path.join(results, material, "pd_dx*")):
        if os.path.isdir(path):
            runs[os.path.basename(path)] = path
    def key(name):
        m = re.match(r"pd_dx([0-9.]+)(.*)", name)
        return (m.group(2), -float(m.group(1)))
    return [(name, runs[name]) for name in sorted(runs, key=key)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("results")
    parser.add_argument("--plot-dir", default=HERE)
    parser.add_argument("--fe", default="fe_r2")
    args = parser.parse_args()
    results = os.path.abspath(args.results)
    found = [m for m in materials.MATERIALS
             if os.path.isdir(os.path.join(results, m, args.fe))]
    if not found:
        raise SystemExit(f"postprocess.py: no {args.fe} run in {results}")

    fes, pds, rows, floor, hoop = {}, {}, [], [], {}
    angles = np.radians(np.arange(0.0, 360.0, 1.0))
    for m in found:
        label, entries = materials.MATERIALS[m]
        fe = fes[m] = FEField(os.path.join(results, m, args.fe))
        fe_reaction = float(statistics(os.path.join(results, m, args.fe))["reaction_right_x"])
        hoop[m] = {"fe": fe_hoop(fe, entries),
                   "lekhnitskii": np.array([materials.lekhnitskii_hoop(entries, t)
                                            for t in angles])}
        for name, path in pd_runs(results, m):
            pd = PDRun(path)
            pds[(m, name)] = pd
            if name.endswith("_nohole"):
                u_far = far_field(entries, pd.x)
                inner = pd.interior(hole=False)
                # the hole's perturbation at the particles of the dx-matching hole run, for scale
                floor.append((m, name, {
                    "l2": rel(pd.u - u_far, u_far), "l2_in": rel(pd.u[inner] - u_far[inner],
                                                              u_far[inner]),
                    "max": float(np.abs(pd.u - u_far).max() / np.abs(u_far).max()),
                    "reaction": float(pd.stats["reaction_right_x"]),
                    "exact_reaction": REMOTE_STRESS * L * float(THICKNESS)}))
                continue
            r = compare(pd, fe, entries)
            r["fe_reaction"] = fe_reaction
            rows.append((m, name, r))
            if not name.endswith("_nosc"):
                u_fe = fe.displacement(pd.x)
                hoop[m][name] = (hoop_fit(pd.x, pd.u, pd.dx, entries, angles),
                                 hoop_fit(pd.x, u_fe, pd.dx, entries, angles))

    print("## PD against FE (%s), displacement at the particles\n" % args.fe)
    print("| material | run | particles | L2 all | L2 interior | L2 / perturbation, all | "
          "L2 / perturbation, interior | max | eps_33 L2 interior (all) | reaction PD / FE - 1 |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for m, name, r in rows:
        print(f"| {m} | {name} | {r['n']} | {100 * r['l2']:.3f} % | {100 * r['l2_in']:.3f} % | "
              f"{100 * r['pert']:.2f} % | {100 * r['pert_in']:.2f} % | {100 * r['max']:.3f} % | "
              f"{100 * r['e33_in']:.2f} % ({100 * r['e33_all']:.1f} %) | "
              f"{100 * (r['reaction'] / r['fe_reaction'] - 1):+.2f} % |")
    if floor:
        print("\n## The plate without the hole against the exact uniform field\n")
        print("| material | run | L2 all | L2 interior | max | reaction / (sigma L h) - 1 |")
        print("|---|---|---|---|---|---|")
        for m, name, r in floor:
            print(f"| {m} | {name} | {100 * r['l2']:.3f} % | {100 * r['l2_in']:.4f} % | "
                  f"{100 * r['max']:.3f} % | "
                  f"{100 * (r['reaction'] / r['exact_reaction'] - 1):+.2f} % |")
    print("\n## Hoop stress at the hole, largest sigma_tt / sigma and its angle (deg, mod 180)\n")
    names = sorted({k for m in hoop for k in hoop[m] if k.startswith("pd_")},
                   key=lambda n: -float(re.match(r"pd_dx([0-9.]+)", n).group(1)))
    head = "| material | FE (nodal stress) | Lekhnitskii (infinite plate) |"
    for n in names:
        head += f" PD {n[3:]} fit | FE fit at the same particles |"
    print(head)
    print("|---" * (3 + 2 * len(names)) + "|")
    for m in found:
        h = hoop[m]
        line = "| %s | %.3f at %.0f | %.3f at %.0f |" % ((m,) + peak(*h["fe"]) +
                                                       peak(angles, h["lekhnitskii"]))
        for n in names:
            if n in h:
                line += " %.3f at %.0f | %.3f at %.0f |" % (peak(angles, smooth(h[n][0])) +
                                                            peak(angles, smooth(h[n][1])))
            else:
                line += " | |"
        print(line)

    # The FE reference against a finer one (other fe_r* runs), at the particles of the finest
    # hole run of the material.
    checks = []
    for m in found:
        entries = materials.MATERIALS[m][1]
        for path in sorted(glob.glob(os.path.join(results, m, "fe_r*"))):
            if (not os.path.isdir(path) or os.path.basename(path) == args.fe
                    or "_a" in os.path.basename(path)):
                continue
            other = FEField(path)
            runs = [n for (mm, n) in pds if mm == m and not n.endswith(("_nohole", "_nosc"))]
            pd = pds[(m, min(runs, key=lambda n: float(n[5:])))]
            u, v = fes[m].displacement(pd.x), other.displacement(pd.x)
            pert = v - far_field(entries, pd.x)
            checks.append((m, os.path.basename(path), rel(u - v, v), rel(u - v, pert),
                           peak(*fe_hoop(other, entries))[0], peak(*hoop[m]["fe"])[0]))
    if checks:
        print("\n## The FE reference (%s) against a finer mesh\n" % args.fe)
        print("| material | finer run | L2 difference at the particles | relative to the "
              "perturbation | hoop stress peak, finer / reference |")
        print("|---|---|---|---|---|")
        for m, name, d, dp, fine, ref in checks:
            print(f"| {m} | {name} | {100 * d:.4f} % | {100 * dp:.3f} % | {fine:.4f} / {ref:.4f} |")

    # Diagnostic: the PD runs against FE with a larger hole (fe_r*_a<mm> runs), over the
    # particles outside the larger hole.
    enlarged = []
    for m in found:
        for path in sorted(glob.glob(os.path.join(results, m, "fe_r*_a*"))):
            if not os.path.isdir(path):
                continue
            radius = float(re.search(r"_a([0-9.]+)$", path).group(1)) * 1e-3
            other = FEField(path)
            for name in [n for (mm, n) in pds if mm == m and not n.endswith("_nohole")]:
                pd = pds[(m, name)]
                out = np.hypot(pd.x[:, 0] - CENTRE, pd.x[:, 1] - CENTRE) > radius
                u = other.displacement(pd.x[out])
                inner = pd.interior()[out]
                u_ref = fes[m].displacement(pd.x[out])
                enlarged.append((m, name, radius, rel(pd.u[out] - u_ref, u_ref),
                                 rel(pd.u[out] - u, u), rel(pd.u[out][inner] - u[inner], u[inner])))
    if enlarged:
        print("\n## Diagnostic: PD against FE with a larger hole (particles outside it)\n")
        print("| material | run | FE hole radius | L2 against a = 10 mm | L2 against it, all | "
              "interior |")
        print("|---|---|---|---|---|---|")
        for m, name, radius, ref, d, di in enlarged:
            print(f"| {m} | {name} | {radius * 1e3:g} mm | {100 * ref:.3f} % | {100 * d:.3f} % | "
                  f"{100 * di:.3f} % |")

    plots(args.plot_dir, found, fes, pds, hoop, angles)



def plots(directory, found, fes, pds, hoop, angles):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.tri as mtri

    um = 1e6
    # Lines through the centre: the mean of the two particle rows (columns) at c -+ dx/2.
    fig, axes = plt.subplots(len(found), 2, figsize=(11, 2.6 * len(found)), squeeze=False)
    for row, m in enumerate(found):
        entries = materials.MATERIALS[m][1]
        fe = fes[m]
        s = np.linspace(0, L, 801)
        s = s[np.abs(s - CENTRE) >= A]
        for col, (comp, name) in enumerate(((0, "u_x"), (1, "u_y"))):
            ax = axes[row, col]
            line = (np.column_stack([s, np.full_like(s, CENTRE)]) if comp == 0 else
                    np.column_stack([np.full_like(s, CENTRE), s]))
            v = fe.displacement(line)[:, comp] - far_field(entries, line)[:, comp]
            for part in (s < CENTRE, s > CENTRE):
                ax.plot(s[part] * 1e3, v[part] * um, "k-", lw=1.2,
                        label="FE" if part[0] else None)
            for name_run, marker in (("pd_dx1", "o"), ("pd_dx0.5", ".")):
                if (m, name_run) not in pds:
                    continue
                pd = pds[(m, name_run)]
                across = 1 - comp  # the coordinate across the line
                sel = {}
                for side in (-1, 1):
                    near = np.abs(pd.x[:, across] - (CENTRE + side * pd.dx / 2)) < pd.dx / 4
                    sel[side] = {round(p[comp] / pd.dx * 2): (p, u) for p, u in
                                 zip(pd.x[near], pd.u[near])}
                keys = sorted(set(sel[-1]) & set(sel[1]))
                pos = np.array([sel[-1][k][0][comp] for k in keys])
                val = np.array([0.5 * (sel[-1][k][1][comp] + sel[1][k][1][comp]) for k in keys])
                pts = np.array([0.5 * (sel[-1][k][0] + sel[1][k][0]) for k in keys])
                val = val - far_field(entries, pts)[:, comp]
                every = 2 if name_run == "pd_dx1" else 1
                ax.plot(pos[::every] * 1e3, val[::every] * um, marker, ms=4 if marker == "o" else 3,
                        mfc="none" if marker == "o" else None,
                        label="PD dx = %g mm" % (pd.dx * 1e3))
            ax.axvspan((CENTRE - A) * 1e3, (CENTRE + A) * 1e3, color="0.9")
            where = "y = 50 mm" if comp == 0 else "x = 50 mm"
            ax.set_title(f"{materials.MATERIALS[m][0]}: {name} - far field on {where}", fontsize=9)
            ax.set_xlabel("x [mm]" if comp == 0 else "y [mm]")
            ax.set_ylabel("[um]")
            ax.grid(alpha=0.3)
            if row == 0:
                ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "lines.png"), dpi=110)
    plt.close(fig)

    # Contours of u_x and u_y: FE solid, PD (finest hole run) dashed.
    fig, axes = plt.subplots(2, len(found), figsize=(3.2 * len(found), 6.4), squeeze=False)
    for col, m in enumerate(found):
        fe = fes[m]
        runs = [n for (mm, n) in pds if mm == m and not n.endswith(("_nohole", "_nosc"))]
        pd = pds[(m, "pd_dx0.5")] if (m, "pd_dx0.5") in pds else pds[(m, runs[0])]
        for row, comp in enumerate((0, 1)):
            ax = axes[row, col]
            v_fe = fe.values["displacement"][:, comp] * um
            levels = np.linspace(v_fe.min(), v_fe.max(), 17)[1:-1]
            mm = mtri.Triangulation(fe.nodes[:, 0] * 1e3, fe.nodes[:, 1] * 1e3,
                                    fe.triangulation.triangles)
            ax.tricontour(mm, v_fe, levels=levels, colors="k", linewidths=0.8)
            grid, extent = lattice_grid(pd, pd.u[:, comp] * um)
            h = pd.dx * 1e3
            gx = np.arange(grid.shape[1]) * h + h / 2
            gy = np.arange(grid.shape[0]) * h + h / 2
            ax.contour(gx, gy, np.ma.masked_invalid(grid), levels=levels, colors="r",
                       linewidths=0.8, linestyles="--")
            ax.add_patch(plt.Circle((CENTRE * 1e3, CENTRE * 1e3), A * 1e3, color="0.85"))
            ax.set_aspect("equal")
            ax.set_xticks([]), ax.set_yticks([])
            ax.set_title("%s\n%s (FE black, PD dx = %g mm red)" %
                         (materials.MATERIALS[m][0], "u_x" if comp == 0 else "u_y", pd.dx * 1e3),
                         fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "contours.png"), dpi=110)
    plt.close(fig)

    # The main case: the hole's perturbation of the far field, PD, FE, PD - FE.
    if MAIN in found:
        entries = materials.MATERIALS[MAIN][1]
        runs = [n for (mm, n) in pds if mm == MAIN and not n.endswith(("_nohole", "_nosc"))]
        pd = pds[(MAIN, "pd_dx0.5")] if (MAIN, "pd_dx0.5") in pds else pds[(MAIN, runs[0])]
        u_far = far_field(entries, pd.x)
        u_fe = fes[MAIN].displacement(pd.x)
        fig, axes = plt.subplots(2, 3, figsize=(12, 7.6))
        for row in range(2):
            a, b = (pd.u - u_far)[:, row] * um, (u_fe - u_far)[:, row] * um
            lim = np.abs(b).max()
            for col, (v, title, vmax) in enumerate(((a, "PD", lim), (b, "FE", lim),
                                                    (a - b, "PD - FE", np.abs(a - b).max()))):
                ax = axes[row, col]
                grid, extent = lattice_grid(pd, v)
                pc = ax.imshow(grid, origin="lower", extent=extent, cmap="RdBu_r", vmin=-vmax,
                               vmax=vmax, interpolation="nearest")
                fig.colorbar(pc, ax=ax, shrink=0.8, label="um")
                ax.set_xlabel("x [mm]")
                ax.set_ylabel("y [mm]")
                ax.set_title("%s: %s - far field at the particles (dx = %g mm)" %
                             (title, "u_x" if row == 0 else "u_y", pd.dx * 1e3), fontsize=9)
        fig.suptitle(materials.MATERIALS[MAIN][0])
        fig.tight_layout()
        fig.savefig(os.path.join(directory, "fields.png"), dpi=110)
        plt.close(fig)

    # Hoop stress around the hole, 0 to 180 degrees (the problem is symmetric under a half turn).
    n_col = 3
    n_row = (len(found) + n_col) // n_col
    fig, axes = plt.subplots(n_row, n_col, figsize=(4.2 * n_col, 3.4 * n_row), squeeze=False)
    deg = np.degrees(angles)
    half = deg <= 180
    handles = {}
    for k, m in enumerate(found):
        ax = axes[k // n_col, k % n_col]
        h = hoop[m]
        fe_half = np.degrees(h["fe"][0]) <= 180
        curves = [(np.degrees(h["fe"][0])[fe_half], h["fe"][1][fe_half],
                   dict(color="k", lw=1.4), "FE, stress at the hole's vertices"),
                  (deg[half], h["lekhnitskii"][half], dict(color="0.5", ls="--", lw=1),
                   "Lekhnitskii, infinite plate")]
        for n, color in (("pd_dx1", "C0"), ("pd_dx0.5", "C1"), ("pd_dx0.25", "C2")):
            if n in h:
                curves.append((deg[half], smooth(h[n][0])[half], dict(color=color, lw=1.1),
                               "PD dx = %s mm, fit" % n[5:]))
                curves.append((deg[half], smooth(h[n][1])[half], dict(color=color, lw=1, ls=":"),
                               "FE at the same particles, same fit (dx = %s mm)" % n[5:]))
        for x, y, style, label in curves:
            handles[label] = ax.plot(x, y, **style)[0]
        ax.set_xlim(0, 180)
        ax.set_xticks(range(0, 181, 30))
        ax.set_xlabel("angle on the hole from the x axis [deg]")
        ax.set_ylabel("sigma_tt / sigma")
        ax.set_title(materials.MATERIALS[m][0], fontsize=9)
        ax.grid(alpha=0.3)
    for k in range(len(found), n_row * n_col):
        axes[k // n_col, k % n_col].axis("off")
    axes[-1, -1].legend(list(handles.values()), list(handles.keys()), loc="center", fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "hoop.png"), dpi=110)
    plt.close(fig)

if __name__ == "__main__":
    main()
