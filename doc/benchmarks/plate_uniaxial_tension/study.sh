#!/usr/bin/env bash
# The variants of the README table. Each is plate_uniaxial_tension.prm (100 x 100, grips 2 delta
# thick that carry the elastic field in y, geometric partial volume, surface correction on) with
# a few entries changed by sed, and runs in its own folder under the results directory:
#   - surface correction off; 200 x 200 particles (dx = 0.25 mm, delta = 1 mm);
#   - partial volume 'book' and 'none', each with and without surface correction;
#   - delta = 3.015 dx (the code's default horizon factor) instead of 4 dx;
#   - the applied displacement divided by 100 (geometric nonlinearity of the stretch);
#   - rigid grips (u_y = +-U, the previous main case) delta thick, 100 x 100 and 200 x 200;
#   - elastic grips only delta thick.
# About 3 min on 2 cores in all. Writes mid_lines.png of the main case into the results directory.
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

no_correction='s/Surface correction        = true/Surface correction        = false/'
book='s/Partial volume correction = geometric/Partial volume correction = book/'
none='s/Partial volume correction = geometric/Partial volume correction = none/'
fine='s/Lattice spacing           = 5e-4/Lattice spacing           = 2.5e-4/'
horizon_3015='s/Horizon factor            = 4/Horizon factor            = 3.015/'
small='s/2\*5.6141e-4\/0.05\*/2*5.6141e-6\/0.05*/'
# Grip thickness: 2 delta at 100 x 100 is 4 mm (the main case); 2 mm is delta at 100 x 100 and
# 2 delta at 200 x 200; 1 mm is delta at 200 x 200.
grips_2mm='s/0.05, 0.054/0.05, 0.052/; s/0, -0.004/0, -0.002/'
grips_1mm='s/0.05, 0.054/0.05, 0.051/; s/0, -0.004/0, -0.001/'
rigid='/subsection pull top/,/^  end/ s/Function   = .*/Function   = 5.6141e-4*min(t\/2e-5, 1)/;
       /subsection pull bottom/,/^  end/ s/Function   = .*/Function   = -5.6141e-4*min(t\/2e-5, 1)/'

run() { # name sed-script
  mkdir -p "$results/$1"
  sed "$2" "$here/plate_uniaxial_tension.prm" > "$results/$1/plate.prm"
  if [ -n "$2" ] && cmp -s "$here/plate_uniaxial_tension.prm" "$results/$1/plate.prm"; then
    echo "study.sh: the variant $1 changed nothing" >&2
    exit 1
  fi
  (cd "$results/$1" && mpirun -np "$np" "$build/bin/perideal-solid" plate.prm > log.txt)
}

run main ''
run no_correction "$no_correction"
run n200 "$fine; $grips_2mm"
run n200_no_correction "$fine; $grips_2mm; $no_correction"
run book "$book"
run book_no_correction "$book; $no_correction"
run none "$none"
run none_no_correction "$none; $no_correction"
run horizon_3015 "$horizon_3015"
run small_strain "$small"
run rigid "$rigid; $grips_2mm"
run rigid_no_correction "$rigid; $grips_2mm; $no_correction"
run n200_rigid "$rigid; $fine; $grips_1mm"
run elastic_delta "$grips_2mm"
run elastic_delta_no_correction "$grips_2mm; $no_correction"

cd "$results"
"$python" "$here/postprocess.py" --markdown main no_correction n200 n200_no_correction \
  book book_no_correction none none_no_correction horizon_3015 rigid rigid_no_correction \
  n200_rigid elastic_delta elastic_delta_no_correction \
  --labels "main case,correction off,200 × 200,200 × 200 correction off,book,\
book correction off,none,none correction off,δ = 3.015 dx,rigid grips δ thick,\
rigid grips δ thick correction off,rigid grips δ thick 200 × 200,elastic layers δ thick,\
elastic layers δ thick correction off" \
  > table.txt
"$python" "$here/postprocess.py" --grip-displacement 5.6141e-6 --plot-dir small_strain \
  small_strain --labels "grip displacement / 100" > small_strain.txt
"$python" "$here/postprocess.py" --plot-dir . main --labels "main case" > main.txt
cat table.txt small_strain.txt
