#!/usr/bin/env bash
# The polycrystal benchmark: the grains (make_grains.py), then, for the grain-boundary fracture
# energy ratios 0.3, 0.5, 0.75, 1, 1.5, 2, the notched plate all-particle (polycrystal.prm) and
# coupled (coupled.prm: particles in the crack band, homogenized FE elsewhere; the mesh from
# make_mesh.py), one rank each; postprocess.py prints the table of README.md and draws
# polycrystal_intergranular.png and polycrystal_cracks.png. About 2 min on one core.
# usage: bash doc/benchmarks/polycrystal/run.sh [BUILD_DIR]   (default: build)
#        PC_RATIOS="0.5 1" to run other ratios.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="$(cd "${1:-build}" && pwd)"
python=${PYTHON:-/usr/bin/python3}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$here"
"$python" make_grains.py 0.004 -0.002,-0.032 0.062,0.032 grains.txt
"$python" make_mesh.py
ratios=${PC_RATIOS:-0.3 0.5 0.75 1 1.5 2}
for ratio in $ratios; do
  mkdir -p results
  sed "s/\(Grain boundary fracture energy ratio *= *\).*/\1$ratio/" specimen.prm \
    > "results/specimen_$ratio.prm"
  for run in polycrystal coupled; do
    directory=results/ratio_$ratio
    [ "$run" = coupled ] && directory=results/coupled_ratio_$ratio
    mkdir -p "$directory"
    sed -e "s|ratio_1$|ratio_$ratio|" -e "s|include specimen.prm|include results/specimen_$ratio.prm|" \
      "$run.prm" > "$directory/run.prm"
    start=$(date +%s.%N)
    "$build/bin/perideal-solid" "$directory/run.prm" > "$directory/run.log"
    echo "$(date +%s.%N) - $start" | bc > "$directory/wall_time"
    echo "$directory: done ($(cat "$directory/wall_time") s)"
  done
done
"$python" postprocess.py $ratios
