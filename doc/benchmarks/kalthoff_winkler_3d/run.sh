#!/usr/bin/env bash
# The 3D Kalthoff-Winkler plate end to end: build PeriDeal (installing the dependencies if
# missing, as root), run the adaptive coupled file and its all-PD reference on 2 MPI ranks,
# post-process each (crack angle per layer through the thickness, pictures) and print the
# angles at mid-thickness and on the faces, the wall times and the peak memories.
#
# Usage: run.sh [--dx SPACING] [--np N] [--prm FILE]
#   --dx SPACING  lattice spacing [m] instead of the files' 1e-3 (horizon = 3.015 dx; the output
#                 intervals scaled to keep ~30 snapshots), e.g. --dx 5e-4;
#   --np N        MPI ranks (default 2);
#   --prm FILE    run only this parameter file (e.g. kalthoff_3d_adaptive.prm).
# Memory: about 41 B per bond and 57 bonds per particle (README.md, "Memory"): all-PD needs
# 0.7 GiB at dx = 1 mm, 3.5 GiB at 0.5 mm; do not start it at 0.25 mm (27 GiB).
# Environment: PERIDEAL_BUILD_DIR, PERIDEAL_RESULTS_DIR (default
# <top>/results/kalthoff_winkler_3d_dx<SPACING>), PYTHON.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../../.." && pwd)

dx=1e-3 np=2 prms=("$here/kalthoff_3d_adaptive.prm" "$here/kalthoff_3d_pd.prm")
while [ $# -gt 0 ]; do
  case "$1" in
    --dx) dx=$2; shift 2 ;;
    --np) np=$2; shift 2 ;;
    --prm) prms=("$(cd "$(dirname "$2")" && pwd)/$(basename "$2")"); shift 2 ;;
    -h|--help) sed -n 2,16p "$0"; exit 0 ;;
    *) echo "run.sh: unknown argument <$1> (see run.sh --help)" >&2; exit 1 ;;
  esac
done
# Dependencies, Open MPI as root, the build: python, build.
source "$here/../run_preamble.sh"

results_top=${PERIDEAL_RESULTS_DIR:-$top/results/kalthoff_winkler_3d_dx$dx}
scale=$("$python" -c "print(max(1, round(1e-3 / float('$dx'))))")
summary=()
for prm in "${prms[@]}"; do
  name=$(basename "$prm" .prm)
  results=$results_top/$name
  mkdir -p "$results"
  cd "$results"
  {
    echo "include $prm"
    echo "subsection Discretization"
    echo "  set Lattice spacing = $dx"
    echo "end"
    echo "subsection Output"
    echo "  set Output interval     = $((25 * scale))"
    echo "  set Statistics interval = $((5 * scale))"
    echo "end"
  } > run.prm
  # The CPU time too (user + system of all ranks): on a shared machine it moves less than the
  # wall time.
  timer=()
  if [ -x /usr/bin/time ]; then
    timer=(/usr/bin/time -f "CPU time of the run: %U s user, %S s system" -o cpu.log)
  fi
  start=$(date +%s.%N)
  "${timer[@]}" mpirun -np "$np" "$build/bin/perideal-solid" run.prm | tee run.log
  seconds=$("$python" -c "print(f'{$(date +%s.%N) - $start:.1f}')")
  echo "Wall time of the run: $seconds s (mpirun -np $np)" | tee -a run.log
  [ -f cpu.log ] && tee -a run.log < cpu.log
  "$python" "$here/postprocess.py" "$results" | tee postprocess.log
  memory=$(grep -o "Peak memory: [0-9.]* MiB" run.log | sed 's/Peak memory: //')
  summary+=("$name: $(grep 'crack angle faces' postprocess.log), $(tail -1 postprocess.log),"
            "  wall time $seconds s, peak memory $memory")
done
echo "Summary (dx = $dx m; experiment: about 70 deg):"
printf '  %s\n' "${summary[@]}"
