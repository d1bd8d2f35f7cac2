#!/usr/bin/env bash
# The variants of the README table: surface correction on/off, 100 x 100 and 200 x 200
# particles, and the grip diagnostics (grips that carry the elastic field, grips 2 delta
# thick). Each variant is plate_uniaxial_tension.prm with a few entries changed by sed; each
# runs in its own folder under the results directory. About 2 min on 2 cores in all.
# Usage: study.sh [RESULTS_DIR]   (PERIDEAL_BUILD_DIR: build tree, default <repo>/build;
#                                  PYTHON: a python3 with numpy, h5py, matplotlib; NP: ranks)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../../.." && pwd)
build=${PERIDEAL_BUILD_DIR:-$top/build}
results=${1:-${PERIDEAL_RESULTS_DIR:-$top/results/plate_uniaxial_tension}/study}
python=${PYTHON:-/usr/bin/python3}
np=${NP:-2}
mkdir -p "$results"

no_correction='s/set Surface correction = true/set Surface correction = false/'
fine='s/set Lattice spacing    = 5e-4/set Lattice spacing    = 2.5e-4/; s/0.05, 0.052/0.05, 0.051/; s/0, -0.002/0, -0.001/'
elastic_grips='s/= 5.6141e-4\*min(t\/2e-5, 1)/= 0.0224564*(y-0.025)*min(t\/2e-5, 1)/; s/= -5.6141e-4\*min(t\/2e-5, 1)/= 0.0224564*(y-0.025)*min(t\/2e-5, 1)/'
thick_grips='s/0.05, 0.052/0.05, 0.054/; s/0, -0.002/0, -0.004/'

run() { # name sed-script
  mkdir -p "$results/$1"
  sed "$2" "$here/plate_uniaxial_tension.prm" > "$results/$1/plate.prm"
  (cd "$results/$1" && mpirun -np "$np" "$build/bin/perideal-solid" plate.prm > log.txt)
}

run n100_correction ''
run n100_no_correction "$no_correction"
run n200_correction "$fine"
run n200_no_correction "$fine; $no_correction"
run n100_elastic_grips "$elastic_grips"
run n100_elastic_grips_no_correction "$elastic_grips; $no_correction"
run n100_elastic_grips_2delta "$elastic_grips; $thick_grips"

cd "$results"
"$python" "$here/postprocess.py" n100_correction n100_no_correction n200_correction n200_no_correction \
  --labels "100x100 correction on,100x100 correction off,200x200 correction on,200x200 correction off"
"$python" "$here/postprocess.py" n100_elastic_grips n100_elastic_grips_no_correction n100_elastic_grips_2delta \
  --labels "elastic grips correction on,elastic grips correction off,elastic grips 2 delta correction on" \
  --plot-dir n100_elastic_grips
