#!/usr/bin/env python3
"""Stability of the two-way thermoelastic splits of PeriDeal's explicit runs, one Fourier mode
(doc/theory/thermoelasticity.md, "The stable time step").

The mode u, theta of   u'' = -w2 u + g theta,   theta' = -lam theta - eta u',
with g eta = delta w2 (the adiabatic modulus is (1 + delta) times the isothermal one), advanced
by the two splits of velocity Verlet and the heat's forward-Euler sub-steps of length h:

- "lagging" (before): the new acceleration reads the predicted adiabatic temperature
  theta_n - eta (u_{n+1} - u_n), then n sub-steps of the heat with the source
  -eta (u_{n+1} - u_n) / dt held over the step; the next step starts from the stored
  acceleration, which misses the conduction of the step;
- "adiabatic" (Armero and Simo 1992, the code now): after the drift to u_{n+1} the temperature
  takes the adiabatic change -eta (u_{n+1} - u_n) at once, the heat conducts over the step at
  that configuration (n sub-steps, no source), and the acceleration at u_{n+1} reads the
  temperature of t_{n+1}. The conduction's factor over the step is c = (1 - h lam)^n; the code
  takes n even (c >= 0).

Prints the critical dt * w_ad (w_ad^2 = (1 + delta) w2) of both against delta and lam / w_ad,
the adiabatic split's growth with an odd number of sub-steps (c < 0), and its energy: without
conduction the split is velocity Verlet of the adiabatic mode (the energy
(v^2 + w2 u^2 + (g / eta) theta^2) / 2 kept to O(dt^2), no drift), with conduction it decays.
"""
import numpy as np


def step_lagging(state, dt, w2, lam, eta, g, nsub):
    u, v, a, th = state
    u1 = u + dt * v + 0.5 * dt * dt * a
    a1 = -w2 * u1 + g * (th - eta * (u1 - u))
    v1 = v + 0.5 * dt * (a + a1)
    s, h = -eta * (u1 - u) / dt, dt / nsub
    for _ in range(nsub):
        th = th + h * (-lam * th + s)
    return np.array([u1, v1, a1, th])


def step_adiabatic(state, dt, w2, lam, eta, g, nsub):
    u, v, a, th = state
    u1 = u + dt * v + 0.5 * dt * dt * a
    th = th - eta * (u1 - u)
    h = dt / nsub
    for _ in range(nsub):
        th = th - h * lam * th
    a1 = -w2 * u1 + g * th
    v1 = v + 0.5 * dt * (a + a1)
    return np.array([u1, v1, a1, th])


def amplification(step, dt, w2, lam, delta, nsub, g=1.0):
    """Spectral radius of the one-step map of the state (u, v, a, theta)."""
    eta = delta * w2 / g
    M = np.zeros((4, 4))
    for col in range(4):
        x = np.zeros(4)
        x[col] = 1.
        M[:, col] = step(x, dt, w2, lam, eta, g, nsub)
    # The adiabatic split's a is -w2 u + g theta after every step: the map on (u, v, theta).
    return max(abs(np.linalg.eigvals(M)))


def sub_steps(dt, lam, even):
    """The heat's sub-steps at h lam <= 1.8 (its stable step times a safety factor 0.9)."""
    n = max(1, int(np.ceil(dt * lam / 1.8)))
    return n + n % 2 if even else n


def critical(step, delta, ratio, even, tol=1e-7):
    """Smallest x = dt w_ad in (0, 2.2] with growth, lam = ratio * w_ad; None: none."""
    wad = np.sqrt(1. + delta)
    for x in np.linspace(0.005, 2.2, 1000):
        dt = x / wad
        lam = ratio * wad
        if amplification(step, dt, 1., lam, delta, sub_steps(dt, lam, even)) > 1 + tol:
            return x
    return None


def energy_history(dt_wad, delta, lam_ratio, periods):
    """The energy (v^2 + w2 u^2 + (g / eta) theta^2) / 2 over the adiabatic split's steps,
    relative to its start, from u = 1 at rest and theta = 0."""
    w2, g = 1., 1.
    eta = delta * w2 / g
    wad = np.sqrt(1. + delta)
    dt = dt_wad / wad
    lam = lam_ratio * wad
    nsub = sub_steps(dt, lam, True)
    state = np.array([1., 0., -w2, 0.])
    energy = lambda s: 0.5 * (s[1] ** 2 + w2 * s[0] ** 2 + (g / eta) * s[3] ** 2)
    history = [energy(state)]
    for _ in range(int(periods * 2 * np.pi / dt_wad)):
        state = step_adiabatic(state, dt, w2, lam, eta, g, nsub)
        history.append(energy(state))
    return np.array(history) / history[0]


