#!/usr/bin/env bash
# End to end: install dependencies (as root), build PeriDeal, run the plate of seed 003 sec. 3.1
# with the Timoshenko-bond model for nu = 0.1 ... 0.3 (lattice calibration with the stiffness fit
# and with the energy method of surface correction, continuum calibration) and with the classical
# bond-based model (nu = 1/3), compare the interior displacements with plane-stress elasticity
# and plot the effective Poisson ratio against the target (nu_eff.png) and u_y across the plate
# (u_y.png). usage: run.sh   (PERIDEAL_BUILD_DIR, PERIDEAL_RESULTS_DIR override the defaults)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../../.." && pwd)
if [ "$(id -u)" -eq 0 ]; then
  "$top/contrib/install_dependencies.sh"
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
"$top/contrib/build.sh"
build=${PERIDEAL_BUILD_DIR:-$top/build}
results=${PERIDEAL_RESULTS_DIR:-$top/results/timoshenko_plate}
mkdir -p "$results"
cd "$results"
strain=$(awk 'BEGIN {print 2e8 / 1.92e11}')
case_run() { # name model nu calibration surface-correction-method hold
  cat > "$1.prm" <<PRM
include $here/timoshenko_plate.prm
subsection Discretization
  set Surface correction method = $5
end
subsection Material
  set Model = $2
  subsection timoshenko bond based
    set Poisson's ratio = $3
    set Calibration     = $4
  end
end
subsection Boundary conditions
  subsection hold
    set Function = $6
  end
end
subsection Output
  set Directory = $1
end
PRM
  mpirun -np 2 "$build/bin/perideal-solid" "$1.prm" > "$1.log"
  echo "$1: done"
}
# The Timoshenko series: lattice calibration with the stiffness fit (the recommended set-up) and
# with the energy method, continuum calibration with the stiffness fit.
for nu in 0.1 0.15 0.2 0.25 0.3; do
  for series in "lattice fit" "lattice energy" "continuum fit"; do
    set -- $series
    method=$([ "$2" = fit ] && echo "stiffness fit" || echo energy)
    case_run "${1}_${2}_$nu" "timoshenko bond based" "$nu" "$1" "$method" \
      "$strain * x; -$nu * $strain * y; 0"
  done
done
for method in fit energy; do
  case_run "pmb_$method" "bond based" 0.333333333333333 lattice \
    "$([ "$method" = fit ] && echo "stiffness fit" || echo energy)" \
    "$strain * x; -0.333333333333333 * $strain * y"
done
"${PYTHON:-/usr/bin/python3}" "$here/postprocess.py" "$results"
echo
echo "Results in $results: one directory per case (particles.xdmf opens in ParaView), *.png plots."
