#!/usr/bin/python3
"""Comparison of the coupling methods (issue #16, part 2): blended against overlapping Schwarz.

usage: compare.py [--build BUILD_DIR] [--work WORK_DIR] [--quick]

Runs every case of this directory's parameter files (*.prm, changed by contrib/prm_fill.py) with `Coupling/Method = blended` and
`overlapping schwarz` (serial, one rank each), measures the wall time of each run, reads from the
printed summary the displacement error against the exact field, the residual of the exact field
(the ghost force) and the Schwarz iterations, compares the cracked plates with the full-PD
plate at the common particles (particle HDF5 output), and writes

- doc/coupling_methods.md (the report, from report.md.in),
- doc/coupling_methods/*.png (the plots),
- WORK_DIR/results.json (every number of the report).

Any run that fails (non-zero exit, a missing line in its output) stops the script with the run's
output and a non-zero exit status.
"""
import argparse
import datetime
import glob
import json
import os
import platform
import re
import shutil
import subprocess
import sys
import time

import h5py
import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "contrib"))
import prm_fill  # noqa: E402
METHODS = ["blended", "overlapping schwarz"]
SHORT = {"blended": "blended", "overlapping schwarz": "schwarz"}



def model(name, entries, physics, fe_entries):
    """The @MATERIAL@ and @FE_MATERIAL@ blocks of patch_2d.prm for a PD model and FE physics."""
    return {"MATERIAL": f"  set Model   = {name}\n  subsection {name}\n{entries}\n  end",
            "FE_MATERIAL": f"  set Physics = {physics}\n{fe_entries}"}


# Models of the 2D patch tests.
PMB = model("bond based", "    set Young's modulus = 200e9", "linear elasticity",
            "  subsection Elasticity\n    set Young's modulus = 200e9\n"
            "    set Poisson's ratio = 0.3333333333333333\n  end")
LPS = model("linear peridynamic solid",
            "    set Young's modulus = 200e9\n    set Poisson's ratio = 0.3", "linear elasticity",
            "  subsection Elasticity\n    set Young's modulus = 200e9\n"
            "    set Poisson's ratio = 0.3\n  end")
ANTIPLANE = model("antiplane bond based", "    set Shear modulus = 26e9", "scalar laplace",
                  "  subsection scalar laplace\n    set Coefficient = 26e9\n  end")
TRANSLATION = "1e-5; -2e-5"
ROTATION = "-1e-4*y; 1e-4*x"
UNIFORM = "1e-4*x + 2e-5*y; 3e-5*x - 5e-5*y"
LINEAR = "1e-3*(x^2 + x*y); 1e-3*(2*x^2 + y^2)/2"
# -div(C grad u) of LINEAR for plane stress: PMB lambda = mu = 75 GPa (E = 200 GPa, nu = 1/3);
# LPS lambda = E nu / (1 - nu^2), mu = E / (2 (1 + nu)) with nu = 0.3.
PMB_LINEAR_FORCE = "-1e-3*(2*75e9 + 4*75e9); -1e-3*(2*75e9 + 5*75e9)"
LPS_LINEAR_FORCE = "-1e-3*(2*200e9*0.3/0.91 + 4*200e9/2.6); -1e-3*(2*200e9*0.3/0.91 + 5*200e9/2.6)"
UNIFORM_3D = "1e-4*x + 2e-5*y; 3e-5*x - 5e-5*y + 1e-5*z; -2e-5*x + 4e-5*z"

# (name, template, fields, exact for both local models?)
PATCH_CASES = [
    ("PMB 2D translation", "patch_2d", dict(PMB, EXACT=TRANSLATION, BODY_FORCE="0; 0"), True),
    ("PMB 2D rotation", "patch_2d", dict(PMB, EXACT=ROTATION, BODY_FORCE="0; 0"), True),
    ("PMB 2D uniform strain", "patch_2d", dict(PMB, EXACT=UNIFORM, BODY_FORCE="0; 0"), True),
    ("PMB 2D linear strain", "patch_2d", dict(PMB, EXACT=LINEAR, BODY_FORCE=PMB_LINEAR_FORCE),
     False),
    ("LPS 2D translation", "patch_2d", dict(LPS, EXACT=TRANSLATION, BODY_FORCE="0; 0"), True),
    ("LPS 2D rotation", "patch_2d", dict(LPS, EXACT=ROTATION, BODY_FORCE="0; 0"), True),
    ("LPS 2D uniform strain", "patch_2d", dict(LPS, EXACT=UNIFORM, BODY_FORCE="0; 0"), True),
    ("LPS 2D linear strain", "patch_2d", dict(LPS, EXACT=LINEAR, BODY_FORCE=LPS_LINEAR_FORCE),
     False),
    ("antiplane uniform slope", "patch_2d",
     dict(ANTIPLANE, EXACT="1e-4*x - 2e-4*y", BODY_FORCE="0"), True),
    ("antiplane quadratic", "patch_2d",
     dict(ANTIPLANE, EXACT="1e-3*(x^2 + y^2)", BODY_FORCE="-4e-3*26e9"), False),
    ("PMB 3D uniform strain", "patch_3d", dict(EXACT=UNIFORM_3D), True),
]


