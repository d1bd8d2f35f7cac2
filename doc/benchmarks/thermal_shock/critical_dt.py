#!/usr/bin/python3
"""The critical temperature difference of the alumina quench (README.md, "Critical dT").

A long strip of width 2L (the plate's 10 mm face, L = 5 mm), quenched on its long edges by
convection h into water at T_w, plane stress, free to expand as a whole: the edge carries the
uniaxial stress sigma_xx = E alpha (T_mean - T_edge) (beam theory of the strip; the stress across
the strip vanishes at the edge, plane stress through the thickness). With theta = (T - T_w) /
(T0 - T_w) of the slab with Biot number Bi = h L / k (Carslaw & Jaeger 1959, sec. 3.11: theta =
sum C_n cos(l_n y/L) exp(-l_n^2 Fo), l_n tan l_n = Bi, C_n = 4 sin l_n / (2 l_n + sin 2 l_n),
Fo = kappa t / L^2), the edge strain is alpha dT phi(Fo), phi = theta_mean - theta_edge, and its
peak phi_max(Bi) sets the critical temperature difference

    dT_c = eps_c / (alpha phi_max(Bi)),

eps_c the strain at which the material breaks in uniaxial tension: the PD model's critical
stretch s0 (a bond along the edge carries the edge strain), or sigma_f / E of the real alumina.
Manson's fit 1/phi = 1.5 + 3.25/Bi - 0.5 exp(-16/Bi) (for a plate, without its 1/(1 - nu)) is
printed for comparison. Usage: critical_dt.py [h [dx]] (defaults 5e4 W/(m^2 K), 2.5e-4 m).
"""

import math
import sys

import numpy as np


def eigenvalues(bi, n):
    """The first n roots of l tan l = Bi (bisection in (k pi, k pi + pi/2))."""
    roots = []
    for k in range(n):
        a, b = k * math.pi + 1e-12, k * math.pi + math.pi / 2 - 1e-12
        for _ in range(200):
            m = 0.5 * (a + b)
            if m * math.tan(m) - bi > 0:
                b = m
            else:
                a = m
        roots.append(0.5 * (a + b))
    return np.array(roots)


def phi_max(bi, n=400):
    """Peak of theta_mean - theta_edge over the Fourier number, and the Fourier number of it."""
    lam = eigenvalues(bi, n)
    c = 4 * np.sin(lam) / (2 * lam + np.sin(2 * lam))
    fo = np.logspace(-6, 1, 20000)
    decay = np.exp(-np.outer(fo, lam**2))
    edge = decay @ (c * np.cos(lam))
    mean = decay @ (c * np.sin(lam) / lam)
    phi = mean - edge
    k = int(np.argmax(phi))
    return phi[k], fo[k]


def main():
    h = float(sys.argv[1]) if len(sys.argv) > 1 else 5e4
    dx = float(sys.argv[2]) if len(sys.argv) > 2 else 2.5e-4
    E, rho, G0, alpha, k, c = 370e9, 3980.0, 24.32, 7.5e-6, 31.0, 880.0
    L, horizon = 5e-3, 3.015 * dx
    kappa = k / (rho * c)
    bi = h * L / k
    phi, fo = phi_max(bi)
    manson = 1.0 / (1.5 + 3.25 / bi - 0.5 * math.exp(-16.0 / bi))
    # Bond-based PMB in 2D (plane stress): s0 = sqrt(4 pi G0 / (9 E delta)) (Ha & Bobaru 2010).
    s0 = math.sqrt(4 * math.pi * G0 / (9 * E * horizon))
    sigma_f = 380e6  # NIST SRD 150 (Munro 1997), sintered alpha-alumina, flexural, 20 C
    print(f"h = {h:g} W/(m^2 K), L = {1e3 * L:g} mm, k = {k:g} W/(m K): Bi = {bi:.3f}")
    print(f"thermal diffusivity kappa = {kappa:.4e} m^2/s, L^2/kappa = {L * L / kappa:.3f} s")
    print(f"phi_max = {phi:.4f} at Fo = {fo:.4f} (t = {fo * L * L / kappa * 1e3:.1f} ms); "
          f"Manson's fit {manson:.4f}")
    print(f"PD (dx = {1e3 * dx:g} mm, delta = {1e3 * horizon:.4f} mm): s0 = {s0:.5e}, "
          f"strength E s0 = {E * s0 / 1e6:.1f} MPa, dT_c = s0 / (alpha phi_max) = "
          f"{s0 / (alpha * phi):.1f} K (without the Biot factor {s0 / alpha:.1f} K)")
    print(f"alumina (sigma_f = {sigma_f / 1e6:g} MPa): dT_c = sigma_f / (E alpha phi_max) = "
          f"{sigma_f / (E * alpha * phi):.1f} K")
    lch = E * G0 / sigma_f**2
    delta_f = 4 * math.pi * G0 / (9 * E * (sigma_f / E) ** 2)
    print(f"horizon at which the PD strength E s0 equals sigma_f: {1e3 * delta_f:.4f} mm "
          f"(Irwin's length E G0 / sigma_f^2 = {1e3 * lch:.4f} mm)")


if __name__ == "__main__":
    main()
