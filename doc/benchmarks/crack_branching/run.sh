#!/usr/bin/env bash
# End to end: install dependencies if missing (as root), build PeriDeal, run the crack-branching
# benchmark (a pre-notched soda-lime glass plate pulled by tractions on its long edges) on 2 MPI
# ranks, post-process (damage picture, crack-tip speed against time with the Rayleigh speed,
# branch point) and say where the results are. By default the flagship pair at dx = 0.25 mm,
# 2 MPa: the adaptive coupled run (branching_adaptive.prm: FE with PD that starts around the
# notch tip and follows the crack and its branches) and its all-PD reference (branching.prm),
# then the branch points and the ratios of the wall times and of the peak memories.
#
# Usage: run.sh [--dx SPACING] [--load SIGMA] [--np N] [--prm FILE] [--study] [--app NAME]
#   --dx SPACING  lattice spacing [m] instead of the files' 2.5e-4 (horizon = 4 dx; the output
#                 interval is scaled to keep an output about every 0.9 us);
#   --load SIGMA  the traction [Pa] on the long edges instead of the files' 2e6 (the published
#                 load levels: 2e6, 4e6, 12e6);
#   --np N        MPI ranks (default 2);
#   --prm FILE    run only this parameter file of the case (e.g. branching.prm, or
#                 branching_adaptive_fe_traction.prm, which stops at about 37 us);
#   --study       the all-PD studies instead of the flagship: 2 MPa at dx = 1, 0.5, 0.25 and
#                 0.125 mm (delta = 4, 2, 1, 0.5 mm; the last 2.5 min on 2 cores), 4 and
#                 12 MPa at dx = 0.25 mm, and the comparison plots convergence.png, loads.png;
#   --app NAME    the application in the build's bin/ (default perideal-solid).
# Environment: PERIDEAL_BUILD_DIR (default <top>/build), PERIDEAL_RESULTS_DIR (default
# <top>/results/crack_branching; each run in a subdirectory named after its parameter file, the
# spacing and the load), PYTHON (default /usr/bin/python3).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../../.." && pwd)

dx=2.5e-4 load="" np=2 app=perideal-solid study=0
prms=("$here/branching_adaptive.prm" "$here/branching.prm")
while [ $# -gt 0 ]; do
  case "$1" in
    --dx) dx=$2; shift 2 ;;
    --load) load=$2; shift 2 ;;
    --np) np=$2; shift 2 ;;
    --prm) prms=("$(cd "$(dirname "$2")" && pwd)/$(basename "$2")"); shift 2 ;;
    --study) study=1; shift ;;
    --app) app=$2; shift 2 ;;
    -h|--help) sed -n 2,24p "$0"; exit 0 ;;
    *) echo "run.sh: unknown argument <$1> (see run.sh --help)" >&2; exit 1 ;;
  esac
done
# Dependencies, Open MPI as root, the build: python, build.
source "$here/../run_preamble.sh"
results_top=${PERIDEAL_RESULTS_DIR:-$top/results/crack_branching}

# run_case PRM SPACING LOAD: run one file in <results_top>/<name>_dx<SPACING>[_<LOAD>], print
# the post-processing, leave the directory's name in $results.
run_case() {
  local prm=$1 spacing=$2 sigma=$3 name
  name=$(basename "$prm" .prm)_dx$spacing${sigma:+_$sigma}
  results=$results_top/$name
  mkdir -p "$results"
  (
    cd "$results"
    interval=$("$python" -c "print(max(1, round(20 * 2.5e-4 / float('$spacing'))))")
    {
      echo "include $prm"
      echo "subsection Discretization"
      echo "  set Lattice spacing = $spacing"
      echo "end"
      echo "subsection Output"
      echo "  set Output interval = $interval"
      echo "end"
      if [ -n "$sigma" ]; then
        echo "subsection Boundary conditions"
        echo "  subsection pull top"
        echo "    set Function = 0; $sigma"
        echo "  end"
        echo "  subsection pull bottom"
        echo "    set Function = 0; -$sigma"
        echo "  end"
        echo "end"
      fi
    } > run.prm
    start=$(date +%s.%N)
    mpirun -np "$np" "$build/bin/$app" run.prm | tee run.log
    seconds=$("$python" -c "print(f'{$(date +%s.%N) - $start:.1f}')")
    echo "Wall time of the run: $seconds s (mpirun -np $np)" | tee -a run.log
    "$python" "$here/tip_speed.py" . --labels "$name" | tee postprocess.log
  )
  echo
  echo "Results in $results: particles.xdmf (open in ParaView; coupled runs also solution.xdmf,"
  echo "the FE field), damage.png, tip_speed.png, tip_speed.csv, statistics.csv, run.log,"
  echo "postprocess.log."
  echo
}

if [ "$study" -eq 1 ]; then
  dirs=() labels=()
  for spacing in 1e-3 5e-4 2.5e-4 1.25e-4; do
    run_case "$here/branching.prm" "$spacing" ""
    delta=$("$python" -c "print(f'{4 * float(\"$spacing\") * 1e3:g}')")
    dirs+=("$results") labels+=("delta = $delta mm")
  done
  "$python" "$here/tip_speed.py" "${dirs[@]}" --labels "$(IFS=,; echo "${labels[*]}")" \
    --compare "$results_top/convergence.png" | tee "$results_top/convergence.log"
  dirs=("$results_top/branching_dx2.5e-4") labels=("2 MPa")
  for sigma in 4e6 12e6; do
    run_case "$here/branching.prm" 2.5e-4 "$sigma"
    dirs+=("$results") labels+=("$("$python" -c "print(f'{float(\"$sigma\") / 1e6:g}')") MPa")
  done
  "$python" "$here/tip_speed.py" "${dirs[@]}" --labels "$(IFS=,; echo "${labels[*]}")" \
    --compare "$results_top/loads.png" | tee "$results_top/loads.log"
  echo "Comparison plots: $results_top/convergence.png, $results_top/loads.png"
  exit 0
fi

for prm in "${prms[@]}"; do
  run_case "$prm" "$dx" "$load"
done

echo "Summary:"
for prm in "${prms[@]}"; do
  name=$(basename "$prm" .prm)_dx$dx${load:+_$load}
  echo "  $name: $(tail -1 "$results_top/$name/postprocess.log")"
done
if [ ${#prms[@]} -eq 2 ]; then
  "$python" - "$results_top" "_dx$dx${load:+_$load}" <<'PY'
import re, sys
def measure(name, what):
    log = open(f"{sys.argv[1]}/{name}{sys.argv[2]}/run.log").read()
    return float(re.search(what + r": ([\d.e+]+)", log).group(1))
for what, label in (("Wall time of the run", "wall time"), ("Peak memory", "peak memory")):
    print(f"  {label} adaptive / all-PD: "
          f"{measure('branching_adaptive', what) / measure('branching', what):.2f}")
PY
fi
