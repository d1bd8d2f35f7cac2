#!/usr/bin/env bash
# Nooru-Mohamed double-edge-notched concrete under shear then tension (load path 4b) with
# Timoshenko-beam bonds (seed 003, sec. 3.2): builds PeriDeal if needed, runs the all-PD case
# (full_pd.prm) and the coupled case with the adaptive PD region (coupled_adaptive.prm) side by
# side, one rank each pinned to its own core (their wall times compare), then the coupled case
# with the fixed band (coupled.prm: PD in the band of the cracks, FE elsewhere), and
# post-processes them (postprocess.py: checks, the force-displacement curves and the crack
# paths, nooru_mohamed_force_displacement.png, nooru_mohamed_cracks.png and
# nooru_mohamed_adaptive_region.png beside this script).
# Each run takes one to three minutes on one core of the development machine.
#
# Usage: run.sh   (from anywhere; results in <top>/results/nooru_mohamed)
# Environment: PERIDEAL_BUILD_DIR (default <top>/build), PYTHON (default /usr/bin/python3).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../../.." && pwd)
python=${PYTHON:-/usr/bin/python3}
if [ "$(id -u)" -eq 0 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
"$top/contrib/build.sh"
build=${PERIDEAL_BUILD_DIR:-$top/build}
results=$top/results/nooru_mohamed
rm -rf "$results"
mkdir -p "$results"
cd "$top"
[ -f meshes/nooru_mohamed_2d.msh ] || "$python" "$here/make_mesh.py"

# All-PD and the adaptive coupled run side by side, then the fixed band's coupled run.
run() {
  taskset -c "$2" /usr/bin/time -f "$1: wall %e s, peak memory %M kB" -o "$results/$1.time" \
    "$build/bin/perideal-solid" "doc/benchmarks/nooru_mohamed/$1.prm" > "$results/$1.log"
}
second=$(( 1 % $(nproc) ))
run full_pd 0 &
run coupled_adaptive $second &
wait
run coupled 0
cat "$results/full_pd.time" "$results/coupled_adaptive.time" "$results/coupled.time"
"$python" - "$results" <<'PY'
import sys
t = {}
for name in ("full_pd", "coupled_adaptive", "coupled"):
    t[name] = float(open(f"{sys.argv[1]}/{name}.time").read().split()[2])
print(f"wall time coupled_adaptive / all-PD (side by side): {t['coupled_adaptive'] / t['full_pd']:.2f}")
print(f"wall time coupled / all-PD (one after the other): {t['coupled'] / t['full_pd']:.2f}")
PY
"$python" "$here/postprocess.py" "$results" --plot "$results/nooru_mohamed"
cp "$results"/nooru_mohamed_*.png "$here/"
