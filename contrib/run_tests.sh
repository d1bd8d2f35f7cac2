#!/usr/bin/env bash
# The test command of the README: install dependencies (as root), build, run the ctest suite.
# The tests labelled "long" (tests/CMakeLists.txt, perideal_label_long_tests) are left out;
# `--long` runs only them, `--all` everything. Other arguments go to ctest.
set -euo pipefail
selection=(-LE long)
case "${1:-}" in
  --long) selection=(-L long); shift ;;
  --all) selection=(); shift ;;
esac
top=$(cd "$(dirname "$0")/.." && pwd)
if [ "$(id -u)" -eq 0 ]; then
  "$top/contrib/install_dependencies.sh"
  # Open MPI refuses to start as root unless told so explicitly.
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
command -v numdiff >/dev/null || { echo "numdiff is missing: the tests cannot compare output" >&2; exit 1; }
python3 "$top/contrib/check_dependencies.py" "$top"
# The ccache settings of build.sh for the test programs ctest compiles too.
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$top} CCACHE_NOHASHDIR=${CCACHE_NOHASHDIR:-1}
"$top/contrib/build.sh"
build=${PERIDEAL_BUILD_DIR:-$top/build}
cd "$build"
ctest -j "$(nproc)" --output-on-failure ${selection[@]+"${selection[@]}"} "$@"
