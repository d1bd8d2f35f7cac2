#!/bin/bash
# Thermal stresses in a disk (README.md): all-PD and coupled (blended, overlapping Schwarz)
# against the closed form, at three lattice spacings (the FE mesh refined with them). Writes
# results/errors.csv and convergence.png beside this file; prints the errors per run.
# Usage: run.sh [perideal-solid] (default: the build of this checkout).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
solver=${1:-$root/build/bin/perideal-solid}
ranks=${RANKS:-2}
run() { mpirun --oversubscribe -np "$ranks" "$solver" "$@"; }
out=$here/results
mkdir -p "$out"
echo "case,dx,particle_max,particle_rms,fe_max,fe_rms,seconds" > "$out/errors.csv"
for level in 0 1 2; do
  dx=$(python3 -c "print(2.5e-3 / 2**$level)")
  centre=$(python3 -c "print(1.5 * $dx)")
  refinements=$((4 + level))
  for case in pd blended schwarz; do
    prm=disk_pd.prm
    [ "$case" != pd ] && prm=disk_coupled.prm
    work=$out/${case}_$level
    mkdir -p "$work"
    sed -e "s/set Lattice spacing = .*/set Lattice spacing = $dx/" \
        -e "s/set Radius = 3.75e-3/set Radius = $centre/" \
        -e "s/set Global refinements  = .*/set Global refinements  = $refinements/" \
        -e "s/set Method            = blended/set Method            = $( [ "$case" = schwarz ] && echo 'overlapping schwarz' || echo blended)/" \
        -e "s|set Directory  = results|set Directory  = .|" \
        "$here/$prm" > "$work/case.prm"
    start=$(date +%s.%N)
    if ! (cd "$work" && run case.prm > log.txt 2>&1); then
      # A run that fails is recorded, and the study goes on.
      echo "$case,$dx,failed,,,,"  >> "$out/errors.csv"
      echo "$case dx = $dx: FAILED ($(grep -m1 -o 'The coupled static solve failed[^.]*' "$work/log.txt"))"
      continue
    fi
    seconds=$(python3 -c "import time; print(round(time.time() - $start, 1))")
    line=$(/usr/bin/python3 "$here/errors.py" "$work")
    echo "$case,$dx,$line,$seconds" >> "$out/errors.csv"
    echo "$case dx = $dx: particle max, rms, FE max, rms = $line ($seconds s)"
  done
done
/usr/bin/python3 "$here/plot.py" "$out/errors.csv" "$here/convergence.png"
