#!/usr/bin/env bash
# The test command of the README: install dependencies (as root), build, run the ctest suite.
set -euo pipefail
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
ctest -j "$(nproc)" --output-on-failure "$@"
