#!/usr/bin/env bash
# Torsion of the 1 x 2 bar with an edge crack (seed 000, example 8.5): for the crack lengths
# a = 0, 0.25, 0.5, 0.75 (a/b with b = 1, the side the crack runs across) the FE file
# torsion_crack_fe.prm on the slit mesh of make_mesh.py (Q2, h = 1/32, 1/64, 1/128) and the PD file
# torsion_crack_pd.prm with the bond-based and the state-based antiplane model (dx = 0.02, 0.01),
# and for a > 0 the coupled file torsion_crack_coupled.prm (PD around the crack, FE elsewhere) with
# the same models and lattices (wall times on 2 ranks; a = 0.5, dx = 0.01 again on one core,
# taskset -c 0), then postprocess.py prints the torque tables against the FE value extrapolated to
# h = 0 and the coupled against the all-PD torques, and draws torque_vs_crack.png and
# stress_near_crack.png. About 25 minutes on 2 cores; results go to results/ next to this script.
# usage: bash doc/benchmarks/torsion_edge_crack/run.sh [BUILD_DIR]   (default: build)
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
for a in 0 0.25 0.5 0.75; do
  /usr/bin/python3 make_mesh.py "$a" 16 "results/section_a$a.msh"
  for level in 1 2 3; do
    name="fe_a${a}_l$level"
    variant torsion_crack_fe "$name" -e "s|Mesh file *= .*|Mesh file = results/section_a$a.msh|" \
      -e "s|Global refinements = .*|Global refinements = $level|"
    runs+=("results/$name")
  done
  tip=$(python3 -c "print(-0.5 + $a)")
  for model in bond state; do
    # The state-based model as the seed has it (stabilization 0; 'statestab': 0.1, below).
    seed=(-e "/subsection antiplane state based/,/end/s|\(set Twist axis *= .*\)|\1\n    set Stabilization         = 0|")
    for dx in 0.02 0.01; do
      name="pd_${model}_a${a}_dx$dx"
      lo=$(python3 -c "print($dx * 0.1)")
      hi=$(python3 -c "print($dx * 0.9)")
      crack="-0.6, 0 : $tip, 0"
      [ "$a" = 0 ] && crack=""
      variant torsion_crack_pd "$name" -e "s|Lattice spacing = .*|Lattice spacing = $dx|" \
        -e "s|Cracks = .*|Cracks = $crack|" \
        -e "s|Model   = antiplane bond based|Model   = antiplane $model based|" \
        -e "s|subsection antiplane bond based|subsection antiplane $model based|" "${seed[@]}" \
        -e "s|Lower corner = 0.002, 0.002|Lower corner = $lo, $lo|" \
        -e "s|Upper corner = 0.018, 0.018|Upper corner = $hi, $hi|"
      runs+=("results/$name")
      if [ "$model" = state ] && [ "$a" = 0.5 ] && [ "$dx" = 0.01 ]; then
        # The state-based model with the default stabilization 0.1: the crack opening.
        sed -e "s|Stabilization         = 0|Stabilization         = 0.1|" \
          -e "s|results/$name|results/pd_statestab_a${a}_dx$dx|" "results/$name.prm" \
          > "results/pd_statestab_a${a}_dx$dx.prm"
        runs+=("results/pd_statestab_a${a}_dx$dx")
      fi
      [ "$a" = 0 ] && continue
      # Coupled: PD in the box of the crack (beta = 1 to 0.1 beyond the tip and the crack line,
      # ramps to 0.2), FE Q2 on the plain mesh (h = 1/16) elsewhere.
      name="coupled_${model}_a${a}_dx$dx"
      variant torsion_crack_coupled "$name" -e "s|Lattice spacing = .*|Lattice spacing = $dx|" \
        -e "s|Cracks = .*|Cracks = $crack|" \
        -e "s|Model   = antiplane bond based|Model   = antiplane $model based|" \
        -e "s|subsection antiplane bond based|subsection antiplane $model based|" "${seed[@]}" \
        -e "s|(0.2 - x) / 0.1|($(python3 -c "print(round($tip + 0.2, 6))") - x) / 0.1|"
      runs+=("results/$name")
    done
  done
done
# Each run on 2 ranks; its wall time (set-up, solve and output) goes to results/NAME.time.
for run in "${runs[@]}"; do
  echo "== $run"
  start=$(date +%s.%N)
  mpirun -np 2 "$solver" "$run.prm" | grep -E '^(Particles|FE region|Load step|Section integrals)'
  python3 -c "print(f'{$(date +%s.%N) - $start:.2f}')" > "$run.time"
done
# One-rank wall times (results/NAME.time1) of the all-PD and the coupled run, a = 0.5, dx = 0.01.
for model in bond state; do
  for kind in pd coupled; do
    run="results/${kind}_${model}_a0.5_dx0.01"
    start=$(date +%s.%N)
    taskset -c 0 "$solver" "$run.prm" > /dev/null
    python3 -c "print(f'{$(date +%s.%N) - $start:.2f}')" > "$run.time1"
  done
done
/usr/bin/python3 postprocess.py "${runs[@]}" --plot torque_vs_crack.png \
  --stresses results/pd_bond_a0.5_dx0.01 results/pd_state_a0.5_dx0.01 stress_near_crack.png
/usr/bin/python3 opening.py results/fe_a0.5_l3 results/pd_bond_a0.5_dx0.01 \
  results/pd_state_a0.5_dx0.01 results/pd_statestab_a0.5_dx0.01 --plot crack_opening.png
