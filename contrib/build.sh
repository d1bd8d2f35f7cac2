#!/usr/bin/env bash
# Configure and build PeriDeal (Release, Ninja, ccache) in ./build (or $PERIDEAL_BUILD_DIR).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
build=${PERIDEAL_BUILD_DIR:-$top/build}
cmake -G Ninja -S "$top" -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j "$(nproc)"
