#!/usr/bin/env bash
# The test command of the README: install the build and test dependencies (as root), build the
# library and the test programs, run the ctest suite, print the ten slowest cases and fail if a
# case ran past its tier's budget (tests/CMakeLists.txt: PERIDEAL_TEST_BUDGET,
# PERIDEAL_LONG_TEST_BUDGET).
# The tests labelled "long" (perideal_label_long_tests) are left out; `--long` runs only them,
# `--all` everything. Other arguments go to ctest.
set -euo pipefail
selection=(-LE long)
case "${1:-}" in
  --long) selection=(-L long); shift ;;
  --all) selection=(); shift ;;
esac
top=$(cd "$(dirname "$0")/.." && pwd)
if [ "$(id -u)" -eq 0 ]; then
  "$top/contrib/install_dependencies.sh" --tests
  # Open MPI refuses to start as root unless told so explicitly.
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
command -v numdiff >/dev/null || { echo "numdiff is missing: the tests cannot compare output" >&2; exit 1; }
python3 "$top/contrib/check_dependencies.py" "$top"
"$top/contrib/build.sh"
build=${PERIDEAL_BUILD_DIR:-$top/build}
# The test programs, compiled by ninja in parallel before ctest runs them.
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$top} CCACHE_NOHASHDIR=${CCACHE_NOHASHDIR:-1}
start=$(date +%s)
cmake --build "$build" --target perideal-tests -j "$(nproc)"
echo "Test programs built in $(( $(date +%s) - start )) s"
cd "$build"
log=$build/Testing/run_tests.log
mkdir -p "$(dirname "$log")"
start=$(date +%s)
set +e
ctest -j "$(nproc)" --output-on-failure ${selection[@]+"${selection[@]}"} "$@" | tee "$log"
status=${PIPESTATUS[0]}
set -e
echo "ctest wall time: $(( $(date +%s) - start )) s"
python3 "$top/contrib/test_times.py" "$log" "$build" || status=1
exit "$status"
