"""The materials of the benchmark and their plane-stress algebra (no files, no runs).

Each material is the dict of ElasticMaterial entries (<Material/anisotropic plane stress> and
<Finite elements/Elasticity>, include/perideal/base/elasticity.h) plus a label. The functions
repeat what source/base/elasticity.cc does (engineering constants -> Voigt stiffness, rotation
by z-x-z Euler angles, plane-stress reduction) so that the boundary values of the uniform
far field and the reference stress concentrations can be written into the parameter files.
"""
import math

import numpy as np

GPA = 1e9

# Isotropic, nu = 1/4 (Cauchy's relations: lambda = mu). E = 120 GPa is representative of a
# glass-ceramic of the Pyroceram family (the slides' isotropic example; their value is not
# given); with displacement loading only E/nu matter through the far strain, which scales out.
ISOTROPIC = {"Symmetry": "isotropic", "Young's modulus": "120e9", "Poisson's ratio": "0.25"}
# Cubic NaCl: C11 = 49.1, C12 = C44 = 12.8 GPa (C12 = C44: Cauchy's relations hold exactly);
# the values of issue #15 and of the project's unit tests, within about 1 % of room-temperature
# ultrasonic data for rock salt.
NACL = {"Symmetry": "cubic", "Cubic constants": "49.1e9, 12.8e9, 12.8e9"}
# The seed note's orthotropic Cauchy test tensor (note 004, sec. 3.3), Voigt C11 = 12, C22 = 9,
# C33 = 6, C12 = C66 = 3, C13 = C55 = 2, C23 = C44 = 1 (x 10 GPa), as engineering constants
# (the inverse of its compliance; tests/app-solid/coupled_patch_aniso_plane_stress_2d.prm).
ORTHOTROPIC = {
    "Symmetry": "orthotropic",
    "Young's moduli": "105283018867.92453, 82058823529.411758, 56363636363.63636",
    "Poisson's ratios": "0.30188679245283018, 0.28301886792452829, 0.088235294117647065",
    "Shear moduli": "30e9, 20e9, 10e9",
}


def rotated(entries, phi):
    out = dict(entries)
    out["Orientation"] = "%g, 0, 0" % phi
    return out


# name: (label, entries)
MATERIALS = {
    "isotropic": ("isotropic, E = 120 GPa, nu = 1/4", ISOTROPIC),
    "nacl": ("cubic NaCl", NACL),
    "nacl_30": ("cubic NaCl, axes at 30 deg", rotated(NACL, 30)),
    "orthotropic": ("orthotropic (note 004)", ORTHOTROPIC),
    "orthotropic_30": ("orthotropic (note 004), axes at 30 deg", rotated(ORTHOTROPIC, 30)),
}

VOIGT = [(0, 0), (1, 1), (2, 2), (1, 2), (0, 2), (0, 1)]


def floats(text):
    return [float(v) for v in text.split(",")]


def voigt_stiffness(entries):
    """The 6 x 6 Voigt stiffness in the material axes."""
    symmetry = entries["Symmetry"]
    if symmetry == "isotropic":
        E, nu = float(entries["Young's modulus"]), float(entries["Poisson's ratio"])
        lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
        C = np.zeros((6, 6))
        C[:3, :3] = lam
        C[:3, :3] += 2 * mu * np.eye(3)
        C[3:, 3:] = mu * np.eye(3)
        return C
    if symmetry == "cubic":
        c11, c12, c44 = floats(entries["Cubic constants"])
        C = np.full((3, 3), c12) + (c11 - c12) * np.eye(3)
        return np.block([[C, np.zeros((3, 3))], [np.zeros((3, 3)), c44 * np.eye(3)]])
    if symmetry == "orthotropic":
        E1, E2, E3 = floats(entries["Young's moduli"])
        n12, n13, n23 = floats(entries["Poisson's ratios"])
        G12, G13, G23 = floats(entries["Shear moduli"])
        S = np.zeros((6, 6))
        S[0, 0], S[1, 1], S[2, 2] = 1 / E1, 1 / E2, 1 / E3
        S[0, 1] = S[1, 0] = -n12 / E1
        S[0, 2] = S[2, 0] = -n13 / E1
        S[1, 2] = S[2, 1] = -n23 / E2
        S[3, 3], S[4, 4], S[5, 5] = 1 / G23, 1 / G13, 1 / G12
        return np.linalg.inv(S)
    raise ValueError(symmetry)


def tensor(voigt):
    C = np.zeros((3, 3, 3, 3))
    for I, (i, j) in enumerate(VOIGT):
        for J, (k, l) in enumerate(VOIGT):
            for a, b in ((i, j), (j, i)):
                for c, d in ((k, l), (l, k)):
                    C[a, b, c, d] = voigt[I, J]
    return C


def rotation(phi, theta=0.0, psi=0.0):
    """z-x-z Euler angles in degrees; columns are the material axes in global coordinates."""
    def rz(t):
        c, s = math.cos(math.radians(t)), math.sin(math.radians(t))
        return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])

    def rx(t):
        c, s = math.cos(math.radians(t)), math.sin(math.radians(t))
        return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])

    return rz(phi) @ rx(theta) @ rz(psi)


