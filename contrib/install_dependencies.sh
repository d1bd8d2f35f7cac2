#!/usr/bin/env bash
# Install every Debian package PeriDeal needs to build, test (doxygen: the library reference's
# test), run the benchmarks and plot.
# Run as root on Debian 12 (bookworm) or newer.
set -euo pipefail
packages=(
  cmake ninja-build ccache g++ git numdiff doxygen
  libdeal.ii-dev libeigen3-dev openmpi-bin libopenmpi-dev
  python3 python3-numpy python3-matplotlib python3-h5py
)
if [ "$(id -u)" -ne 0 ]; then
  echo "contrib/install_dependencies.sh: run as root (apt-get needs it)" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update
apt-get install -y --no-install-recommends "${packages[@]}"
