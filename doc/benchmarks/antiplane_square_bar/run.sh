#!/usr/bin/env bash
# The square bar under antiplane shear (seed 000, example 8.1): the PD file square_bar_pd.prm with
# the bond-based model, the state-based model (the paper's, stabilization 0) and the state-based
# model with stabilization 0.1, for dx = 0.04 ... 0.005 (horizon 3.015 dx, six fictitious layers
# beyond each clamped side), and the FE file square_bar_fe.prm (Q1, h = 1/8 ... 1/256); then
# postprocess.py prints the table against the series and draws square_bar_field.png and
# square_bar_convergence.png. About ten minutes on 2 cores; results go to results/ next to this
# script.
# usage: bash doc/benchmarks/antiplane_square_bar/run.sh [BUILD_DIR]   (default: build)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="$(cd "${1:-build}" && pwd)"
solver="$build/bin/perideal-solid"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$here"
rm -rf results
mkdir -p results

# variant SOURCE NAME SED-EXPRESSIONS...: SOURCE.prm with its output directory set to
# results/NAME and the given edits, written to results/NAME.prm.
variant() {
  local source=$1 name=$2
  shift 2
  sed -e "s|set Directory    = .*|set Directory    = results/$name|" \
    -e "s|set Directory = .*|set Directory = results/$name|" "$@" "$source.prm" > "results/$name.prm"
}

runs=()
for dx in 0.04 0.02 0.01 0.005; do
  # Six fictitious layers beyond each side, the top row of particles and the probe, for this dx.
  layers=(-e "s|Lattice spacing = .*|Lattice spacing = $dx|"
    -e "s|Lower corner = -0.56, -0.5|Lower corner = $(python3 -c "print(-0.5 - 6 * $dx)"), -0.5|"
    -e "s|Upper corner = 0.56, 0.5|Upper corner = $(python3 -c "print(0.5 + 6 * $dx)"), 0.5|"
    -e "s|Lower corner = -0.5, 0.49|Lower corner = -0.5, $(python3 -c "print(0.5 - $dx)")|"
    -e "s|Layer thickness = .*|Layer thickness = $dx|"
    -e "s|Probe points = .*|Probe points = $(python3 -c "print($dx / 2)"), $(python3 -c "print(0.5 - $dx / 2)")|")
  variant square_bar_pd "bb_dx$dx" "${layers[@]}"
  variant square_bar_pd "sb_dx$dx" "${layers[@]}" \
    -e "s|set Model   = .*|set Model   = antiplane state based|"
  variant square_bar_pd "sbs0.1_dx$dx" "${layers[@]}" \
    -e "s|set Model   = .*|set Model   = antiplane state based|" \
    -e "s|Stabilization = 0|Stabilization = 0.1|"
  runs+=("results/bb_dx$dx" "results/sb_dx$dx" "results/sbs0.1_dx$dx")
done
fe_runs=()
for level in 3 4 5 6 7 8; do
  variant square_bar_fe "fe_l$level" -e "s|Global refinements  = .*|Global refinements  = $level|"
  fe_runs+=("results/fe_l$level")
done
for run in "${runs[@]}" "${fe_runs[@]}"; do
  echo "== $run"
  mpirun -np 2 "$solver" "$run.prm" | grep -E '^(Particles|FE region|Probe|  \()' || true
done
/usr/bin/python3 postprocess.py --pd "${runs[@]}" --fe "${fe_runs[@]}" \
  --plot square_bar_field.png square_bar_convergence.png
