#!/usr/bin/env bash
# Static patch tests of the blended coupling: the displacement error against the exact affine
# field and the reaction against the applied traction, for uniaxial tension (20 MPa) and shear
# (15 MPa), as the overlap width W, the particle spacing dx and the FE cell size h change.
# Prints a Markdown table.
# usage: bash doc/benchmarks/coupling_patch/static_study.sh [path/to/perideal-solid]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
solver="${1:-$here/../../../build/bin/perideal-solid}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
tension_bcs='    set Names = left, bottom, right
    subsection left
      set Boundary ids = 0
      set Components   = x
      set Function     = 0
    end
    subsection bottom
      set Boundary ids = 2
      set Components   = y
      set Function     = 0
    end
    subsection right
      set Boundary ids = 1
      set Type         = traction
      set Function     = 20e6; 0
    end'
shear_bcs='    set Names = bottom, left, right, top
    subsection bottom
      set Boundary ids = 2
      set Function     = 0; 1e-4*x
    end
    subsection left
      set Boundary ids = 0
      set Type         = traction
      set Function     = 0; -15e6
    end
    subsection right
      set Boundary ids = 1
      set Type         = traction
      set Function     = 0; 15e6
    end
    subsection top
      set Boundary ids = 3
      set Type         = traction
      set Function     = 15e6; 0
    end'
echo "| state | W [mm] | dx [mm] | h [mm] | error FE nodes | error particles | reaction [N] (exact) | strain energy / exact |"
echo "|---|---|---|---|---|---|---|---|"
run() { # name W dx ncells
  local bcs exact reaction energy
  if [ "$1" = tension ]; then
    bcs="$tension_bcs"; exact="1e-4*x; -1e-4*y/3"; reaction="left"; energy=1e-2
  else
    bcs="$shear_bcs"; exact="1e-4*y; 1e-4*x"; reaction="bottom"; energy=1.5e-2
  fi
  /usr/bin/python3 "$here/../../../contrib/prm_fill.py" "$here/static.prm" "$work/p.prm" \
    "BOUNDARY_CONDITIONS=$bcs" "EXACT=$exact" "DX=$3" \
    "GENERATOR_ARGUMENTS=$4, $4 : 0, 0 : 0.1, 0.1 : true" \
    "BLENDING=min(1, max(0, min(min((x - 0.03) / $2, (0.07 - x) / $2), min((y - 0.03) / $2, (0.07 - y) / $2))))"
  out=$(cd "$work" && "$solver" p.prm)
  errors=$(echo "$out" | sed -n 's/.*FE nodes \([^,]*\), particles \(.*\)/\1 | \2/p')
  r=$(echo "$out" | sed -n "s/^Reaction $reaction: \([^ ]*\) \([^ ]*\) N/\1/p")
  se=$(echo "$out" | sed -n 's/^Strain energy: \([^ ]*\) J.*/\1/p')
  echo "| $1 | $(/usr/bin/python3 -c "print(f'{$2*1e3:g}')") | $(/usr/bin/python3 -c "print(f'{$3*1e3:g}')") | $(/usr/bin/python3 -c "print(f'{100/$4:g}')") | $errors | $r ($([ "$1" = tension ] && echo -2000 || echo -1500)) | $(/usr/bin/python3 -c "print(f'{$se/$energy:.6f}')") |"
}
for state in tension shear; do
  for W in 0.005 0.01 0.02; do run $state $W 1e-3 25; done
  run $state 0.01 5e-4 25
  run $state 0.01 1e-3 50
  run $state 0.01 5e-4 50
done