def multi_mode(nsub, h_lam, x, seed, n=8):
    """Spectral radius of the adiabatic split of M u'' = -K u + B theta, C theta' = -L theta -
    B^T u' (M = C = 1, T_0 = 1) with random symmetric K > 0, L >= 0 and a random B (no common
    modes), at dt * w_ad,max = x (w_ad^2 the eigenvalues of K + B B^T) and nsub sub-steps of
    h * lam_max(L) = h_lam."""
    rng = np.random.default_rng(seed)
    A = rng.standard_normal((n, n))
    K = A @ A.T / n + 0.1 * np.eye(n)
    A = rng.standard_normal((n, n))
    L = A @ A.T / n
    B = rng.standard_normal((n, n))
    dt = x / np.sqrt(np.linalg.eigvalsh(K + B @ B.T).max())
    L *= h_lam * nsub / (dt * np.linalg.eigvalsh(L).max())
    P = np.linalg.matrix_power(np.eye(n) - dt / nsub * L, nsub)
    M = np.zeros((3 * n, 3 * n))
    for col in range(3 * n):
        s = np.zeros(3 * n)
        s[col] = 1.
        u, v, th = s[:n], s[n:2 * n], s[2 * n:]
        u1 = u + dt * v + 0.5 * dt * dt * (-K @ u + B @ th)
        th1 = P @ (th - B.T @ (u1 - u))
        v1 = v + 0.5 * dt * ((-K @ u + B @ th) + (-K @ u1 + B @ th1))
        M[:, col] = np.concatenate([u1, v1, th1])
    return max(abs(np.linalg.eigvals(M)))


def fmt(x):
    return "none" if x is None else f"{x:.3f}"


if __name__ == "__main__":
    ratios = [1e-3, 1e-1, 1., 10., 100.]
    deltas = [0.01, 0.25, 1., 100., 5e4]
    print("critical dt*w_ad (none: stable up to 2.2); columns lam/w_ad =", ratios)
    print("lagging split (before):")
    for delta in deltas:
        print(f"  delta {delta:8g}:",
              " ".join(fmt(critical(step_lagging, delta, r, False)) for r in ratios))
    print("adiabatic split, even number of heat sub-steps (the code):")
    for delta in deltas:
        print(f"  delta {delta:8g}:",
              " ".join(fmt(critical(step_adiabatic, delta, r, True)) for r in ratios))
    print("adiabatic split, any number of sub-steps (odd ones at h lam > 1 grow):")
    for delta in deltas:
        print(f"  delta {delta:8g}:",
              " ".join(fmt(critical(step_adiabatic, delta, r, False)) for r in ratios))
    print("adiabatic split: growth per step (rho - 1) at dt*w_ad = 0.5, 1.5, 1.9, 1.99, 2.01")
    for delta in [0.05, 1., 5e4]:
        for r in [0.01, 1., 10.]:
            wad = np.sqrt(1. + delta)
            row = []
            for x in [0.5, 1.5, 1.9, 1.99, 2.01]:
                dt, lam = x / wad, r * wad
                row.append(amplification(step_adiabatic, dt, 1., lam, delta,
                                         sub_steps(dt, lam, True)) - 1)
            print(f"  delta {delta:g} lam/w_ad {r:g}:", " ".join(f"{g:.3g}" for g in row))
    print("adiabatic split, a single sub-step of h lam = 1.5 (c = -0.5): growth per step at "
          "dt*w_ad = 0.5, 1, 1.5")
    for delta in [0.01, 1., 5e4]:
        wad = np.sqrt(1. + delta)
        print(f"  delta {delta:g}:",
              " ".join(f"{amplification(step_adiabatic, x / wad, 1., 1.5 * wad / x, delta, 1) - 1:.3g}"
                       for x in [0.5, 1., 1.5]))
    print("adiabatic split, no conduction: largest |E/E_0 - 1| over the first 20 and over 200 "
          "periods (bounded: no drift; second order in dt)")
    for delta in [0.25, 5e4]:
        row = []
        for x in [0.1, 0.2, 1.9]:
            e = energy_history(x, delta, 0., 200)
            first = e[:len(e) // 10]
            row.append(f"dt*w_ad {x:g}: {np.abs(first - 1).max():.3g} {np.abs(e - 1).max():.3g}")
        print(f"  delta {delta:g}:", "; ".join(row))
    print("adiabatic split with conduction: E_end / E_0 after 200 periods, and the largest "
          "E / E_0 (the heat flow dissipates)")
    for delta in [0.25, 5e4]:
        for r in [0.1, 1., 10.]:
            row = []
            for x in [0.5, 1.9]:
                e = energy_history(x, delta, r, 200)
                row.append(f"dt*w_ad {x:g}: {e[-1]:.3g} {e.max():.4g}")
            print(f"  delta {delta:g} lam/w_ad {r:g}:", "; ".join(row))
    print("adiabatic split of a random system of 8 unknowns (20 draws, dt*w_ad,max = 0.5, 1, 1.5, "
          "1.9): largest rho - 1")
    for nsub, h_lam in [(2, 1.6), (4, 1.6), (1, 0.9), (1, 1.6)]:
        worst = max(multi_mode(nsub, h_lam, x, seed) for seed in range(20)
                    for x in [0.5, 1., 1.5, 1.9])
        print(f"  {nsub} sub-step(s) of h lam_max = {h_lam:g}: {worst - 1:.3g}")
