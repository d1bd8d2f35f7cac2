#!/usr/bin/env bash
# Ghost-force study of the blended coupling: the force residual of patch-test states (rigid
# translation and rotation, uniform tension and shear) as the overlap width W, the particle
# spacing dx and the FE cell size h change. Prints a Markdown table.
# usage: bash doc/benchmarks/coupling_patch/study.sh [path/to/perideal-solid]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
solver="${1:-$here/../../../build/bin/perideal-solid}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
echo "| state | W [mm] | dx [mm] | h [mm] | max residual [N] | relative to the FE force scale |"
echo "|---|---|---|---|---|---|"
run() { # name ux uy W dx ncells
  /usr/bin/python3 "$here/../../../contrib/prm_fill.py" "$here/patch.prm" "$work/p.prm" \
    "DISPLACEMENT=$2; $3" "DX=$5" "GENERATOR_ARGUMENTS=$6, $6 : 0, 0 : 0.1, 0.1 : true" \
    "BLENDING=min(1, max(0, min(min((x - 0.03) / $4, (0.07 - x) / $4), min((y - 0.03) / $4, (0.07 - y) / $4))))"
  line=$(cd "$work" && "$solver" p.prm | grep "Force residual")
  abs=$(echo "$line" | sed 's/.*t = 0: \([^ ]*\) N.*/\1/')
  rel=$(echo "$line" | sed 's/.*scale: //')
  h=$(python3 -c "print(f'{100/$6:g}')")
  echo "| $1 | $(python3 -c "print(f'{$4*1e3:g}')") | $(python3 -c "print(f'{$5*1e3:g}')") | $h | $abs | $rel |"
}
run translation "1e-6 + 0*x" "2e-6 + 0*y" 0.01 1e-3 25
for theta in 1e-6 1e-4 1e-3; do
  run "rotation $theta rad" "-$theta*(y-0.05)" "$theta*(x-0.05)" 0.01 1e-3 25
done
# The PD stretch of a rotation, sqrt(1 + theta^2) - 1 = theta^2 / 2, as a uniform dilatation
# (FE and PD both strained: only the blending's ghost force remains).
run "dilatation 5e-7" "5e-7*(x-0.05)" "5e-7*(y-0.05)" 0.01 1e-3 25
for state in "tension:1e-4*x:0" "shear:1e-4*y:1e-4*x"; do
  IFS=: read -r name ux uy <<< "$state"
  for W in 0.005 0.01 0.02; do run "$name" "$ux" "$uy" $W 1e-3 25; done
  run "$name" "$ux" "$uy" 0.01 5e-4 25
  run "$name" "$ux" "$uy" 0.01 1e-3 50
  run "$name" "$ux" "$uy" 0.01 5e-4 50
done
