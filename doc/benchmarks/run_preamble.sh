# What the benchmarks' run.sh share (sourced, not run; the caller sets top, the repository's top
# directory): install the dependencies if something is missing (as root; the list is
# contrib/install_dependencies.sh's), let Open MPI run as root, build PeriDeal (incremental: a
# no-op when up to date). Sets python (default /usr/bin/python3, or $PYTHON) and build (the
# build directory, default <top>/build, or $PERIDEAL_BUILD_DIR).
python=${PYTHON:-/usr/bin/python3}

if ! { command -v cmake && command -v ninja && command -v mpirun && command -v numdiff &&
       dpkg -s libdeal.ii-dev && "$python" -c "import numpy, h5py, matplotlib"; } >/dev/null 2>&1; then
  if [ "$(id -u)" -eq 0 ]; then
    "$top/contrib/install_dependencies.sh"
  else
    echo "run.sh: dependencies missing; run contrib/install_dependencies.sh as root first" >&2
    exit 1
  fi
fi
if [ "$(id -u)" -eq 0 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi

"$top/contrib/build.sh"
build=${PERIDEAL_BUILD_DIR:-$top/build}
