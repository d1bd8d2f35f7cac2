#!/usr/bin/env bash
# End to end: install dependencies if missing (as root), build PeriDeal, run the Kalthoff-Winkler
# benchmark on 2 MPI ranks, post-process (damage map, energies, crack angle) and say where the
# results are.
#
# Usage: run.sh [--dx SPACING] [--np N] [--prm FILE] [--app NAME]
#   --dx SPACING  lattice spacing [m] instead of the 1e-3 of the parameter file (horizon =
#                 3.015 dx; the output intervals are scaled to keep ~25 snapshots), e.g.
#                 --dx 5e-4 (1 min on 2 cores) or --dx 2.5e-4 (about 6 min, 322 400 particles);
#   --np N        MPI ranks (default 2);
#   --prm FILE    another parameter file of the same case (default kalthoff_pd.prm beside this
#                 script; a coupled variant keeps the same output names and post-processing);
#   --app NAME    the application in the build's bin/ (default perideal-solid).
# Environment: PERIDEAL_BUILD_DIR (default <top>/build), PERIDEAL_RESULTS_DIR (default
# <top>/results/kalthoff_winkler[_dx<SPACING>]), PYTHON (default /usr/bin/python3).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../../.." && pwd)

dx="" np=2 prm="$here/kalthoff_pd.prm" app=perideal-solid
while [ $# -gt 0 ]; do
  case "$1" in
    --dx) dx=$2; shift 2 ;;
    --np) np=$2; shift 2 ;;
    --prm) prm=$(cd "$(dirname "$2")" && pwd)/$(basename "$2"); shift 2 ;;
    --app) app=$2; shift 2 ;;
    -h|--help) sed -n 2,15p "$0"; exit 0 ;;
    *) echo "run.sh: unknown argument <$1> (see run.sh --help)" >&2; exit 1 ;;
  esac
done
python=${PYTHON:-/usr/bin/python3}

# Dependencies: only when something is missing (contrib/install_dependencies.sh holds the list).
if ! { command -v cmake && command -v ninja && command -v mpirun && command -v numdiff &&
       dpkg -s libdeal.ii-dev && "$python" -c "import numpy, h5py, matplotlib"; } >/dev/null 2>&1; then
  if [ "$(id -u)" -eq 0 ]; then
    "$top/contrib/install_dependencies.sh"
  else
    echo "run.sh: dependencies missing; run contrib/install_dependencies.sh as root first" >&2
    exit 1
  fi
fi
if [ "$(id -u)" -eq 0 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi

# Build (incremental: a no-op when up to date).
"$top/contrib/build.sh"
build=${PERIDEAL_BUILD_DIR:-$top/build}

results=${PERIDEAL_RESULTS_DIR:-$top/results/kalthoff_winkler${dx:+_dx$dx}}
mkdir -p "$results"
cd "$results"
if [ -n "$dx" ]; then
  # A parameter file that includes the benchmark's and overrides the resolution.
  scale=$("$python" -c "print(max(1, round(1e-3 / float('$dx'))))")
  cat > kalthoff_dx.prm <<EOF
include $prm
subsection Discretization
  set Lattice spacing = $dx
end
subsection Output
  set Particle output interval = $((25 * scale))
  set Statistics interval      = $((5 * scale))
end
EOF
  prm=$results/kalthoff_dx.prm
fi

start=$(date +%s)
mpirun -np "$np" "$build/bin/$app" "$prm" | tee run.log
echo "Wall time of the run: $(( $(date +%s) - start )) s (mpirun -np $np)" | tee -a run.log
"$python" "$here/postprocess.py" "$results" | tee postprocess.log
echo
echo "Results in $results: statistics.csv, particles.xdmf (open in ParaView), damage_final.png,"
echo "energies.png, crack_angle.png, crack_angle.csv, run.log, postprocess.log."
