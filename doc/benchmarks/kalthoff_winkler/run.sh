#!/usr/bin/env bash
# End to end: install dependencies if missing (as root), build PeriDeal, run the Kalthoff-Winkler
# benchmark on 2 MPI ranks, post-process (damage map, energies, crack angle) and say where the
# results are. By default the flagship: the coupled FE + PD variant whose PD region follows the
# cracks from two disks at the notch tips (kalthoff_adaptive.prm), the coupled variant with PD in
# a band placed on the known crack path (kalthoff_coupled.prm) and their all-PD reference with
# the same model and lattice (kalthoff_pd_pmb.prm), then the three crack angles and the ratios of
# the wall times and of the peak memories to the all-PD run's.
#
# Usage: run.sh [--dx SPACING] [--np N] [--prm FILE] [--app NAME]
#   --dx SPACING  lattice spacing [m] instead of the 1e-3 of the parameter files (horizon =
#                 3.015 dx; the output intervals are scaled to keep ~25 snapshots), e.g.
#                 --dx 1e-3 (10 s on 2 cores) or --dx 5e-4 (20 s); the flagship runs at
#                 2.5e-4 unless --dx or --prm is given (a few minutes; the coupled band of PD
#                 needs dx <= 0.5 mm, see kalthoff_coupled.prm);
#   --np N        MPI ranks (default 2);
#   --prm FILE    run only this parameter file of the case (e.g. kalthoff_pd.prm, the all-PD
#                 state-based variant); every variant keeps the same output names and
#                 post-processing;
#   --app NAME    the application in the build's bin/ (default perideal-solid).
# Environment: PERIDEAL_BUILD_DIR (default <top>/build), PERIDEAL_RESULTS_DIR (default
# <top>/results/kalthoff_winkler[_dx<SPACING>]; each variant in a subdirectory named after its
# parameter file), PYTHON (default /usr/bin/python3).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../../.." && pwd)

flagship=("$here/kalthoff_adaptive.prm" "$here/kalthoff_coupled.prm" "$here/kalthoff_pd_pmb.prm")
dx="" np=2 prms=("${flagship[@]}") app=perideal-solid
while [ $# -gt 0 ]; do
  case "$1" in
    --dx) dx=$2; shift 2 ;;
    --np) np=$2; shift 2 ;;
    --prm) prms=("$(cd "$(dirname "$2")" && pwd)/$(basename "$2")"); shift 2 ;;
    --app) app=$2; shift 2 ;;
    -h|--help) sed -n 2,21p "$0"; exit 0 ;;
    *) echo "run.sh: unknown argument <$1> (see run.sh --help)" >&2; exit 1 ;;
  esac
done
# Dependencies, Open MPI as root, the build: python, build.
source "$here/../run_preamble.sh"

# The flagship at the resolution its coupled band needs.
if [ -z "$dx" ] && [ ${#prms[@]} -eq 3 ]; then
  dx=2.5e-4
fi
results_top=${PERIDEAL_RESULTS_DIR:-$top/results/kalthoff_winkler${dx:+_dx$dx}}
summary=()
for prm in "${prms[@]}"; do
  name=$(basename "$prm" .prm)
  results=$results_top/$name
  mkdir -p "$results"
  cd "$results"
  # A parameter file that includes the benchmark's (whose mesh path is relative to it) and
  # overrides, with --dx, the resolution.
  scale=$("$python" -c "print(max(1, round(1e-3 / float('${dx:-1e-3}'))))")
  {
    echo "include $prm"
    if [ -n "$dx" ]; then
      echo "subsection Discretization"
      echo "  set Lattice spacing = $dx"
      echo "end"
      echo "subsection Output"
      echo "  set Output interval = $((25 * scale))"
      echo "  set Statistics interval      = $((5 * scale))"
      echo "end"
    fi
  } > run.prm

  start=$(date +%s.%N)
  mpirun -np "$np" "$build/bin/$app" run.prm | tee run.log
  seconds=$("$python" -c "print(f'{$(date +%s.%N) - $start:.1f}')")
  echo "Wall time of the run: $seconds s (mpirun -np $np)" | tee -a run.log
  "$python" "$here/postprocess.py" "$results" | tee postprocess.log
  angle=$(tail -1 postprocess.log | sed 's/.*: //')
  summary+=("$name: crack angle $angle deg, wall time $seconds s")
  echo
  echo "Results in $results: statistics.csv, particles.xdmf (open in ParaView; coupled runs also"
  echo "solution.xdmf, the FE field), damage_final.png, energies.png, crack_angle.png,"
  echo "crack_angle.csv, run.log, postprocess.log."
  echo
done

echo "Summary (experiment: about 70 deg):"
printf '  %s\n' "${summary[@]}"
if [ ${#prms[@]} -eq 3 ]; then
  "$python" - "$results_top" <<'PY'
import re, sys
def measure(name, what):
    log = open(f"{sys.argv[1]}/{name}/run.log").read()
    return float(re.search(what + r": ([\d.e+]+)", log).group(1))
for what, label in (("Wall time of the run", "wall time"), ("Peak memory", "peak memory")):
    p = measure("kalthoff_pd_pmb", what)
    for name in ("kalthoff_adaptive", "kalthoff_coupled"):
        print(f"  {label} {name} / all-PD: {measure(name, what) / p:.2f}")
PY
fi