def box_ramp(dim, lo, hi, width):
    """The blending function: 0 outside (lo, hi)^dim, linear ramps of the given width inside."""
    ramp = None
    for x in "xyz"[:dim]:
        term = f"min(({x} - {lo}) / {width}, ({hi} - {x}) / {width})"
        ramp = term if ramp is None else f"min({ramp}, {term})"
    return f"min(1, max(0, {ramp}))"


# The overlap of each patch test: its width W [m] and the fields it sets.
PATCH_W = {"patch_2d": dict(W="0.01", BLENDING=box_ramp(2, "0.03", "0.07", "0.01"),
                            RELAXATION="aitken"),
           "patch_3d": dict(W="0.005", BLENDING=box_ramp(3, "0.006", "0.018", "0.005"))}
# Overlap sweep: PMB uniform strain in 2D, beta = 1 on [40, 60]^2 mm, ramps of width W [mm]
# outside it (beta > 0 on (40 mm - W, 60 mm + W)^2). Below 8 mm Schwarz refuses the set-up (an
# interface dof's nearest particle in the volume constraint).
SWEEP_W = [8, 10, 12, 16, 20]
SWEEP_METHODS = [("blended", "aitken"), ("overlapping schwarz", "aitken"),
                 ("overlapping schwarz", "none")]

# Cracked plates (cracked_plate_*.prm): lattice, plate, crack centre, beta = 1 core and
# beta > 0 support of the coupled runs (boxes in x and y; through the thickness in 3D).
DX = 1e-3
PLATES = [
    dict(name="cracked plate 2D", coupled="cracked_plate_coupled", full="cracked_plate_full_pd",
         dim=2, size=(0.1, 0.1), centre=(0.05, 0.05), core=(0.036, 0.064, 0.040, 0.060),
         support=(0.028, 0.072, 0.032, 0.068)),
    dict(name="cracked plate 3D", coupled="cracked_plate_3d_coupled",
         full="cracked_plate_3d_full_pd", dim=3, size=(0.04, 0.04, 0.004), centre=(0.02, 0.02),
         core=(0.011, 0.029, 0.014, 0.026), support=(0.005, 0.035, 0.008, 0.032)),
]

RE_ERROR = re.compile(r"Displacement error \(largest, relative to the largest exact value\): "
                      r"FE nodes (\S+), particles (\S+)")
RE_GHOST = re.compile(r"Force residual of the exact field: (\S+) N .*scale: (\S+)")
RE_SCHWARZ = re.compile(r"Overlapping Schwarz: (\d+) iterations")
RE_PARTICLES = re.compile(r"^Particles: (\d+)", re.M)
RE_DOFS = re.compile(r"FE region: .* (\d+) dofs")


def fill(name, fields, path):
    """Write this directory's name.prm with the marked fields changed to path."""
    prm_fill.fill(os.path.join(HERE, name + ".prm"), fields, path)


def run(solver, prm, log):
    """Run the solver on prm (serial), return (output, wall time [s]); fail loudly."""
    start = time.perf_counter()
    proc = subprocess.run([solver, prm], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True, cwd=os.path.dirname(prm))
    wall = time.perf_counter() - start
    with open(log, "w") as f:
        f.write(proc.stdout)
    if proc.returncode != 0:
        sys.stderr.write(proc.stdout[-4000:])
        raise SystemExit(f"FAILED: {solver} {prm} exited with {proc.returncode} (log {log})")
    print(f"  {os.path.basename(os.path.dirname(prm)):52s} {wall:7.2f} s", flush=True)
    return proc.stdout, wall


def need(regex, text, what, log):
    m = regex.search(text)
    if m is None:
        raise SystemExit(f"FAILED: no '{what}' in the output {log}")
    return m


