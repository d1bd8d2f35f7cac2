#!/bin/bash
# The alumina quench (README.md): runs for T0 = 300, 450, 600 degrees C (water 20 degrees C),
# then cracks.py (count, spacing, lengths per run; the plots). Usage:
#   [METHODS="pd coupled adaptive"] [END_TIME=0.15] [SEED=k] run.sh [BUILD_DIR] [OUT_DIR] [T0 ...]
# BUILD_DIR defaults to ../../../build (the perideal-solid there), OUT_DIR to ./results (which
# git ignores), T0 to "300 450 600". METHODS (default "pd") names the inputs: pd = quench.prm
# (all-PD), coupled = quench_coupled.prm (PD frame along the edges, FE core), adaptive =
# quench_adaptive.prm (the PD region grows where the cracks run), strength =
# quench_strength.prm (coupled at alumina's strength, delta = 0.087 mm: a 14.4 mm segment of one
# quenched edge, PD band 3 mm deep, cracks.py with --dx 2.88e-5 --edges bottom; about an hour
# per run on one core, so these write a checkpoint after every load step: a stopped run goes on
# with 'cd DIR && perideal-solid --restart quench_T<T0>.prm'). Each run writes
# OUT_DIR/T<T0>/ (pd) or OUT_DIR/<method>/T<T0>/ (the others) with
# {quench_T<T0>.prm,run.log,time.log,results/}; a run whose results/statistics.csv and run.log
# summary exist already is not repeated (delete its folder to run it again). Runs one after the
# other on one core. SEED=k (environment) runs the lattice of <Perturbation seed> k instead of 1,
# in T<T0>_seed<k>. END_TIME=t (environment) runs to t seconds in load steps of 10 ms (5 ms for
# strength) instead of
# the file's End time (quench.prm 0.4 s; quench_coupled.prm and quench_adaptive.prm 0.15 s):
# END_TIME=0.15 gives the all-PD run of the side-by-side table. NICE=n runs the solver under
# nice -n n (the strength runs: NICE=10).
set -euo pipefail
HERE="$(cd "$(dirname "$0")" && pwd)"
BUILD="$(cd "${1:-$HERE/../../../build}" && pwd)"
OUT="${2:-$HERE/results}"
shift $(( $# > 2 ? 2 : $# )) || true
T0S="${*:-300 450 600}"
SEED="${SEED:-1}"
METHODS="${METHODS:-pd}"
END_TIME="${END_TIME:-}"
NICE="${NICE:-0}"
SUFFIX=""
[ "$SEED" = 1 ] || SUFFIX="_seed$SEED"
mkdir -p "$OUT"
for METHOD in $METHODS; do
  measure=""
  step=0.01
  checkpoint=off
  case "$METHOD" in
    pd) input="$HERE/quench.prm"; base="$OUT"; end="${END_TIME:-0.4}"; label=all-PD; prefix="" ;;
    coupled) input="$HERE/quench_coupled.prm"; base="$OUT/coupled"; end="${END_TIME:-0.15}"
      label=coupled; prefix=coupled_ ;;
    adaptive) input="$HERE/quench_adaptive.prm"; base="$OUT/adaptive"; end="${END_TIME:-0.15}"
      label=adaptive; prefix=adaptive_ ;;
    strength) input="$HERE/quench_strength.prm"; base="$OUT/strength"; end="${END_TIME:-0.15}"
      label="coupled, PD at sigma_f"; prefix=strength_
      measure="--dx 2.88e-5 --edges bottom"; step=0.005; checkpoint=1 ;;
    *) echo "run.sh: METHODS takes pd, coupled, adaptive, strength; not '$METHOD'" >&2; exit 1 ;;
  esac
  steps=$(/usr/bin/python3 -c "print(max(1, round($end / $step)))")
  dirs=""
  for T0 in $T0S; do
    dir="$base/T$T0$SUFFIX"
    dirs="$dirs $dir"
    mkdir -p "$dir"
    if [ -f "$dir/results/statistics.csv" ] && grep -q "^Peak memory" "$dir/run.log" 2>/dev/null; then
      echo "$METHOD, T0 = $T0: kept the run in $dir"
      continue
    fi
    cat > "$dir/quench_T$T0.prm" <<PRM
# The quench of $(basename "$input") from T0 = $T0 degrees C (stress-free at T0), to $end s in
# load steps of $(/usr/bin/python3 -c "print(1e3 * $step)") ms, written by run.sh.
include $input
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
subsection Solver
  set Load steps = $steps
end
subsection Time stepping
  set End time = $end
end
subsection Output
  set Checkpoint interval = $checkpoint
end
PRM
    echo "$METHOD, T0 = $T0: running in $dir"
    (cd "$dir" &&
      nice -n "$NICE" /usr/bin/time -v "$BUILD/bin/perideal-solid" "quench_T$T0.prm" > run.log 2> time.log) ||
      echo "$METHOD, T0 = $T0: the run stopped (time.log has the message); measured as far as it went"
  done
  /usr/bin/python3 "$HERE/cracks.py" --end-time "$end" --method "$label" --prefix "$prefix" \
    $measure --out "$base" $dirs
done
