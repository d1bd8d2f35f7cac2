#!/usr/bin/env bash
# Install the Debian packages PeriDeal needs to build and test (doxygen: the library reference's
# test; python3: the test command's scripts) and, unless --tests is given, also those the
# benchmarks' post-processing and plots need (numpy, matplotlib, h5py). The test command
# (contrib/run_tests.sh) passes --tests: the plotting packages are a tenth of the download
# (60 of 580 packages, 61 of 615 MB on a fresh Debian 12) and no test uses them.
# Run as root on Debian 12 (bookworm) or newer. Usage: install_dependencies.sh [--tests]
set -euo pipefail
packages=(
  cmake ninja-build ccache g++ git numdiff doxygen
  libdeal.ii-dev libeigen3-dev openmpi-bin libopenmpi-dev
  python3
)
case "${1:-}" in
  --tests) ;;
  "") packages+=(python3-numpy python3-matplotlib python3-h5py) ;;
  *) echo "contrib/install_dependencies.sh: unknown argument <$1> (accepted: --tests)" >&2; exit 1 ;;
esac
if [ "$(id -u)" -ne 0 ]; then
  echo "contrib/install_dependencies.sh: run as root (apt-get needs it)" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update
# dpkg's --force-unsafe-io skips the sync after every unpacked file (as Debian's container images
# do): the 580 packages of a fresh machine unpacked in 364 s instead of 1078 s (fresh Debian 12
# minbase chroot, the same machine under the same load). The price: a crash during the install
# can leave files of the packages being unpacked empty; reinstall them then.
apt-get install -y --no-install-recommends -o Dpkg::Options::=--force-unsafe-io "${packages[@]}"
