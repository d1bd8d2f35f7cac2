#!/bin/bash
# The many-rank measurements of README.md (issue #41, part 3), from a build of PeriDeal:
#   bash run.sh BUILD_DIR [WORK_DIR]
# 1. kalthoff_plate_3d.prm and kalthoff_plate_3d_adaptive.prm on 1, 2, 4 and 8 ranks (more ranks
#    than cores: --oversubscribe): the summaries must be identical line by line (times, memory
#    and the communication line excepted); prints each rank count's communication line.
#    The same plate at dx = 2 mm (rows on the notch planes, the slits), the same comparison.
# 2. The same plate at dx = 0.625 mm (8 x the particles), 20 steps, for the communication line.
# 3. The all-PD cube of doc/benchmarks/performance/pmb_lattice_3d.prm (41^3 particles), 20 steps.
# 4. The traffic per step counted by MPI itself (mpi_traffic.c preloaded, two run lengths) for the
#    plate on 4 ranks, against the code's count.
set -e
BUILD=$(cd "${1:?usage: run.sh BUILD_DIR [WORK_DIR]}" && pwd)
HERE=$(cd "$(dirname "$0")" && pwd)
WORK=${2:-$(mktemp -d)}
mkdir -p "$WORK" && cd "$WORK"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
SOLID="$BUILD/bin/perideal-solid"
FILTER='time|elapsed|per second|Peak|PeriDeal|^step|Set-up|Communication'

run() { # run NAME RANKS PRM [OVERRIDES]: NAME.RANKS.log
  local name=$1 n=$2 prm=$3
  { echo "include $prm"; echo "$4"; } > "$name.prm"
  /usr/bin/time -f "%e s wall, %M KB peak of one rank" \
    mpirun --oversubscribe -np "$n" "$SOLID" "$name.prm" > "$name.$n.log" 2> "$name.$n.time"
}

for case in kalthoff_plate_3d kalthoff_plate_3d_adaptive; do
  for n in 1 2 4 8; do
    run "$case" "$n" "$HERE/$case.prm" "subsection Output
  set Directory = $case.$n
end"
    echo "$case on $n ranks: $(tail -1 "$case.$n.time")"
    grep Communication "$case.$n.log" || true
  done
  for n in 2 4 8; do
    if diff <(grep -v -E "$FILTER" "$case.1.log") <(grep -v -E "$FILTER" "$case.$n.log") > /dev/null
    then echo "$case: $n ranks identical to 1 rank"
    else echo "$case: $n ranks DIFFER from 1 rank"; fi
  done
done

# The plate at dx = 2 mm: particle rows on the notch planes (the slits of the mesh).
for n in 1 2 4 8; do
  run slit "$n" "$HERE/kalthoff_plate_3d.prm" "subsection Discretization
  set Lattice spacing = 2e-3
end
subsection Output
  set Directory = slit.$n
end"
  echo "plate dx = 2 mm on $n ranks: $(tail -1 "slit.$n.time")"
done
for n in 2 4 8; do
  if diff <(grep -v -E "$FILTER" slit.1.log) <(grep -v -E "$FILTER" "slit.$n.log") > /dev/null
  then echo "plate dx = 2 mm: $n ranks identical to 1 rank"
  else echo "plate dx = 2 mm: $n ranks DIFFER from 1 rank"; fi
done

for n in 1 2 4 8; do
  run fine "$n" "$HERE/kalthoff_plate_3d.prm" "subsection Discretization
  set Lattice spacing = 6.25e-4
end
subsection Time stepping
  set End time = 2e-6
end
subsection Output
  set Directory = fine.$n
end"
  echo "plate dx = 0.625 mm on $n ranks: $(grep -E '^Particles|^Bonds' "fine.$n.log" | tr '\n' ' ')$(tail -1 "fine.$n.time")"
  grep -E "Communication|bond updates" "fine.$n.log" || true
done

for n in 1 2 4 8; do
  run cube "$n" "$HERE/../performance/pmb_lattice_3d.prm" "subsection Time stepping
  set End time = 2e-7
end
subsection Output
  set Directory = cube.$n
end"
  echo "cube on $n ranks: $(grep -E '^Particles|^Bonds' "cube.$n.log" | tr '\n' ' ')$(tail -1 "cube.$n.time")"
  grep -E "Communication|bond updates" "cube.$n.log" || true
done

mpicc -shared -fPIC -O2 -o libmpi_traffic.so "$HERE/mpi_traffic.c"
for end in 3.5e-5 1.75e-5; do
  { echo "include $HERE/kalthoff_plate_3d.prm"
    echo "subsection Time stepping"; echo "  set End time = $end"; echo "end"
    echo "subsection Output"; echo "  set Statistics interval = 1000"; echo "  set Directory = traffic.$end"; echo "end"; } > traffic.$end.prm
  mpirun --oversubscribe -np 4 -x LD_PRELOAD="$PWD/libmpi_traffic.so" "$SOLID" traffic.$end.prm \
    > traffic.$end.log 2>&1
done
s1=$(grep -o "steps: [0-9]*" traffic.3.5e-5.log | cut -d' ' -f2)
s2=$(grep -o "steps: [0-9]*" traffic.1.75e-5.log | cut -d' ' -f2)
paste <(grep mpi_traffic traffic.3.5e-5.log | sort) <(grep mpi_traffic traffic.1.75e-5.log | sort) |
  awk -v d=$((s1 - s2)) '{printf "MPI counted, %s %s %.0f B sent per step, %.2f messages, %.2f collectives\n",
    $2, $3, ($8 - $20) / d, ($6 - $18) / d, ($10 - $22) / d}'
grep Communication traffic.3.5e-5.log
echo "results in $WORK"
