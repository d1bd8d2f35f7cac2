#!/usr/bin/env python3
"""The fracture energy of PMB's discrete square lattice against G_c (issue #40, a lead checked).

Breaking every bond across a straight line of a 2D square lattice (spacing dx, horizon m dx)
dissipates G_lattice = f * C_lattice / C_continuum * G_c, where
- C is the sum (integral) of |xi| beta over the bonds that cross the line, per unit length: the
  critical stretch s0 = sqrt(4 pi G_c / (9 E delta)) is calibrated with the continuum integral;
- beta is the partial-volume factor ('none': 1 inside the horizon; 'book', the default:
  (delta + dx/2 - |xi|) / dx beyond delta - dx/2);
- f is the interior bond factor of the energy surface correction, which scales every interior
  bond so that the lattice gives the continuum's C_1111 (f_C1111) or the isotropic expansion's
  energy (f_iso) at an unchanged s0.
LEFM's peak load scales with sqrt(G), so sqrt(G_lattice / G_c) is the peak ratio that the lattice
alone would explain. usage: python3 lattice_energy.py
"""

import math


def beta(rule, r, delta, dx):
    if r > delta:
        return 0.0
    if rule == "book" and r > delta - dx / 2:
        return (delta + dx / 2 - r) / dx
    return 1.0


def simpson(f, a, b, n=400):
    h = (b - a) / n
    return h / 3 * sum((1 if k in (0, n) else 4 if k % 2 else 2) * f(a + k * h)
                       for k in range(n + 1))


def ratios(m, rule):
    dx, delta = 1.0, m
    n = int(math.ceil(m)) + 1
    bonds = [(a, b) for a in range(-n, n + 1) for b in range(-n, n + 1) if (a, b) != (0, 0)]
    r = {ab: math.hypot(*ab) for ab in bonds}
    # Interior factors: continuum over lattice, per unit dx^2.
    f_iso = (2 * math.pi * delta ** 3 / 3) / sum(r[ab] * beta(rule, r[ab], delta, dx)
                                                 for ab in bonds)
    f_c1111 = (math.pi * delta ** 3 / 4) / sum(
        r[ab] * (ab[0] / r[ab]) ** 4 * beta(rule, r[ab], delta, dx) for ab in bonds)
    # Bonds across the line y = 0 from one column of particles at y = -(k + 1/2) dx.
    crossing = sum(r[(a, b)] * beta(rule, r[(a, b)], delta, dx)
                   for k in range(n + 1) for (a, b) in bonds if b - (k + 0.5) > 0)
    # Continuum: int_0^delta dz int_{xi_y > z, |xi| < delta} |xi| dA.
    continuum = simpson(lambda z: simpson(
        lambda s: s * s * 2 * math.acos(min(1.0, z / s)) if s > z else 0.0, z, delta, 200),
        0.0, delta, 200)
    return f_iso, f_c1111, crossing / continuum


if __name__ == "__main__":
    print("| partial volumes | m | C_lattice / C_continuum | f_C1111 | f_iso | "
          "G_lattice / G_c (f_C1111) | sqrt |")
    print("|---|---|---|---|---|---|---|")
    for rule in ("none", "book"):
        for m in (2.015, 3.015, 4.015):
            f_iso, f_c1111, c = ratios(m, rule)
            g = c * (f_c1111 if rule == "book" else 1.0)
            print(f"| {rule} | {m} | {c:.3f} | {f_c1111:.3f} | {f_iso:.3f} | {g:.3f} | "
                  f"{math.sqrt(g):.3f} |")