def global_tensor(entries):
    """The 3D C_ijkl in the global axes."""
    angles = floats(entries.get("Orientation", "0, 0, 0"))
    R = rotation(*angles)
    return np.einsum("ia,jb,kc,ld,abcd->ijkl", R, R, R, R, tensor(voigt_stiffness(entries)))


def reduced(entries):
    """The plane-stress stiffness C'_abcd = C_abcd - C_ab33 C_33cd / C_3333 (2 x 2 x 2 x 2)."""
    C = global_tensor(entries)
    P = C[:2, :2, 2, 2]
    return C[:2, :2, :2, :2] - np.einsum("ab,cd->abcd", P, P) / C[2, 2, 2, 2]


def mandel(C2):
    """A 2D fourth-order tensor as the 3 x 3 matrix (e11, e22, 2 e12) -> (s11, s22, s12)."""
    idx = [(0, 0), (1, 1), (0, 1)]
    return np.array([[C2[i, j, k, l] for (k, l) in idx] for (i, j) in idx])


def far_strain(entries, stress):
    """The uniform strain (e_xx, e_yy, e_xy) of the uniaxial stress sigma_xx = stress."""
    e = np.linalg.solve(mandel(reduced(entries)), [stress, 0.0, 0.0])
    return e[0], e[1], 0.5 * e[2]


def cauchy_defect(entries):
    """max |C_ijkl - C_ikjl| / max |C| (0 for the completely symmetric tensors of the model)."""
    C = global_tensor(entries)
    return np.abs(C - np.einsum("ikjl->ijkl", C)).max() / np.abs(C).max()


def hoop_compliance(entries, theta):
    """1/E_t of the direction t = (-sin theta, cos theta) tangent to the hole at the angle theta:
    on the traction-free hole the hoop stress is sigma_tt = eps_tt E_t."""
    t = np.array([-math.sin(theta), math.cos(theta)])
    S = np.linalg.inv(mandel(reduced(entries)))
    v = np.array([t[0] * t[0], t[1] * t[1], t[0] * t[1]])
    return v @ S @ v


def lekhnitskii_hoop(entries, theta):
    """sigma_tt / S at the angle theta on the circular hole of an infinite anisotropic plate
    under the remote uniaxial stress S along x (Lekhnitskii, Anisotropic Plates, 1968, ch. 6:
    complex potentials phi_k(z_k) = G_k z_k + A_k / s_k, z_k = x + mu_k y, s_k the exterior of
    the unit disc; mu_1, mu_2 the roots with positive imaginary part of
    S11 mu^4 - 2 S16 mu^3 + (2 S12 + S66) mu^2 - 2 S26 mu + S22 = 0, S the reduced compliance
    with engineering shear strain; sigma_xx = 2 Re sum mu_k^2 phi_k', sigma_yy = 2 Re sum
    phi_k', sigma_xy = -2 Re sum mu_k phi_k'; the A_k make the hole traction free)."""
    S = np.linalg.inv(mandel(reduced(entries)))
    S11, S22, S12, S16, S26, S66 = S[0, 0], S[1, 1], S[0, 1], S[0, 2], S[1, 2], S[2, 2]
    roots = [r for r in np.roots([S11, -2 * S16, 2 * S12 + S66, -2 * S26, S22]) if r.imag > 0]
    if len(roots) < 2 or abs(roots[0] - roots[1]) < 1e-5:
        return 1 - 2 * math.cos(2 * theta)  # mu_1 = mu_2 = i: isotropic in the plane (Kirsch)
    m = np.array(roots)
    # Remote field: Im G_1 = 0 (the rigid rotation at infinity changes no stress), then
    # 2 Re sum mu^2 G = 1, 2 Re sum G = 0, 2 Re sum mu G = 0 for the unknowns (g1, Re G2, Im G2).
    M = np.array([[2 * (m[0] ** 2).real, 2 * (m[1] ** 2).real, -2 * (m[1] ** 2).imag],
                  [2.0, 2.0, 0.0],
                  [2 * m[0].real, 2 * m[1].real, -2 * m[1].imag]])
    g1, g2r, g2i = np.linalg.solve(M, [1.0, 0.0, 0.0])
    G = np.array([g1, g2r + 1j * g2i])
    # On the hole (radius 1) z_k = (1 - i mu_k)/2 s + (1 + i mu_k)/2 / s with s = e^{i theta}: the
    # e^{i theta} terms of 2 Re sum w_k phi_k (w = 1 and w = mu) must vanish.
    X = [0.5 * np.sum(w * G * (1 - 1j * m)) for w in (1.0, m)]
    Y = [0.5 * np.sum(w * G * (1 + 1j * m)) for w in (1.0, m)]
    A = np.linalg.solve(np.array([[1.0, 1.0], [m[0], m[1]]]),
                        [-np.conj(X[0]) - Y[0], -np.conj(X[1]) - Y[1]])
    s = np.exp(1j * theta)
    dz_ds = 0.5 * (1 - 1j * m) - 0.5 * (1 + 1j * m) / s ** 2
    dphi = G - A / s ** 2 / dz_ds
    sxx = 2 * np.sum(m ** 2 * dphi).real
    syy = 2 * np.sum(dphi).real
    sxy = -2 * np.sum(m * dphi).real
    c, n = math.cos(theta), math.sin(theta)
    return sxx * n * n + syy * c * c - 2 * sxy * n * c
