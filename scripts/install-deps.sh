#!/usr/bin/env bash
# Installs exactly the Debian packages flexure builds and tests with. Idempotent; run as root
# (or with sudo available) on Debian 12. Packages already present are left alone.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  ccache  # scripts/test.sh: the MPI build reuses the serial build's objects of the layers below io
  libeigen3-dev libgsl-dev libhdf5-dev hdf5-tools libsundials-dev
  libaec-dev zlib1g-dev  # the static libhdf5.a needs szip (libaec) and zlib at link time
  libcli11-dev nlohmann-json3-dev libfmt-dev libtomlplusplus-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libnlopt-cxx-dev  # the optimiser of `flexure design` (docs/design.md)
  # The MPI build (-DFLEXURE_MPI=ON, docs/scaling.md): Open MPI and the parallel HDF5 built on it.
  openmpi-bin libopenmpi-dev libhdf5-openmpi-dev
  python3-matplotlib python3-h5py python3-numpy
  # The Python module (docs/python.md): pybind11, the headers of Debian's Python, pytest, and
  # what `pip install --no-build-isolation .` into a venv needs offline.
  pybind11-dev python3-pybind11 python3-dev python3-pytest python3-venv python3-pip
  python3-setuptools python3-wheel
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
