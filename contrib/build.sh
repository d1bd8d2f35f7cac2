#!/usr/bin/env bash
# Configure and build PeriDeal (Release, Ninja, ccache) in ./build (or $PERIDEAL_BUILD_DIR).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
build=${PERIDEAL_BUILD_DIR:-$top/build}
# ccache: paths below the checkout are hashed relative to it and the build directory is not
# hashed (deal.II's flags carry -g), so every clone and worktree shares the cache.
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$top} CCACHE_NOHASHDIR=${CCACHE_NOHASHDIR:-1}
cmake -G Ninja -S "$top" -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j "$(nproc)"
