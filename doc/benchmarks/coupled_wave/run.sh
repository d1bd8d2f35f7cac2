#!/usr/bin/env bash
# Run both strips and print the reflection of the overlap (a few seconds on 2 cores).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
solver="${1:-$here/../../../build/bin/perideal-solid}"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$here"
for case in coupled fe_reference; do
  mpirun -np 2 "$solver" "$case.prm" | grep -E "Energy error|Coupling"
done
/usr/bin/python3 reflection.py results_coupled results_fe_reference
