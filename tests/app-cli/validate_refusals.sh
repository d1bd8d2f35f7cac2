#!/bin/bash
# Each file of invalid/ passes the entries' own checks but breaks one that needs the mesh, the
# regions' geometry or the model's calibration (or deal.II's pattern check); perideal-solid
# --validate, given all of them at once, must refuse each, name the entry given in the file's
# "# Expect:" line in that file's error, exit non-zero and leave nothing on disk.
# Usage: validate_refusals.sh INVALID-DIR COMMAND... (the command that runs perideal-solid, e.g.
# "mpiexec -np 2 perideal-solid").
invalid=$(cd "$1" && pwd)
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
files=("$invalid"/*.prm)
failures=0
if "$@" --validate "${files[@]}" > out.txt 2> err.txt; then
  echo "FAILED: --validate of the ${#files[@]} files exits 0"
  failures=$((failures + 1))
fi
for file in "${files[@]}"; do
  expect=$(sed -n 's/^# Expect: //p' "$file")
  # The error of this file: from its "Error in FILE:" line to the next file's.
  error=$(awk -v head="Error in $file:" '/^Error in /{p = ($0 == head)} p' err.txt)
  if grep -qxF "$file: valid" out.txt; then
    echo "FAILED: $(basename "$file") validates"
    failures=$((failures + 1))
  elif ! grep -qF -- "$expect" <<< "$error"; then
    echo "FAILED: $(basename "$file") is refused without naming $expect:"
    echo "$error"
    failures=$((failures + 1))
  else
    echo "$(basename "$file"): refused, naming $expect"
  fi
done
summary="${#files[@]} files: 0 valid, ${#files[@]} refused"
grep -qxF "$summary" out.txt || { echo "FAILED: no line <$summary>"; failures=$((failures + 1)); }
rm -f out.txt err.txt
if [ -n "$(ls -A)" ]; then
  echo "FAILED: left on disk: $(ls -A)"
  failures=$((failures + 1))
fi
exit $failures
