#!/usr/bin/env bash
# Anisotropic plate with a hole (issue #15, sec. 4; seed 004): the PD generalized plane-stress
# model against plane-stress FE with the same C for an isotropic, a cubic (NaCl) and an
# orthotropic material, the last two also with their axes at 30 degrees. cases.py writes the
# meshes and the parameter files (from plate_hole_pd.prm and plate_hole_fe.prm), every run goes
# on 2 MPI ranks, postprocess.py prints the tables of README.md and draws the plots. About
# 7 minutes on 2 cores (shared); results go to results/ next to this script, the plots next
# to this script.
# usage: bash doc/benchmarks/anisotropic_plate_hole/run.sh [--fine] [BUILD_DIR]   (default: build)
#   --fine: also the main case at dx = 0.25 mm (160 000 particles, about 2.5 more minutes)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
fine=()
if [ "${1:-}" = --fine ]; then
  fine=(--fine)
  shift
fi
build="$(cd "${1:-build}" && pwd)"
solver="$build/bin/perideal-solid"
python=${PYTHON:-/usr/bin/python3}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$here"
rm -rf results
mkdir -p results
"$python" cases.py results "${fine[@]}" > results/runs.txt
: > results/timings.txt
while read -r prm; do
  name=${prm#"$here/results/"}
  name=${name%.prm}
  echo "== $name"
  start=$(date +%s%N)
  # (stdin from /dev/null: mpirun would read the rest of the list)
  if ! mpirun -np 2 "$solver" "$prm" < /dev/null > "results/$name.log" 2>&1; then
    cat "results/$name.log"
    exit 1
  fi
  end=$(date +%s%N)
  grep -E '^(Particles|FE region|Reaction right)' "results/$name.log" | cut -c1-120
  ms=$(( (end - start) / 1000000 ))
  printf '%s %d.%01d\n' "$name" $((ms / 1000)) $((ms % 1000 / 100)) >> results/timings.txt
done < results/runs.txt
"$python" postprocess.py results | tee results/tables.md
