#!/usr/bin/env python3
"""Elastic moduli of an interior particle of the square lattice, 2D plane-stress PMB (README.md,
"Where the remaining errors come from").

For a homogeneous strain the PMB energy density of an interior particle is
W = c/4 sum_j beta_j |xi_j| s_j^2 V_j, so in the small-strain limit
C11 = c/2 sum beta |xi| n_x^4 V, C12 = c/2 sum beta |xi| n_x^2 n_y^2 V. The continuum horizon
gives C12/C11 = 1/3 and C11 = E/(1 - 1/9). Printed per partial-volume rule and delta/dx:

- C11 / continuum C11: the stiffness error without surface correction;
- nu_eff = C12/C11: the lateral contraction in uniaxial stress (u_x slope error nu_eff/nu - 1);
- E_eff / E = C11 (1 - nu_eff^2) / (E / (1 - 1/9)) in uniaxial stress, without surface correction
  and with it (the energy method scales an interior particle so that C11 is the continuum one);
- for delta = 4 dx, the nominal stress of the exact (nonlinear) stretch in uniaxial stress at the
  strain of the benchmark, relative to the linear E_eff eps.

Usage: lattice_moduli.py   (numpy only)
"""

import numpy as np

EPS = 2 * 5.6141e-4 / 0.05  # applied strain of the benchmark


def family(m, rule):
    """Bond vectors (in units of dx) and weights beta of an interior particle, delta = m dx."""
    n = int(np.ceil(m + 1))
    i, j = np.meshgrid(np.arange(-n, n + 1, dtype=float), np.arange(-n, n + 1, dtype=float))
    i, j = i.ravel(), j.ravel()
    r = np.hypot(i, j)
    keep = r > 0
    i, j, r = i[keep], j[keep], r[keep]
    if rule == "geometric":  # |xi| < delta + dx/2
        member = r < m + 0.5 - 1e-12
    else:  # 'book' and 'none': |xi| <= delta
        member = r <= m + 1e-12
    beta = np.where((rule == "none") | (r <= m - 0.5), 1.0, m + 0.5 - r)
    return i, j, np.where(member, beta, 0.0)


def moduli(m, rule):
    x, y, w = family(m, rule)
    r = np.hypot(x, y)
    c11 = np.sum(w * r * (x / r) ** 4)
    c12 = np.sum(w * r * (x / r) ** 2 * (y / r) ** 2)
    c11_continuum = m**3 / 3 * 3 * np.pi / 4  # int_0^delta r^2 dr int cos^4
    return c11 / c11_continuum, c12 / c11


def nonlinear_factor(m, rule, eps):
    """P_yy(eps) / (E_eff eps) in uniaxial stress with the exact stretch |F xi|/|xi| - 1."""
    x, y, w = family(m, rule)
    r = np.hypot(x, y)

    def energy(fx, fy):
        s = np.hypot(fx * x, fy * y) / r - 1
        return np.sum(w * r * s * s)

    def stress(fx, fy, axis, h=1e-7):
        if axis == 0:
            return (energy(fx + h, fy) - energy(fx - h, fy)) / (2 * h)
        return (energy(fx, fy + h) - energy(fx, fy - h)) / (2 * h)

    def uniaxial(e):  # F_xx with P_xx = 0 at F_yy = 1 + e, by bisection
        lo, hi = 1 - e, 1.0
        for _ in range(80):
            mid = 0.5 * (lo + hi)
            lo, hi = (lo, mid) if stress(mid, 1 + e, 0) > 0 else (mid, hi)
        return 0.5 * (lo + hi)

    small = 1e-6
    modulus = stress(uniaxial(small), 1 + small, 1) / small
    return stress(uniaxial(eps), 1 + eps, 1) / (modulus * eps)


def main():
    print("rule       delta/dx  C11/C11_cont  nu_eff  (nu_eff/nu - 1)  "
          "E_eff/E without / with correction")
    for m in (3.015, 4, 5, 6, 8):
        for rule in ("none", "book", "geometric"):
            k, nu = moduli(m, rule)
            with_correction = (1 - nu**2) / (1 - 1 / 9)
            print(f"{rule:10s} {m:6.3f}   {k:10.4f}    {nu:.4f}  {100 * (3 * nu - 1):+6.2f} %"
                  f"        {k * with_correction:.4f} / {with_correction:.4f}")
    for rule in ("none", "book", "geometric"):
        factor = nonlinear_factor(4, rule, EPS)
        print(f"delta = 4 dx, {rule}: nominal stress at eps = {EPS:.5f} / linear = {factor:.4f}")


if __name__ == "__main__":
    main()
