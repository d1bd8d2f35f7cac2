#!/usr/bin/env bash
# Side-by-side kernel benchmark: PeriDeal and LAMMPS on the same 41^3 PMB and LPS problems, run
# back to back (same minute), then PeriDeal PMB on two MPI ranks. Prints one line per run. The
# one-rank runs are pinned to core 0 (taskset), so that both codes run on the same core.
# usage: compare_lammps.sh BUILD_DIR BENCH_DIR [REPEATS]
#   BUILD_DIR: PeriDeal build (bin/perideal-solid); BENCH_DIR: directory with lammps_rate.sh and
#   lammps_{pmb,lps}_41.in (doc/benchmarks/performance/lammps).
set -eu
# Open MPI refuses to run as root unless told (containers, CI): the two-rank line needs it.
if [ "$(id -u)" = 0 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
build=$(realpath "$1"); bench=$(realpath "$2"); repeats=${3:-3}
here=$(dirname "$(realpath "$0")")
work=$(mktemp -d); cd "$work"
rate() { "$@" 2>&1 | sed -n 's/^bond updates per second: //p'; }
for r in $(seq "$repeats"); do
  for model in pmb lps; do
    echo "run $r $model perideal-1rank $(rate taskset -c 0 "$build/bin/perideal-solid" "$here/${model}_lattice_3d.prm")"
    echo "run $r $model lammps-1rank $(cd "$bench" && taskset -c 0 ./lammps_rate.sh "lammps_${model}_41.in" | sed 's/.*: //')"
  done
  echo "run $r pmb perideal-2ranks $(rate mpirun -np 2 "$build/bin/perideal-solid" "$here/pmb_lattice_3d.prm")"
done
rm -rf "$work"