def patch_run(solver, work, name, template, fields, method, geometry):
    W = geometry["W"]
    relaxation = geometry.get("RELAXATION", "aitken")
    label = SHORT[method] + ("" if relaxation == "aitken" else "_" + relaxation)
    tag = re.sub(r"[^a-z0-9]+", "_", f"{name} {label} {W}".lower())
    directory = os.path.join(work, tag)
    os.makedirs(directory, exist_ok=True)
    prm = os.path.join(directory, "run.prm")
    changed = {key: value for key, value in geometry.items() if key != "W"}
    fill(template, dict(fields, METHOD=method, DIRECTORY="results", **changed), prm)
    out, wall = run(solver, prm, os.path.join(directory, "output.txt"))
    log = os.path.join(directory, "output.txt")
    e = need(RE_ERROR, out, "Displacement error", log)
    g = need(RE_GHOST, out, "Force residual of the exact field", log)
    row = dict(case=name, method=method, W=float(W), wall=wall,
               error_fe=float(e.group(1)), error_pd=float(e.group(2)),
               ghost=float(g.group(1)), ghost_rel=float(g.group(2)),
               particles=int(need(RE_PARTICLES, out, "Particles", log).group(1)),
               iterations=None, relaxation=relaxation if method != "blended" else None)
    if method == "overlapping schwarz":
        row["iterations"] = int(need(RE_SCHWARZ, out, "Overlapping Schwarz", log).group(1))
    return row


def last_particles(directory, dim):
    files = sorted(glob.glob(os.path.join(directory, "particles_*.h5")))
    if not files:
        raise SystemExit(f"FAILED: no particles_*.h5 in {directory}")
    with h5py.File(files[-1], "r") as h5:
        return (np.asarray(h5["nodes"][:, :dim], float),
                np.asarray(h5["displacement"][:, :dim], float))


def keys(points):
    """Integer keys of lattice points in half spacings (particles sit at odd multiples)."""
    return [tuple(int(round(c / DX * 2)) for c in p) for p in points]


def inside(p, box):
    return box[0] < p[0] < box[1] and box[2] < p[1] < box[3]


def crack_opening(points, u, centre):
    """Crack opening u_y(x, y_c + dx/2) - u_y(x, y_c - dx/2) at the particle column x = x_c - dx/2
    (next to the crack's centre), averaged over the particle layers through the thickness (3D)."""
    by_key = dict(zip(keys(points), u[:, 1]))
    i = int(round((centre[0] - DX / 2) / DX * 2))
    above = int(round((centre[1] + DX / 2) / DX * 2))
    below = int(round((centre[1] - DX / 2) / DX * 2))
    cod = [v - by_key[(k[0], below) + k[2:]] for k, v in by_key.items()
           if k[0] == i and k[1] == above and (k[0], below) + k[2:] in by_key]
    if not cod:
        raise SystemExit("FAILED: no particle pair across the crack's centre")
    return float(np.mean(cod))


def compare_plate(coupled_dir, full_dir, plate):
    dim = plate["dim"]
    xc, uc = last_particles(coupled_dir, dim)
    xp, up = last_particles(full_dir, dim)
    in_plate = [all(0 < c < s for c, s in zip(p, plate["size"])) for p in xp]
    full = {k: v for k, v, ok in zip(keys(xp), up, in_plate) if ok}
    scale = max(np.linalg.norm(v) for v in full.values())
    diff_core, diff_support = 0.0, 0.0
    n_core = n_support = 0
    for k, p, v in zip(keys(xc), xc, uc):
        if k not in full:
            continue
        d = np.linalg.norm(v - full[k])
        if inside(p, plate["support"]):
            diff_support = max(diff_support, d)
            n_support += 1
        if inside(p, plate["core"]):
            diff_core = max(diff_core, d)
            n_core += 1
    cod_c = crack_opening(xc, uc, plate["centre"])
    cod_p = crack_opening(xp, up, plate["centre"])
    return dict(error_core=diff_core / scale, error_support=diff_support / scale,
                n_core=n_core, n_support=n_support, cod=cod_c, cod_full=cod_p,
                cod_error=abs(cod_c - cod_p) / abs(cod_p), scale=scale)


