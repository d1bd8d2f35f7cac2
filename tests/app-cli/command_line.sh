#!/bin/bash
# The command line of perideal-solid as a new user tries it: --version prints one line naming
# the build (PeriDeal version, git revision, deal.II, Trilinos and MPI versions) and every run's
# log starts with that line; --help and -h print the usage and exit 0; --print-parameters takes
# the dimension 2 or 3 only (4 and x are refused naming them) and prints a file that validates;
# --validate checks several files in one call, refusing each missing one by name; an unknown
# option is refused. Usage: command_line.sh PERIDEAL-SOLID
solver=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0
fail() { echo "FAILED: $*"; failures=$((failures + 1)); }

version=$("$solver" --version) || fail "--version exits non-zero"
[[ $version =~ ^PeriDeal\ [0-9]+\.[0-9]+\.[0-9]+\ \(git\ [^\)]+\),\ deal\.II\ [0-9.]+,\ Trilinos\ [0-9]+\.[0-9]+\.[0-9]+,\ MPI\ [0-9]+\.[0-9]+\ \(.+\)$ ]] ||
  fail "--version prints <$version>"
[ "$(echo "$version" | wc -l)" = 1 ] || fail "--version prints more than one line"

for option in --help -h; do
  out=$("$solver" $option 2>&1) || fail "$option exits non-zero"
  [[ $out == "Usage: perideal-solid"* ]] || fail "$option does not print the usage"
  [[ $out == *"--version"* && $out == *"--print-parameters"* && $out == *"--validate"* ]] ||
    fail "$option does not list every option"
done
"$solver" > out.txt 2>&1 && fail "no argument exits 0"
grep -q "^Usage: perideal-solid" out.txt || fail "no argument does not print the usage"

for dimension in 4 x "2 3"; do
  "$solver" --print-parameters $dimension > out.txt 2> err.txt &&
    fail "--print-parameters $dimension exits 0"
  grep -q "takes the dimension 2 or 3" err.txt || fail "--print-parameters $dimension: $(cat err.txt)"
  [ -s out.txt ] && fail "--print-parameters $dimension prints a template"
done
for dimension in "" 2 3; do
  "$solver" --print-parameters $dimension > "template$dimension.prm" ||
    fail "--print-parameters $dimension"
  grep -q "set Dimension *= *${dimension:-2}" "template$dimension.prm" ||
    fail "--print-parameters $dimension: not the ${dimension:-2}D template"
done
"$solver" --validate template.prm template2.prm template3.prm > out.txt 2>&1 ||
  fail "the templates of --print-parameters do not validate: $(cat out.txt)"
grep -qxF "3 files: 3 valid, 0 refused" out.txt || fail "--validate of 3 files prints $(cat out.txt)"
# Files that do not exist: each refused by name, the others still checked.
"$solver" --validate a.prm template.prm b.prm > out.txt 2> err.txt && fail "--validate a.prm ... exits 0"
grep -qxF "Error in a.prm:" err.txt && grep -qxF "Error in b.prm:" err.txt ||
  fail "--validate a.prm template.prm b.prm does not name both missing files: $(cat err.txt)"
grep -qxF "3 files: 1 valid, 2 refused" out.txt || fail "--validate a.prm ... prints $(cat out.txt)"

for arguments in "--frobnicate" "--validate" "--restart" "a.prm b.prm"; do
  "$solver" $arguments > out.txt 2>&1 && fail "<$arguments> exits 0"
done

# A run (the 2D template, 2 us of explicit dynamics): its log starts with the version line.
"$solver" template.prm > run.log 2>&1 || fail "the 2D template does not run: $(tail -3 run.log)"
[ "$(head -n 1 run.log)" = "$version" ] || fail "the run's log starts with <$(head -n 1 run.log)>"

[ $failures = 0 ] && echo "command line: all checks passed"
exit $failures
