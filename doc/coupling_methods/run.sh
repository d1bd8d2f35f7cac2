#!/usr/bin/env bash
# Comparison of the coupling methods (issue #16, part 2): runs every case of this directory's
# templates with the blended and the overlapping Schwarz coupling and regenerates
# doc/coupling_methods.md and doc/coupling_methods/*.png (compare.py). Fails on the first run
# that fails. About 5-10 minutes on 2 cores.
# usage: bash doc/coupling_methods/run.sh [BUILD_DIR]   (default: build of this repository)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="$(cd "${1:-$here/../../build}" && pwd)"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
exec /usr/bin/python3 "$here/compare.py" --build "$build"