def cracked_plate(solver, work, plate):
    rows = []
    stem = plate["name"].replace(" ", "_").lower()
    directory = os.path.join(work, stem + "_full_pd")
    os.makedirs(directory, exist_ok=True)
    prm = os.path.join(directory, "run.prm")
    fill(plate["full"], dict(DIRECTORY="results"), prm)
    out, wall_full = run(solver, prm, os.path.join(directory, "output.txt"))
    full_dir = os.path.join(directory, "results")
    n_full = int(need(RE_PARTICLES, out, "Particles", prm).group(1))
    for method in METHODS:
        directory = os.path.join(work, stem + "_" + SHORT[method])
        os.makedirs(directory, exist_ok=True)
        prm = os.path.join(directory, "run.prm")
        fill(plate["coupled"], dict(METHOD=method, DIRECTORY="results"), prm)
        log = os.path.join(directory, "output.txt")
        out, wall = run(solver, prm, log)
        row = dict(case=plate["name"], method=method, wall=wall, wall_full=wall_full,
                   particles=int(need(RE_PARTICLES, out, "Particles", log).group(1)),
                   particles_full=n_full, iterations=None)
        if method == "overlapping schwarz":
            row["iterations"] = int(need(RE_SCHWARZ, out, "Overlapping Schwarz", log).group(1))
        row.update(compare_plate(os.path.join(directory, "results"), full_dir, plate))
        rows.append(row)
    return rows


def fmt(x, digits=2):
    if x is None:
        return "—"
    if isinstance(x, int):
        return str(x)
    return f"{x:.{digits}e}"


def patch_table(rows):
    by = {(r["case"], r["method"]): r for r in rows}
    cases = list(dict.fromkeys(r["case"] for r in rows))
    lines = ["| case | exact for both models | blended: error FE / particles | blended: ghost force "
             "[N] (relative) | blended: time [s] | Schwarz: error FE / particles | Schwarz: "
             "residual of the exact field [N] (relative) | Schwarz: iterations | Schwarz: time "
             "[s] |",
             "|---|---|---|---|---|---|---|---|---|"]
    exact = {c[0]: c[3] for c in PATCH_CASES}
    for case in cases:
        b, s = by[(case, "blended")], by[(case, "overlapping schwarz")]
        lines.append(
            f"| {case} | {'yes' if exact[case] else 'no'} "
            f"| {fmt(b['error_fe'])} / {fmt(b['error_pd'])} "
            f"| {b['ghost']:.3g} ({fmt(b['ghost_rel'])}) | {b['wall']:.1f} "
            f"| {fmt(s['error_fe'])} / {fmt(s['error_pd'])} "
            f"| {s['ghost']:.3g} ({fmt(s['ghost_rel'])}) | {s['iterations']} | {s['wall']:.1f} |")
    return "\n".join(lines)


def sweep_key(r):
    return r["method"] if r["relaxation"] in (None, "aitken") else r["method"] + " none"


