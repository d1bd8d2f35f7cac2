#!/usr/bin/env bash
# The square bar with a central crack under antiplane shear (seed 000, example 8.3), lattice
# dx = 0.01 (the paper's), bond-based and state-based (stabilization 0.1) side by side:
#  - the paper's loading, cracked_bar_traction.prm: the crack of total length 0.2 under the
#    tractions +-S = 12000 psi, load steps with bond breaking (the growth arrests);
#  - growth to separation, cracked_bar_grips.prm: the half crack lengths a = 0.1 (the total-length
#    reading) and a = 0.2 (the half-length reading) loaded through grips in 160 load steps;
#  - the coupled variant, cracked_bar_coupled.prm: a = 0.2 under grips with PD only in a band
#    around the crack line, FE elsewhere;
#  - the FE reference of the gripped bar, cracked_bar_fe.prm (Q2 on the half bar of
#    make_mesh.py, h = 1/100 ... 1/400) for a and a +- 0.02: the energy release rate, hence the
#    critical far-field stress; and of the paper's loading (the traction S on the top instead of
#    the grip, a = 0.1): the crack opening;
# then postprocess.py prints the tables and draws load_vs_grip.png, damage.png and
# crack_opening.png. About 50 minutes on 2 (busy) cores; results go to results/ next to this
# script.
# usage: bash doc/benchmarks/antiplane_cracked_bar/run.sh [BUILD_DIR]   (default: build)
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
  sed -e "s|set Directory *= .*|set Directory  = results/$name|" "$@" "$source.prm" > "results/$name.prm"
}
# The state-based model's system couples particles two horizons apart: conjugate gradients
# with AMG instead of the direct solver, and half the load steps under grips.
state=(-e "s|set Model *= antiplane bond based|set Model = antiplane state based|"
  -e "s|Linear solver = direct|Linear solver = cg amg|")

runs=()
variant cracked_bar_traction traction_bb
# (its crack cuts the bar: the singular solve stops after 5000 CG iterations, not 100000)
variant cracked_bar_traction traction_sb "${state[@]}" \
  -e "s|set Load steps    = 12|set Load steps    = 12\n  set Maximum iterations = 5000|"
runs+=(results/traction_bb results/traction_sb)
/usr/bin/python3 make_mesh.py 0.1 50 results/half_traction.msh
variant cracked_bar_fe fe_traction -e "s|Mesh file *= .*|Mesh file = results/half_traction.msh|" \
  -e "s|Global refinements = .*|Global refinements = 3|" \
  -e "/subsection grip/,/end/{s|Type *= value|Type         = flux|;s|Function *= .*|Function     = 12000|}"
runs+=(results/fe_traction)
variant cracked_bar_coupled coupled_bb
variant cracked_bar_coupled coupled_sb "${state[@]}" -e "s|Load steps    = 160|Load steps    = 80|"
runs+=(results/coupled_bb results/coupled_sb)
for a in 0.1 0.2; do
  crack=(-e "s|Cracks = .*|Cracks = -$a, 0 : $a, 0|")
  variant cracked_bar_grips "grips_bb_a$a" "${crack[@]}"
  variant cracked_bar_grips "grips_sb_a$a" "${crack[@]}" "${state[@]}" \
    -e "s|Load steps    = 160|Load steps    = 80|"
  runs+=("results/grips_bb_a$a" "results/grips_sb_a$a")
  for fa in $(python3 -c "print('%g %g %g' % ($a - 0.02, $a, $a + 0.02))"); do
    /usr/bin/python3 make_mesh.py "$fa" 50 "results/half_a$fa.msh"
    for level in 1 2 3; do
      name="fe_a${fa}_l$level"
      variant cracked_bar_fe "$name" -e "s|Mesh file *= .*|Mesh file = results/half_a$fa.msh|" \
        -e "s|Global refinements = .*|Global refinements = $level|"
      runs+=("results/$name")
    done
  done
done
# Each run's log goes to results/NAME.log, its wall time (2 ranks) to results/NAME/wall_time.
# Under the paper's tractions the state-based model's crack cuts the bar, after which no
# equilibrium exists: that run ends with the static solve's error, reported and expected.
for run in "${runs[@]}"; do
  echo "== $run"
  start=$(date +%s.%N)
  if mpirun -np 2 "$solver" "$run.prm" > "$run.log" 2>&1; then
    python3 -c "print($(date +%s.%N) - $start)" > "$run/wall_time"
  elif [ "$run" = results/traction_sb ]; then
    echo "   stopped: $(grep -m1 -o 'The coupled static solve[^.]*' "$run.log")"
  else
    cat "$run.log"
    exit 1
  fi
  grep -E '^(Particles|FE region|Broken bonds|Reaction|Strain energy)' "$run.log" || true
done
/usr/bin/python3 postprocess.py results --plot load_vs_grip.png --damage damage.png \
  --opening crack_opening.png
