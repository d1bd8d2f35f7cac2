#!/bin/bash
# Kill test of checkpoint and restart: run a problem to the end (the reference), then TRIALS
# times: start the same run with checkpoints, kill it with SIGKILL (by process id) at a random
# moment of its run time, continue it with --restart (or from the start if it was killed before
# its first checkpoint) until it ends, and compare its results with the reference:
# statistics.csv and the XDMF records byte for byte (on the same number of ranks the restart is
# exact), the particle and FE fields of the last output with h5diff if it is installed.
#
# Usage: contrib/restart_kill_test.sh BUILD_DIR FILE.prm [TRIALS [RANKS [INTERVAL]]]
#   FILE.prm is included by a wrapper that sets Output/Directory, Output/Progress = false and
#   Output/Checkpoint interval = INTERVAL (default 200), or with INTERVAL = time:T
#   Output/Checkpoint time interval = T (simulated time [s], a load factor for quasi-static
#   runs) instead. Not part of ctest (it runs the problem
#   2 x TRIALS + 1 times). Example:
#   contrib/restart_kill_test.sh build contrib/restart_kill_test.prm 5 2
set -u
build=$(realpath "$1")
prm=$(realpath "$2")
trials=${3:-5}
ranks=${4:-1}
interval=${5:-200}
work=$(mktemp -d /tmp/restart_kill_test.XXXXXX)
cd "$work" || exit 1

if [ "${interval#time:}" != "$interval" ]; then
  checkpoint_entry="Checkpoint time interval = ${interval#time:}"
else
  checkpoint_entry="Checkpoint interval = $interval"
fi

wrapper() { # directory
  printf 'include %s\nsubsection Output\n  set Directory = %s\n  set Progress = false\n  set %s\nend\n' \
    "$prm" "$1" "$checkpoint_entry" >"$1.prm"
}

launch() { # arguments of perideal-solid; sets pid to the run in the background
  if [ "$ranks" -eq 1 ]; then
    "$build/bin/perideal-solid" "$@" >>log.txt 2>&1 &
  else
    mpirun -np "$ranks" "$build/bin/perideal-solid" "$@" >>log.txt 2>&1 &
  fi
  pid=$!
}

# SIGKILL the run @p pid: the ranks themselves under mpirun (a node failure), then mpirun.
kill_run() {
  local pid=$1
  for child in $(pgrep -P "$pid"); do kill -KILL "$child" 2>/dev/null; done
  kill -KILL "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
}

wrapper reference
start=$(date +%s.%N)
launch reference.prm
wait "$pid" || { echo "reference run failed, see $work/log.txt"; exit 1; }
seconds=$(echo "$(date +%s.%N) - $start" | bc)
echo "reference: $seconds s on $ranks rank(s), $checkpoint_entry; in $work"

failures=0
for trial in $(seq 1 "$trials"); do
  dir=trial$trial
  rm -rf "$dir"
  wrapper "$dir"
  delay=$(python3 -c "import random; print(round(random.uniform(0.05, 0.95) * $seconds, 2))")
  launch "$dir.prm"
  sleep "$delay"
  if kill -0 "$pid" 2>/dev/null; then
    kill_run "$pid"
    how="killed after $delay s"
  else
    wait "$pid"
    how="ended before the kill at $delay s"
  fi
  step=$(sed -n 's/^step = //p' "$dir/checkpoint" 2>/dev/null | head -1)
  leftover=$([ -e "$dir/checkpoint.tmp" ] && echo ", checkpoint.tmp left" || echo "")
  if [ -e "$dir/checkpoint" ]; then
    launch --restart "$dir.prm"
    resumed="restarted from step $step$leftover"
  else
    launch "$dir.prm"
    resumed="no checkpoint yet$leftover, run again from the start"
  fi
  wait "$pid" || { echo "trial $trial: the continued run failed, see $work/log.txt"; failures=$((failures + 1)); continue; }
  verdict=ok
  for file in statistics.csv particles.xdmf solution.xdmf; do
    if [ -e "reference/$file" ] && ! cmp -s "reference/$file" "$dir/$file"; then
      verdict="FAILED ($file differs)"
    fi
  done
  if command -v h5diff >/dev/null; then
    for h5 in reference/*.h5; do
      [ -e "$h5" ] || continue
      h5diff -q "$h5" "$dir/$(basename "$h5")" >/dev/null 2>&1 || verdict="FAILED ($(basename "$h5") differs)"
    done
  fi
  [ "$verdict" = ok ] || failures=$((failures + 1))
  echo "trial $trial: $how, $resumed: $verdict"
done
echo "$((trials - failures)) of $trials trials reproduce the reference"
[ "$failures" -eq 0 ]