def sweep_table(rows):
    by = {(r["W"], sweep_key(r)): r for r in rows}
    lines = ["| W [mm] | particles | (W − δ − h) / δ | blended: error FE / particles | blended: ghost force "
             "(relative) | blended: time [s] | Schwarz: error FE / particles | Schwarz: iterations "
             "| Schwarz: time [s] | Schwarz without relaxation: error FE / particles | iterations "
             "| time [s] |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    delta, h = 3.015e-3, 4e-3
    for W in sorted({r["W"] for r in rows}):
        b, s = by[(W, "blended")], by[(W, "overlapping schwarz")]
        n = by[(W, "overlapping schwarz none")]
        lines.append(
            f"| {W * 1e3:g} | {b['particles']} | {(W - delta - h) / delta:.2f} "
            f"| {fmt(b['error_fe'])} / {fmt(b['error_pd'])} | {fmt(b['ghost_rel'])} "
            f"| {b['wall']:.1f} | {fmt(s['error_fe'])} / {fmt(s['error_pd'])} "
            f"| {s['iterations']} | {s['wall']:.1f} "
            f"| {fmt(n['error_fe'])} / {fmt(n['error_pd'])} | {n['iterations']} "
            f"| {n['wall']:.1f} |")
    return "\n".join(lines)


def plate_table(rows):
    lines = ["| case | method | particles (full PD) | largest difference, β = 1 core | largest difference, "
             "β > 0 | COD next to the centre [µm] (full PD) | COD difference | Schwarz iterations "
             "| time [s] (full PD) |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(
            f"| {r['case']} | {r['method']} | {r['particles']} ({r['particles_full']}) "
            f"| {fmt(r['error_core'])} ({r['n_core']} particles) "
            f"| {fmt(r['error_support'])} ({r['n_support']} particles) "
            f"| {r['cod'] * 1e6:.4f} ({r['cod_full'] * 1e6:.4f}) | {fmt(r['cod_error'])} "
            f"| {fmt(r['iterations'])} | {r['wall']:.1f} ({r['wall_full']:.1f}) |")
    return "\n".join(lines)


def plots(patch_rows, sweep_rows, plate_rows):
    cases = list(dict.fromkeys(r["case"] for r in patch_rows))
    by = {(r["case"], r["method"]): r for r in patch_rows}
    x = np.arange(len(cases))
    floor = 1e-16
    written = []
    for key, ylabel, fname in [
            ("error_pd", "largest particle displacement error / largest exact value",
             "error_per_case.png"),
            ("ghost_rel", "residual of the exact field / FE internal-force scale",
             "ghost_force_per_case.png"),
            ("wall", "wall time [s] (one rank)", "wall_time_per_case.png")]:
        fig, ax = plt.subplots(figsize=(10, 4.8))
        for k, method in enumerate(METHODS):
            values = [max(by[(c, method)][key], floor) for c in cases]
            ax.bar(x + (k - 0.5) * 0.38, values, 0.38, label=method)
        ax.set_yscale("log")
        ax.set_xticks(x)
        ax.set_xticklabels(cases, rotation=35, ha="right")
        ax.set_ylabel(ylabel)
        if key != "wall":
            ax.set_title(f"(values below {floor:g} drawn at {floor:g})", fontsize=9)
        ax.grid(axis="y", alpha=0.3)
        ax.legend()
        fig.tight_layout()
        fig.savefig(os.path.join(HERE, fname), dpi=110)
        plt.close(fig)
        written.append(fname)

    Ws = sorted({r["W"] for r in sweep_rows})
    sb = {(r["W"], sweep_key(r)): r for r in sweep_rows}
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4))
    a1.plot([w * 1e3 for w in Ws], [sb[(w, "overlapping schwarz")]["iterations"] for w in Ws],
            "o-", label="Schwarz, Aitken")
    a1.plot([w * 1e3 for w in Ws],
            [sb[(w, "overlapping schwarz none")]["iterations"] for w in Ws], "^-",
            label="Schwarz, no relaxation")
    a1.set_title("iterations to |G(x) - x| <= 1e-12 |G(x)|", fontsize=9)
    a1.set_xlabel("ramp width W [mm]")
    a1.set_ylabel("iterations")
    a1.grid(alpha=0.3)
    a1.legend()
    for method, style in zip(METHODS, ["s-", "o-"]):
        a2.semilogy([w * 1e3 for w in Ws], [max(sb[(w, method)]["error_pd"], floor) for w in Ws],
                    style, label=f"{method}: particle error")
    a2.semilogy([w * 1e3 for w in Ws], [sb[(w, "blended")]["ghost_rel"] for w in Ws], "s--",
                label="blended: relative ghost force")
    a2.set_xlabel("ramp width W [mm]")
    a2.grid(alpha=0.3)
    a2.legend(fontsize=8)
    fig.suptitle("PMB 2D uniform strain against the overlap width")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "overlap_sweep.png"), dpi=110)
    plt.close(fig)
    written.append("overlap_sweep.png")

    plates = list(dict.fromkeys(r["case"] for r in plate_rows))
    fig, ax = plt.subplots(figsize=(8, 4))
    labels = [f"{p}: {q}" for p in plates for q in ["β = 1 core", "β > 0", "COD at centre"]]
    xx = np.arange(len(labels))
    for k, method in enumerate(METHODS):
        values = []
        for p in plates:
            r = next(r for r in plate_rows if r["case"] == p and r["method"] == method)
            values += [r["error_core"], r["error_support"], r["cod_error"]]
        ax.bar(xx + (k - 0.5) * 0.38, values, 0.38, label=method)
    ax.set_xticks(xx)
    ax.set_xticklabels(labels, rotation=30, ha="right", fontsize=8)
    ax.set_ylabel("difference to full PD (relative)")
    ax.set_title("cracked plates, coupled against full PD")
    ax.grid(axis="y", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "cracked_plate.png"), dpi=110)
    plt.close(fig)
    written.append("cracked_plate.png")
    return written


def machine():
    cpu = platform.processor() or "unknown CPU"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return f"{platform.node()}, {cpu}, {os.cpu_count()} cores, {platform.system()} {platform.release()}"


