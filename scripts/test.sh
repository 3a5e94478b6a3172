#!/usr/bin/env bash
# Builds flexure in Release mode and runs the whole test suite: ctest, then pytest on the Python
# module in the build tree, then the module installed as a wheel into a fresh venv and tested
# there (docs/python.md); then the MPI variant (docs/scaling.md): the tool built against Open MPI
# and parallel HDF5 in build-mpi/, and its tests under mpirun with 1, 2 and 3 ranks.
set -euo pipefail
cd "$(dirname "$0")/.."
# Each phase prints its wall time (the suite must stay within CI's 20-minute budget, README).
phase() { echo "== test.sh: $1 done at ${SECONDS} s"; }
bash scripts/install-deps.sh
phase "dependencies"
# A compiler cache where one is installed (install-deps.sh installs ccache): the MPI build below
# compiles the layers under io (solver, elements, beam, mechanisms: no MPI, no HDF5) with exactly
# the serial build's flags, so it takes them from the cache instead of compiling them twice; on a
# machine that ran the suite before, unchanged files are not recompiled at all. CCACHE_BASEDIR
# makes the two build trees' paths compare equal. FLEXURE_NO_CCACHE=1 builds without it.
launcher=()
if [ -z "${FLEXURE_NO_CCACHE:-}" ] && command -v ccache >/dev/null; then
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${launcher[@]}"
cmake --build build -j "$(nproc)"
phase "build"
ctest --test-dir build --output-on-failure -j "$(nproc)"
phase "ctest"

# The Python module from the build tree (Debian's interpreter: numpy, h5py, matplotlib, pytest).
PYTHONPATH="$PWD/build/python" FLEXURE_BUILD_DIR="$PWD/build" /usr/bin/python3 -m pytest -q tests/python
phase "pytest"

# The wheel: pip builds it from this checkout offline (reusing build/), installs it into a venv.
venv="$(mktemp -d)/venv"
trap 'rm -rf "$(dirname "$venv")"' EXIT
/usr/bin/python3 -m venv --system-site-packages "$venv"
FLEXURE_CMAKE_BUILD_DIR="$PWD/build" "$venv/bin/pip" install --quiet --no-build-isolation \
  --no-index .
FLEXURE_EXPECT_INSTALLED="$venv" FLEXURE_BUILD_DIR="$PWD/build" \
  "$venv/bin/python" -m pytest -q tests/python/test_installed.py tests/python/test_cli_parity.py
phase "wheel"

# The MPI variant: only the tool and its MPI tests (the library's own tests ran above). The tests
# compare every file with the serial run of the same binary and with the serial build's binary,
# and run one at a time (each starts up to 3 ranks on this machine's cores).
cmake -S . -B build-mpi -DCMAKE_BUILD_TYPE=Release -DFLEXURE_MPI=ON -DFLEXURE_BUILD_BENCHMARKS=OFF \
  "${launcher[@]}"
cmake --build build-mpi -j "$(nproc)" --target flexure mpi_studies_test
phase "MPI build"
FLEXURE_SERIAL_BINARY="$PWD/build/flexure" \
  ctest --test-dir build-mpi -R '^MpiStudies\.' --output-on-failure
phase "MPI tests"
