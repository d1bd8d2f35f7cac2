#!/usr/bin/env python3
"""Stability of the two-way thermoelastic split of PeriDeal's explicit runs, one Fourier mode
(doc/theory/thermoelasticity.md, "The stable time step").

The mode u, theta of   u'' = -w2 u + g theta,   theta' = -lam theta - eta u',
with g eta = delta w2 (the adiabatic modulus is (1 + delta) times the isothermal one), advanced
as the code does: velocity Verlet of u whose new acceleration reads the predicted adiabatic
temperature theta_n - eta (u_{n+1} - u_n) (ThermoelasticHeating::predict()), then n forward-Euler
sub-steps of the heat with the source -eta (u_{n+1} - u_n) / dt held over the step; the next
step starts from the stored acceleration. Prints the critical dt * w_ad (w_ad^2 = (1 + delta) w2)
against delta and lam / w_ad, the growth per step around it, and the heat's own limit.
"""
import numpy as np


def amplification(dt, w2, lam, delta, nsub, g=1.0):
    """Spectral radius of the one-step map of the state (u, v, a, theta)."""
    eta = delta * w2 / g
    M = np.zeros((4, 4))
    for col in range(4):
        x = np.zeros(4)
        x[col] = 1.
        u, v, a, th = x
        u1 = u + dt * v + 0.5 * dt * dt * a
        a1 = -w2 * u1 + g * (th - eta * (u1 - u))
        v1 = v + 0.5 * dt * (a + a1)
        s, h = -eta * (u1 - u) / dt, dt / nsub
        for _ in range(nsub):
            th = th + h * (-lam * th + s)
        M[:, col] = [u1, v1, a1, th]
    return max(abs(np.linalg.eigvals(M)))


def sub_steps(dt, lam):
    return max(1, int(np.ceil(dt * lam / 1.8)))


def critical(delta, ratio, tol=1e-7):
    """Smallest x = dt w_ad with growth, lam = ratio * w_ad, the heat sub-stepped stably."""
    wad = np.sqrt(1. + delta)
    for x in np.linspace(0.005, 2.2, 2000):
        dt = x / wad
        if amplification(dt, 1., ratio * wad, delta, sub_steps(dt, ratio * wad)) > 1 + tol:
            return x
    return None


if __name__ == "__main__":
    ratios = [1e-3, 1e-1, 1., 10., 100.]
    print("critical dt*w_ad; columns lam/w_ad =", ratios)
    for delta in [0.01, 0.25, 1., 100., 5e4]:
        print(f"delta {delta:8g}:", " ".join(f"{critical(delta, r):.3f}" for r in ratios))
    print("growth per step (rho - 1) at dt*w_ad = 0.9, 1.1, 1.5, 1.9, 2.1")
    for delta in [5e4, 0.05]:
        for r in [0.01, 0.1, 1., 10.]:
            wad = np.sqrt(1. + delta)
            row = []
            for x in [0.9, 1.1, 1.5, 1.9, 2.1]:
                dt = x / wad
                row.append(amplification(dt, 1., r * wad, delta, sub_steps(dt, r * wad)) - 1)
            print(f"delta {delta:g} lam/w_ad {r:g}:", " ".join(f"{g:.3g}" for g in row))
    print("the heat's limit: growth at h*lam = 1.9, 1.99, 2.01, 2.1 (dt*w_ad = 0.5, one sub-step)")
    for delta in [0.05, 1., 5e4]:
        dt = 0.5 / np.sqrt(1. + delta)
        print(f"delta {delta:g}:",
              " ".join(f"{amplification(dt, 1., hl / dt, delta, 1) - 1:.3g}"
                       for hl in [1.9, 1.99, 2.01, 2.1]))
