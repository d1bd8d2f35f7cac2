#!/bin/bash
# Each file of invalid/ passes the entries' own checks but breaks one that needs the mesh, the
# regions' geometry or the model's calibration (or deal.II's pattern check); perideal-solid
# --validate must refuse it, exit non-zero, name the entry given in the file's "# Expect:" line,
# and leave nothing on disk. Usage: validate_refusals.sh INVALID-DIR COMMAND... (the command
# that runs perideal-solid, e.g. "mpiexec -np 2 perideal-solid").
invalid=$(cd "$1" && pwd)
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0
for file in "$invalid"/*.prm; do
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
