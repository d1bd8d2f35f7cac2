#!/bin/bash
# Each file of invalid/ passes the entries' own checks but breaks one that needs the mesh, the
# regions' geometry or the model's calibration (or deal.II's pattern check); perideal-solid
# --validate must refuse it, exit non-zero, name the entry given in the file's "# Expect:" line,
# and leave nothing on disk. Usage: validate_refusals.sh INVALID-DIR SHARD SHARDS COMMAND...
# (the command that runs perideal-solid, e.g. "mpiexec -np 2 perideal-solid"); the script checks
# the files whose index in the sorted list is SHARD modulo SHARDS, so that one ctest case per
# shard stays short on 2 ranks, where each file costs an MPI start.
invalid=$(cd "$1" && pwd)
shard=$2
shards=$3
shift 3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0
index=0
for file in "$invalid"/*.prm; do
  index=$((index + 1))
  if [ $(((index - 1) % shards)) -ne "$shard" ]; then
    continue
  fi
  expect=$(sed -n 's/^# Expect: //p' "$file")
  if "$@" --validate "$file" > out.txt 2> err.txt; then
    echo "FAILED: $(basename "$file") validates"
    failures=$((failures + 1))
  elif ! grep -qF -- "$expect" err.txt; then
    echo "FAILED: $(basename "$file") is refused without naming $expect:"
    cat err.txt
    failures=$((failures + 1))
  else
    echo "$(basename "$file"): refused, naming $expect"
  fi
  rm -f out.txt err.txt
  if [ -n "$(ls -A)" ]; then
    echo "FAILED: $(basename "$file") left on disk: $(ls -A)"
    failures=$((failures + 1))
    rm -rf ./*
  fi
done
exit $failures
