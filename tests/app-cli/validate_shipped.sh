#!/bin/bash
# Every parameter file the repository ships (doc/ and tests/app-solid/, with the .prm.in
# templates of tests/app-solid as configured in the build tree) validates as shipped, from a
# working directory that is not its own folder (relative includes, meshes and grain files are
# found from the file that names them), and a validation leaves nothing on disk. One
# perideal-solid --validate checks all files of a set. Usage: validate_shipped.sh SOURCE-DIR
# BINARY-DIR PERIDEAL-SOLID SET, where SET is `benchmarks` (doc/benchmarks) or `others` (the rest
# of doc/ and tests/app-solid).
source_dir=$1 binary_dir=$2 solver=$3 set=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
case $set in
  benchmarks) list() { find "$source_dir/doc/benchmarks" -name '*.prm' | sort; } ;;
  others) list() {
    find "$source_dir/doc" -path "$source_dir/doc/benchmarks" -prune -o -name '*.prm' -print | sort
    find "$source_dir/tests/app-solid" -name '*.prm' | sort
    find "$binary_dir/tests/app-solid" -maxdepth 1 -name '*.prm' | sort
  } ;;
  *) echo "validate_shipped.sh: SET must be benchmarks or others, not '$set'"; exit 1 ;;
esac
mapfile -t files < <(list)
mkdir run
status=0
(cd run && "$solver" --validate "${files[@]}") > out.txt 2> err.txt || status=1
cat out.txt err.txt
left=$(ls -A run)
if [ -n "$left" ]; then
  echo "FAILED: the validations left on disk: $left"
  status=1
fi
grep -qxF "${#files[@]} files: ${#files[@]} valid, 0 refused" out.txt || status=1
exit $status
