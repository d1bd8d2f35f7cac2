#!/usr/bin/env bash
# End to end: install dependencies (as root), build PeriDeal, run the thin-plate tension benchmark
# of seed 002 to steady state on 2 MPI ranks, compare with plane-stress elasticity and plot.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../../.." && pwd)
if [ "$(id -u)" -eq 0 ]; then
  "$top/contrib/install_dependencies.sh"
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
"$top/contrib/build.sh"
build=${PERIDEAL_BUILD_DIR:-$top/build}
results=${PERIDEAL_RESULTS_DIR:-$top/results/plate_uniaxial_tension}
mkdir -p "$results"
cd "$results"
prm=${1:-$here/plate_uniaxial_tension.prm}
mpirun -np 2 "$build/bin/perideal-solid" "$prm"
"${PYTHON:-/usr/bin/python3}" "$here/postprocess.py" "$results"
echo
echo "Results in $results: statistics.csv, particles.xdmf (open in ParaView), *.png plots."
