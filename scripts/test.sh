#!/usr/bin/env bash
# Builds flexure in Release mode and runs the whole test suite: ctest, then pytest on the Python
# module in the build tree, then the module installed as a wheel into a fresh venv and tested
# there (docs/python.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$(nproc)"
ctest --test-dir build --output-on-failure -j "$(nproc)"

# The Python module from the build tree (Debian's interpreter: numpy, h5py, matplotlib, pytest).
PYTHONPATH="$PWD/build/python" FLEXURE_BUILD_DIR="$PWD/build" /usr/bin/python3 -m pytest -q tests/python

# The wheel: pip builds it from this checkout offline (reusing build/), installs it into a venv.
venv="$(mktemp -d)/venv"
trap 'rm -rf "$(dirname "$venv")"' EXIT
/usr/bin/python3 -m venv --system-site-packages "$venv"
FLEXURE_CMAKE_BUILD_DIR="$PWD/build" "$venv/bin/pip" install --quiet --no-build-isolation \
  --no-index .
FLEXURE_EXPECT_INSTALLED="$venv" FLEXURE_BUILD_DIR="$PWD/build" \
  "$venv/bin/python" -m pytest -q tests/python/test_installed.py tests/python/test_cli_parity.py
