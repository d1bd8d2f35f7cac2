#!/bin/bash
# Every parameter file the repository ships (doc/ and tests/app-solid/, with the .prm.in
# templates of tests/app-solid as configured in the build tree) validates as shipped, from a
# working directory that is not its own folder: relative includes, meshes and grain files are
# found from the file that names them. Usage: validate_shipped.sh SOURCE-DIR BINARY-DIR
# PERIDEAL-SOLID SET [SHARD N], where SET is `benchmarks` (doc/benchmarks) or `others` (the rest
# of doc/ and tests/app-solid), and SHARD N (default 0 1) takes every N-th file of the set from
# the SHARD-th on: so that each ctest case stays short.
source_dir=$1 binary_dir=$2 solver=$3 set=$4 shard=${5:-0} n_shards=${6:-1}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
files=()
case $set in
  benchmarks) list() { find "$source_dir/doc/benchmarks" -name '*.prm' | sort; } ;;
  others) list() {
    find "$source_dir/doc" -path "$source_dir/doc/benchmarks" -prune -o -name '*.prm' -print | sort
    find "$source_dir/tests/app-solid" -name '*.prm' | sort
    find "$binary_dir/tests/app-solid" -maxdepth 1 -name '*.prm' | sort
  } ;;
  *) echo "validate_shipped.sh: SET must be benchmarks or others, not '$set'"; exit 1 ;;
esac
index=0
while IFS= read -r file; do
  [ $((index % n_shards)) = "$shard" ] && files+=("$file")
  index=$((index + 1))
done < <(list)
failed=()
for file in "${files[@]}"; do
  if ! "$solver" --validate "$file" > out.txt 2>&1; then
    failed+=("$file")
    echo "FAILED: $file"
    sed 's/^/    /' out.txt
  fi
  rm -rf ./*
done
echo "${#files[@]} files, $((${#files[@]} - ${#failed[@]})) valid, ${#failed[@]} refused"
[ ${#failed[@]} = 0 ]
