#!/usr/bin/env bash
# Cracked plate, coupled FE-PD against full PD (linear statics, no bond breaks). Runs the full-PD
# reference and the coupled case of coupled.prm with three variants (a larger PD region, a wider
# overlap, a finer FE mesh), then both plates without the pre-crack (the far-field floor: what
# differs between an FE and a PD plate without any crack), prints the differences of each pair and
# draws cod_profile.png for coupled.prm. About a minute on 2 cores; results go to results/ next to
# this script.
# usage: bash doc/benchmarks/cracked_plate_static/run.sh [BUILD_DIR]   (default: build)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="$(cd "${1:-build}" && pwd)"
solver="$build/bin/perideal-solid"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$here"
rm -rf results
mkdir -p results

# variant SOURCE NAME SED-EXPRESSIONS...: SOURCE.prm with its output directory set to
# results/NAME and the given edits, written to results/NAME.prm.
variant() {
  local source=$1 name=$2
  shift 2
  sed -e "s|set Directory  = results/.*|set Directory  = results/$name|" "$@" "$source.prm" \
    > "results/$name.prm"
}
# blending X0 X1 Y0 Y1 W: beta = 1 on [X0 + W, X1 - W] x [Y0 + W, Y1 - W] (m), linear ramps of
# width W, 0 outside [X0, X1] x [Y0, Y1].
blending() {
  echo "s|set Blending function = .*|set Blending function = min(1, max(0, min(min((x - $1) / $5, ($2 - x) / $5), min((y - $3) / $5, ($4 - y) / $5))))|"
}
variant full_pd full_pd
variant coupled coupled
variant coupled large_region -e "$(blending 0.016 0.084 0.020 0.080 0.008)"
variant coupled wide_overlap -e "$(blending 0.020 0.080 0.024 0.076 0.016)"
variant coupled fine_fe -e "s|50, 50 : 0|100, 100 : 0|"
variant full_pd full_pd_no_crack -e "/set Cracks/d"
variant coupled coupled_no_crack -e "/set Cracks/d"

for name in full_pd coupled large_region wide_overlap fine_fe full_pd_no_crack coupled_no_crack; do
  echo "== $name"
  mpirun -np 2 "$solver" "results/$name.prm" | grep -E '^(Particles|Coupling|Broken bonds)'
done
for name in coupled large_region wide_overlap fine_fe; do
  echo "== $name against full PD"
  plot=()
  [ "$name" = coupled ] && plot=(--plot cod_profile.png)
  /usr/bin/python3 postprocess.py "results/$name" results/full_pd "${plot[@]}"
done
echo "== without the pre-crack: coupled against full PD"
/usr/bin/python3 postprocess.py results/coupled_no_crack results/full_pd_no_crack --no-crack
