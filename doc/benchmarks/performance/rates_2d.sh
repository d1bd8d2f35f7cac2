#!/usr/bin/env bash
# The antiplane models' kernel rates beside PMB's on one 2D lattice (lattice_2d.prm), in one run:
# REPEATS rounds of PMB, 'antiplane bond based' and 'antiplane state based' back to back, each on
# one rank pinned to core 0, then the median of each model and its ratio to PMB's.
# usage: rates_2d.sh BUILD_DIR [REPEATS]   (default 3)
set -eu
build=$(realpath "$1"); repeats=${2:-3}
here=$(dirname "$(realpath "$0")")
work=$(mktemp -d); cd "$work"
models=("bond based" "antiplane bond based" "antiplane state based")
rate() {
  # The antiplane models have one component: the ramp of w alone.
  local velocity=()
  [ "$1" = "bond based" ] || velocity=(-e "s|set Velocity = \(.*\); 0|set Velocity = \1|")
  sed -e "s|set Model        = .*|set Model        = $1|" "${velocity[@]}" "$here/lattice_2d.prm" > case.prm
  taskset -c 0 "$build/bin/perideal-solid" case.prm 2>&1 | sed -n 's/^bond updates per second: //p'
}
declare -A rates
for r in $(seq "$repeats"); do
  for model in "${models[@]}"; do
    value=$(rate "$model")
    [ -n "$value" ] || { echo "rates_2d.sh: no rate printed for '$model'" >&2; exit 1; }
    rates[$model]="${rates[$model]:-} $value"
    echo "round $r: $model: $value bond updates/s"
  done
done
median() { tr ' ' '\n' | grep . | sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
pmb=$(echo "${rates[bond based]}" | median)
for model in "${models[@]}"; do
  m=$(echo "${rates[$model]}" | median)
  printf '%-22s median %.3g bond updates/s, %.2f x PMB\n' "$model:" "$m" "$(awk -v a="$m" -v b="$pmb" 'BEGIN {print a / b}')"
done
rm -rf "$work"
