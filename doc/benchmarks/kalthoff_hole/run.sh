#!/usr/bin/env bash
# The second case of the adaptive PD region: the Kalthoff-Winkler plate with a hole off the
# upper crack's path (README.md beside this file). Builds PeriDeal if needed, runs the adaptive
# coupled variant (kalthoff_hole_adaptive.prm) and its all-PD reference (kalthoff_hole_pd.prm)
# on 2 MPI ranks, post-processes each as the Kalthoff-Winkler benchmark does (crack angles,
# damage map, energies, whole-specimen plot) and compares the two crack paths (compare.py: the
# largest distance between them in horizons) and the costs.
#
# Usage: run.sh [--dx SPACING] [--np N]
#   --dx SPACING  lattice spacing [m] (default 2.5e-4; horizon = 3.015 dx; the output intervals
#                 are scaled to keep ~25 snapshots), e.g. --dx 5e-4 (a minute in all);
#   --np N        MPI ranks (default 2).
# Environment: PERIDEAL_BUILD_DIR (default <top>/build), PERIDEAL_RESULTS_DIR (default
# <top>/results/kalthoff_hole_dx<SPACING>), PYTHON (default /usr/bin/python3).
# Dependencies: as doc/benchmarks/kalthoff_winkler/run.sh (which installs them if missing).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../../.." && pwd)
dx=2.5e-4 np=2
while [ $# -gt 0 ]; do
  case "$1" in
    --dx) dx=$2; shift 2 ;;
    --np) np=$2; shift 2 ;;
    -h|--help) sed -n 2,14p "$0"; exit 0 ;;
    *) echo "run.sh: unknown argument <$1> (see run.sh --help)" >&2; exit 1 ;;
  esac
done
python=${PYTHON:-/usr/bin/python3}
if [ "$(id -u)" -eq 0 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
"$top/contrib/build.sh"
build=${PERIDEAL_BUILD_DIR:-$top/build}
results_top=${PERIDEAL_RESULTS_DIR:-$top/results/kalthoff_hole_dx$dx}
scale=$("$python" -c "print(max(1, round(1e-3 / float('$dx'))))")

for name in kalthoff_hole_adaptive kalthoff_hole_pd; do
  results=$results_top/$name
  mkdir -p "$results"
  # The case's file (its paths relative to itself) with the
  # resolution and the output directory of this run.
  cat > "$results/run.prm" <<PRM
include $here/$name.prm
subsection Discretization
  set Lattice spacing = $dx
end
subsection Output
  set Directory           = $results
  set Output interval     = $((25 * scale))
  set Statistics interval = $((5 * scale))
end
PRM
  start=$(date +%s.%N)
  (cd "$top" && mpirun -np "$np" "$build/bin/perideal-solid" "$results/run.prm") | tee "$results/run.log"
  seconds=$("$python" -c "print(f'{$(date +%s.%N) - $start:.1f}')")
  echo "Wall time of the run: $seconds s (mpirun -np $np)" | tee -a "$results/run.log"
  "$python" "$top/doc/benchmarks/kalthoff_winkler/postprocess.py" "$results" | tee "$results/postprocess.log"
done

"$python" "$here/compare.py" "$results_top/kalthoff_hole_adaptive" "$results_top/kalthoff_hole_pd" \
  "$results_top" | tee "$results_top/compare.log"
echo
echo "Results in $results_top: paths.png, paths.csv, compare.log; each run's directory has the"
echo "Kalthoff-Winkler post-processing (damage_final.png, crack_angle.png, specimen.png for the"
echo "adaptive run, particles.xdmf and solution.xdmf for ParaView)."
