#!/usr/bin/env bash
# The bimaterial bar under antiplane shear (seed 000, example 8.2): the PD file bimaterial_pd.prm
# with the bond-based model, the state-based model (the paper's, stabilization 0) and the
# state-based model with stabilization 0.1, for dx = 0.02 ... 0.0025 (horizon 3.015 dx, six
# fictitious layers below the bar), and the FE file bimaterial_fe.prm at two refinements; then
# postprocess.py prints the error table against the exact solution and draws
# bimaterial_profile.png and bimaterial_convergence.png. A few minutes on 2 cores; results go
# to results/ next to this script.
# usage: bash doc/benchmarks/antiplane_bimaterial/run.sh [BUILD_DIR]   (default: build)
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
  sed -e "s|set Directory = .*|set Directory = results/$name|" "$@" "$source.prm" > "results/$name.prm"
}

runs=()
for dx in 0.02 0.01 0.005 0.0025; do
  # Six fictitious layers below the bar and the top row of particles, for this dx.
  layers=(-e "s|Lattice spacing = .*|Lattice spacing = $dx|"
    -e "s|Lower corner = -0.1, -0.56|Lower corner = -0.1, $(python3 -c "print(-0.5 - 6 * $dx)")|"
    -e "s|Lower corner = -0.1, 0.49|Lower corner = -0.1, $(python3 -c "print(0.5 - $dx)")|"
    -e "s|Layer thickness = .*|Layer thickness = $dx|")
  variant bimaterial_pd "bb_dx$dx" "${layers[@]}"
  variant bimaterial_pd "sb_dx$dx" "${layers[@]}" \
    -e "s|set Model   = .*|set Model   = antiplane state based|"
  variant bimaterial_pd "sbs0.1_dx$dx" "${layers[@]}" \
    -e "s|set Model   = .*|set Model   = antiplane state based|" \
    -e "s|Stabilization          = 0|Stabilization          = 0.1|"
  runs+=("results/bb_dx$dx" "results/sb_dx$dx" "results/sbs0.1_dx$dx")
done
fe_runs=()
for level in 0 3; do
  variant bimaterial_fe "fe_l$level" -e "s|Global refinements = .*|Global refinements = $level|"
  fe_runs+=("results/fe_l$level")
done
for run in "${runs[@]}" "${fe_runs[@]}"; do
  echo "== $run"
  mpirun -np 2 "$solver" "$run.prm" | grep -E '^(Particles|FE region|Displacement error)'
done
/usr/bin/python3 postprocess.py --pd "${runs[@]}" --fe "${fe_runs[@]}" \
  --plot bimaterial_profile.png bimaterial_convergence.png