def git_revision():
    """HEAD, marked when tracked files differ from it (the solver may not be HEAD's)."""
    try:
        def git(*args):
            return subprocess.run(["git", "-C", ROOT, *args], stdout=subprocess.PIPE, text=True,
                                  check=True).stdout.strip()
        head = git("rev-parse", "--short", "HEAD")
        return head + (" with uncommitted changes" if git("status", "--porcelain",
                                                           "--untracked-files=no") else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def write_report(results, solver):
    patch_rows, sweep_rows, plate_rows = results["patch"], results["sweep"], results["plate"]
    pngs = plots(patch_rows, sweep_rows, plate_rows)
    text = open(os.path.join(HERE, "report.md.in")).read()
    for key, value in {
            "DATE": results["date"], "MACHINE": results["machine"],
            "REVISION": results["revision"], "SOLVER": solver,
            "TOTAL": f"{results['total']:.0f}", "PATCH_TABLE": patch_table(patch_rows),
            "SWEEP_TABLE": sweep_table(sweep_rows), "PLATE_TABLE": plate_table(plate_rows),
            "NOT_EXACT": not_exact_summary(patch_rows),
    }.items():
        text = text.replace("@" + key + "@", value)
    left = re.findall(r"@[A-Z_]+@", text)
    if left:
        raise SystemExit(f"report.md.in: fields left unfilled: {left}")
    with open(os.path.join(ROOT, "doc", "coupling_methods.md"), "w") as f:
        f.write(text)
    return pngs


def not_exact_summary(rows):
    """One sentence per field the PD lattice does not reproduce: which method's particle error is
    the smaller, by what factor."""
    by = {(r["case"], r["method"]): r for r in rows}
    parts = []
    for name, _, _, exact in PATCH_CASES:
        if exact:
            continue
        b, s = by[(name, "blended")]["error_pd"], by[(name, "overlapping schwarz")]["error_pd"]
        smaller = "blended" if b < s else "Schwarz"
        parts.append(f"{name}: {smaller} smaller by {max(b, s) / min(b, s):.1f}×")
    return "; ".join(parts)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--work", default=os.path.join(HERE, "work"))
    parser.add_argument("--report-only", action="store_true",
                        help="no runs: rewrite the report and plots from WORK/results.json")
    args = parser.parse_args()
    solver = os.path.join(os.path.abspath(args.build), "bin", "perideal-solid")
    work = os.path.abspath(args.work)
    if args.report_only:
        results = json.load(open(os.path.join(work, "results.json")))
        pngs = write_report(results, results["solver"])
        print(f"wrote doc/coupling_methods.md and {', '.join(pngs)} from {work}/results.json")
        return
    if not os.access(solver, os.X_OK):
        raise SystemExit(f"FAILED: no executable {solver}")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    start = time.perf_counter()

    print("== patch tests")
    patch_rows = []
    for name, template, fields, _ in PATCH_CASES:
        for method in METHODS:
            patch_rows.append(patch_run(solver, work, name, template, fields, method,
                                        PATCH_W[template]))
    print("== overlap sweep (PMB 2D uniform strain)")
    sweep_rows = []
    for W in SWEEP_W:
        geometry = dict(W=f"{W * 1e-3:g}", BLENDING=box_ramp(2, f"{0.04 - W * 1e-3:g}",
                                                             f"{0.06 + W * 1e-3:g}", f"{W * 1e-3:g}"))
        for method, relaxation in SWEEP_METHODS:
            sweep_rows.append(patch_run(solver, work, "sweep PMB 2D uniform strain", "patch_2d",
                                        dict(PMB, EXACT=UNIFORM, BODY_FORCE="0; 0"), method,
                                        dict(geometry, RELAXATION=relaxation)))
    print("== cracked plates")
    plate_rows = []
    for plate in PLATES:
        plate_rows += cracked_plate(solver, work, plate)
    total = time.perf_counter() - start

    results = dict(patch=patch_rows, sweep=sweep_rows, plate=plate_rows, total=total,
                   date=datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
                   machine=machine(), revision=git_revision(), solver=solver)
    with open(os.path.join(work, "results.json"), "w") as f:
        json.dump(results, f, indent=1)
    pngs = write_report(results, solver)
    print(f"wrote doc/coupling_methods.md and {', '.join(pngs)}; runs took {total:.0f} s")


if __name__ == "__main__":
    main()
