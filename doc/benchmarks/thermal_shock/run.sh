#!/bin/bash
# The alumina quench (README.md): all-PD runs for T0 = 300, 450, 600 degrees C (water 20 degrees C),
# then cracks.py (count, spacing, lengths per run; the plots). Usage:
#   run.sh [BUILD_DIR] [OUT_DIR] [T0 ...]
# BUILD_DIR defaults to ../../../build (the perideal-solid there), OUT_DIR to ./results (which
# git ignores), T0 to "300 450 600". Each run writes
# OUT_DIR/T<T0>/{quench_T<T0>.prm,run.log,time.log,results/}; a run whose results/statistics.csv
# and run.log summary exist already is not repeated (delete its folder to run it again). Runs
# one after the other on one core. SEED=k (environment) runs the lattice of <Perturbation seed>
# k instead of 1, in OUT_DIR/T<T0>_seed<k> (the scatter of the counts over lattices).
set -euo pipefail
HERE="$(cd "$(dirname "$0")" && pwd)"
BUILD="$(cd "${1:-$HERE/../../../build}" && pwd)"
OUT="${2:-$HERE/results}"
shift $(( $# > 2 ? 2 : $# )) || true
T0S="${*:-300 450 600}"
SEED="${SEED:-1}"
SUFFIX=""
[ "$SEED" = 1 ] || SUFFIX="_seed$SEED"
mkdir -p "$OUT"
for T0 in $T0S; do
  dir="$OUT/T$T0$SUFFIX"
  mkdir -p "$dir"
  if [ -f "$dir/results/statistics.csv" ] && grep -q "^Peak memory" "$dir/run.log" 2>/dev/null; then
    echo "T0 = $T0: kept the run in $dir"
    continue
  fi
  cat > "$dir/quench_T$T0.prm" <<PRM
# The quench of quench.prm from T0 = $T0 degrees C (stress-free at T0), written by run.sh.
include $HERE/quench.prm
subsection Discretization
  set Perturbation seed = $SEED
end
subsection Temperature
  set Reference temperature = $T0
end
subsection Heat
  subsection Initial conditions
    set Displacement = $T0
  end
end
PRM
  echo "T0 = $T0: running in $dir"
  (cd "$dir" &&
    /usr/bin/time -v "$BUILD/bin/perideal-solid" "quench_T$T0.prm" > run.log 2> time.log)
done
/usr/bin/python3 "$HERE/cracks.py" --out "$OUT" $(for T0 in $T0S; do echo "$OUT/T$T0$SUFFIX"; done)
