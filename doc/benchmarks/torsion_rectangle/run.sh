#!/usr/bin/env bash
# Torsion of the 1 x 2 rectangular bar (seed 000, example 8.4): the FE file torsion_fe.prm under
# uniform refinement (Q1: h = 1/4 ... 1/128; Q2: h = 1/4 ... 1/32) and the PD file torsion_pd.prm
# for dx = 0.1 ... 0.01 (horizon 3.015 dx), then postprocess.py prints the convergence table against
# the Saint-Venant series and draws torsion_convergence.png and torsion_stresses.png. A few minutes
# on 2 cores; results go to results/ next to this script.
# usage: bash doc/benchmarks/torsion_rectangle/run.sh [BUILD_DIR]   (default: build)
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

fe_runs=()
for degree in 1 2; do
  last=7
  [ "$degree" = 2 ] && last=5
  for level in $(seq 2 $last); do
    name="fe_q${degree}_l${level}"
    variant torsion_fe "$name" -e "s|Global refinements  = .*|Global refinements  = $level|" \
      -e "s|Polynomial degree   = .*|Polynomial degree   = $degree|"
    fe_runs+=("results/$name")
  done
done
pd_runs=()
for dx in 0.1 0.05 0.025 0.02 0.0125 0.01; do
  name="pd_dx$dx"
  # The particle nearest to the axis, (dx/2, dx/2), holds the warping at 0.
  variant torsion_pd "$name" -e "s|Lattice spacing = .*|Lattice spacing = $dx|" \
    -e "s|Lower corner = 0.002, 0.002|Lower corner = $(python3 -c "print($dx * 0.1)"), $(python3 -c "print($dx * 0.1)")|" \
    -e "s|Upper corner = 0.018, 0.018|Upper corner = $(python3 -c "print($dx * 0.9)"), $(python3 -c "print($dx * 0.9)")|"
  pd_runs+=("results/$name")
done
for run in "${fe_runs[@]}" "${pd_runs[@]}"; do
  echo "== $run"
  mpirun -np 2 "$solver" "$run.prm" | grep -E '^(Particles|FE region|Section integrals|Strain energy)'
done
/usr/bin/python3 postprocess.py --fe "${fe_runs[@]}" --pd "${pd_runs[@]}" \
  --plot torsion_convergence.png --stresses results/pd_dx0.02 torsion_stresses.png
