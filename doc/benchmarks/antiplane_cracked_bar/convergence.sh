#!/usr/bin/env bash
# The state-based antiplane model (stabilization 0.1) with the lattice calibration of G_IIIc
# (issue #40): its critical far-field stress in the gripped cracked bar against the lattice
# spacing, and the crack-tip toughness of the lattice under a K_III field (k_field.prm, both
# antiplane models). Each bar run raises the far field S = 2 mu Delta / W only through a window
# around its critical stress (<Solver/Control/Load history> = time: Delta = A + B t), in steps of
# 0.2-0.5 %, the bracket's width. convergence.py prints the tables of README.md. About 35 minutes on
# 2 (busy) cores, the dx = 0.005 runs (40 000 particles) 10 minutes each; results go to
# results_convergence/ next to this script.
# usage: bash doc/benchmarks/antiplane_cracked_bar/convergence.sh [BUILD_DIR]   (default: build)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="$(cd "${1:-build}" && pwd)"
solver="$build/bin/perideal-solid"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$here"
results=results_convergence
rm -rf "$results"
mkdir -p "$results"

# bar NAME MODEL DX A S0 S1 STEPS SOLVER: cracked_bar_grips.prm at lattice spacing DX (grips of
# four rows), half crack length A, the lattice calibration, the far field from S0 to S1 psi.
bar() {
  /usr/bin/python3 - "$@" <<'PY'
import re, sys
name, model, dx, a, s0, s1, steps, solver = sys.argv[1:]
s = open("cracked_bar_grips.prm").read()
grip = round(0.5 + 4 * float(dx), 10)
A, B = float(s0) / 24e6, (float(s1) - float(s0)) / 24e6  # S = 2 mu Delta / W
edits = [("set Lattice spacing = 0.01", f"set Lattice spacing = {dx}"),
         ("0.5, 0.54", f"0.5, {grip}"), ("-0.5, -0.54", f"-0.5, -{grip}"),
         ("set Model           = antiplane bond based", f"set Model           = {model}"),
         ("set Fracture energy = 2.1161",
          "set Fracture energy = 2.1161\n    set Fracture energy calibration = lattice"),
         ("set Function = 8e-4", f"set Function = {A:.10g}+{B:.10g}*t"),
         ("set Function = -8e-4", f"set Function = -({A:.10g}+{B:.10g}*t)"),
         ("set Linear solver = direct", f"set Linear solver = {solver}"),
         ("subsection Solver", "subsection Time stepping\n  set End time = 1\nend\nsubsection Solver"),
         ("set Load steps    = 160",
          f"set Load steps    = {steps}\n  subsection Control\n    set Load history = time\n  end"),
         ("set Write HDF5 = true", "set Write HDF5 = false")]
for old, new in edits:
    assert old in s, old
    s = s.replace(old, new, 1)
s = re.sub(r"set Cracks = .*", f"set Cracks = -{a}, 0 : {a}, 0", s)
s = re.sub(r"set Directory *= .*", f"set Directory  = results_convergence/{name}", s)
open(f"results_convergence/{name}.prm", "w").write(s)
PY
}
state="antiplane state based"
runs=()
bar bar_sb_dx0.02_a0.2 "$state" 0.02 0.2 5000 11000 60 "cg amg"
bar bar_sb_dx0.01_a0.2 "$state" 0.01 0.2 8800 10000 48 "cg amg"
bar bar_sb_dx0.005_a0.2 "$state" 0.005 0.2 8800 10000 32 "cg amg"
bar bar_sb_dx0.02_a0.1 "$state" 0.02 0.1 10000 14000 80 "cg amg"
bar bar_sb_dx0.01_a0.1 "$state" 0.01 0.1 11800 13400 64 "cg amg"
bar bar_sb_dx0.005_a0.1 "$state" 0.005 0.1 12000 13400 40 "cg amg"
bar bar_bb_dx0.02_a0.2 "antiplane bond based" 0.02 0.2 5000 11000 60 direct
bar bar_bb_dx0.01_a0.2 "antiplane bond based" 0.01 0.2 9600 11000 56 direct
runs+=(bar_sb_dx0.02_a0.2 bar_sb_dx0.01_a0.2 bar_sb_dx0.005_a0.2 bar_sb_dx0.02_a0.1
  bar_sb_dx0.01_a0.1 bar_sb_dx0.005_a0.1 bar_bb_dx0.02_a0.2 bar_bb_dx0.01_a0.2)
sed -e "s|set Directory *= .*|set Directory  = $results/k_field_sb|" k_field.prm \
  > "$results/k_field_sb.prm"
sed -e "s|set Directory *= .*|set Directory  = $results/k_field_bb|" \
  -e "s|set Model *= antiplane state based|set Model           = antiplane bond based|" \
  -e "s|Linear solver = cg amg|Linear solver = direct|" k_field.prm > "$results/k_field_bb.prm"
# without the surface correction (the pre-crack's faces as a grown crack's), K from 1.1 K_IIIc
sed -e "s|set Directory *= .*|set Directory  = $results/k_field_sb_nosc|" \
  -e "s|set Body            = body|set Body            = body\n  set Surface correction = false|" \
  -e "s|0.8+0.5\*t|1.1+0.5*t|" k_field.prm > "$results/k_field_sb_nosc.prm"
runs+=(k_field_sb k_field_bb k_field_sb_nosc)
for run in "${runs[@]}"; do
  echo "== $run"
  mpirun -np 2 "$solver" "$results/$run.prm" > "$results/$run.log" 2>&1 || {
    cat "$results/$run.log"
    exit 1
  }
done
/usr/bin/python3 convergence.py "$results"
