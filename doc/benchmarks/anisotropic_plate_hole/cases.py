#!/usr/bin/env python3
"""Writes the parameter files of the benchmark's runs from plate_hole_pd.prm and
plate_hole_fe.prm (which are the main case: the orthotropic tensor at 30 degrees, dx = 1 mm,
FE refined twice), and the two meshes.

usage: cases.py RESULTS_DIR [RUN ... | --fine]

A run is MATERIAL/KIND with KIND one of
  pd_dx<mm>           particles at the spacing dx (delta = 3.015 dx, layers 7 dx thick)
  pd_dx<mm>_nohole    the same plate without the hole (the floor of the edges and the layers)
  pd_dx<mm>_nosc      with <Discretization/Surface correction> = false
  fe_r<k>             FE, Q2 on the O-grid refined k times
  fe_r<k>_a<mm>       the same with the hole radius a [mm] (diagnostic: the hole a PD run sees)
and MATERIAL a key of materials.MATERIALS. Each run's file is RESULTS_DIR/MATERIAL/KIND.prm,
its output RESULTS_DIR/MATERIAL/KIND/. Without runs: the default list (run.sh); --fine: the
default list and the dx = 0.25 mm run of the main case (run.sh --fine).
"""
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import make_mesh  # noqa: E402
import materials  # noqa: E402

L, A = 0.1, 0.01            # plate side and hole radius [m]
CENTRE = 0.5 * L
REMOTE_STRESS = 10e6        # sigma_xx of the far field [Pa]
LAYER_ROWS = 7              # fictitious layer depth in lattice spacings (>= 2 delta = 6.03 dx)
MATERIAL_KEYS = ["Symmetry", "Young's modulus", "Poisson's ratio", "Cubic constants",
                 "Young's moduli", "Poisson's ratios", "Shear moduli", "Orientation"]
DEFAULTS = {"Symmetry": "isotropic", "Young's modulus": "0", "Poisson's ratio": "0",
            "Cubic constants": "0, 0, 0", "Young's moduli": "0, 0, 0",
            "Poisson's ratios": "0, 0, 0", "Shear moduli": "0, 0, 0", "Orientation": "0, 0, 0"}

DEFAULT_RUNS = (
    [f"{m}/{k}" for m in materials.MATERIALS for k in ("fe_r2", "pd_dx1", "pd_dx0.5",
                                                       "pd_dx1_nohole")]
    + ["orthotropic_30/fe_r3", "orthotropic_30/pd_dx1_nosc"]
    + [f"{m}/fe_r2_a{a}" for m in ("isotropic", "orthotropic_30") for a in ("10.2", "10.4")])
# run.sh --fine adds these (about 2.5 more minutes).
FINE_RUNS = ["orthotropic_30/pd_dx0.25"]


def far_field(entries):
    """The expressions of u = eps . (x - c) of the uniaxial far stress."""
    exx, eyy, exy = materials.far_strain(entries, REMOTE_STRESS)
    X, Y = f"(x-{CENTRE:g})", f"(y-{CENTRE:g})"
    return f"{exx:.16e}*{X} + {exy:.16e}*{Y}; {exy:.16e}*{X} + {eyy:.16e}*{Y}"


def set_entry(text, key, value, count=None):
    """Replace the value of every 'set KEY = ...' line (there must be count of them)."""
    pattern = re.compile(r"^(\s*set " + re.escape(key) + r"\s*=).*$", re.M)
    text, n = pattern.subn(lambda m: m.group(1) + " " + value, text)
    if n == 0 or (count is not None and n != count):
        raise SystemExit(f"cases.py: 'set {key}' found {n} times")
    return text


def with_material(text, entries, n_sections):
    full = dict(DEFAULTS)
    full.update(entries)
    for key in MATERIAL_KEYS:
        text = set_entry(text, key, full[key], n_sections)
    return set_entry(text, "Function", far_field(entries), 2)


def pd_file(results, material, kind):
    match = re.fullmatch(r"pd_dx([0-9.]+)(_nohole|_nosc)?", kind)
    dx = float(match.group(1)) * 1e-3
    text = open(os.path.join(HERE, "plate_hole_pd.prm")).read()
    text = with_material(text, materials.MATERIALS[material][1], 1)
    text = set_entry(text, "Lattice spacing", f"{dx:g}")
    depth = LAYER_ROWS * dx
    text = text.replace("set Lower corner = -0.007, 0", f"set Lower corner = {-depth:g}, 0")
    text = text.replace("set Upper corner = 0.107, 0.1", f"set Upper corner = {L + depth:g}, {L:g}")
    text = set_entry(text, "Layer thickness", f"{depth:g}", 2)
    text = set_entry(text, "Mesh file", os.path.join(results, "plate_hole_body.msh"))
    if match.group(2) == "_nohole":
        text = text.replace("set Shape       = mesh", "set Shape        = box\n"
                            f"    set Lower corner = 0, 0\n    set Upper corner = {L:g}, {L:g}")
    if match.group(2) == "_nosc":
        text = set_entry(text, "Surface correction", "false")
    return text


def fe_file(results, material, kind):
    match = re.fullmatch(r"fe_r([0-9]+)(_a([0-9.]+))?", kind)
    text = open(os.path.join(HERE, "plate_hole_fe.prm")).read()
    text = with_material(text, materials.MATERIALS[material][1], 1)
    text = set_entry(text, "Global refinements", match.group(1))
    mesh = os.path.join(results, "plate_hole_fe.msh")
    if match.group(2):
        mesh = os.path.join(results, f"plate_hole_fe_a{match.group(3)}.msh")
        make_mesh.write_mesh(L, float(match.group(3)) * 1e-3, 16, 16, mesh)
    return set_entry(text, "Mesh file", mesh)


def write(results, run):
    material, kind = run.split("/")
    text = (fe_file if kind.startswith("fe") else pd_file)(results, material, kind)
    text = set_entry(text, "Directory", os.path.join(results, material, kind))
    os.makedirs(os.path.join(results, material), exist_ok=True)
    path = os.path.join(results, material, kind + ".prm")
    with open(path, "w") as f:
        f.write(text)
    return path


def main():
    if len(sys.argv) < 2:
        raise SystemExit(__doc__)
    results = os.path.abspath(sys.argv[1])
    os.makedirs(results, exist_ok=True)
    # The FE mesh: 16 cells per quarter of the hole, 16 graded cells outwards. The particle
    # body: the same outline with 32 cells per quarter and one cell outwards (a mesh region
    # costs a cell search per lattice point; few cells keep it fast, and 128 chords put the
    # boundary within 3 um of the circle).
    make_mesh.write_mesh(L, A, 16, 16, os.path.join(results, "plate_hole_fe.msh"))
    make_mesh.write_mesh(L, A, 32, 1, os.path.join(results, "plate_hole_body.msh"))
    runs = sys.argv[2:] or DEFAULT_RUNS
    if runs == ["--fine"]:
        runs = DEFAULT_RUNS + FINE_RUNS
    for run in runs:
        print(write(results, run))


if __name__ == "__main__":
    main()
