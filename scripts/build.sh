#!/bin/bash
# Configures rheomag (Release, unity batches) into build/ and builds it; installs missing Debian
# packages first.
#   scripts/build.sh          everything: the executable, the tests, the benchmarks, the fuzz targets,
#                             the Python module (build/python; PYTHONPATH=build/python)
#   scripts/build.sh --main   only the rheomag executable and the libraries it links (the main job);
#                             needs neither the test nor the benchmark packages
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = --main ]; then
  scripts/install-deps.sh
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DRHEOMAG_UNITY=ON -DRHEOMAG_TESTS=OFF \
    -DRHEOMAG_BENCH=OFF -DRHEOMAG_PYTHON=OFF >/dev/null
  cmake --build build -j"$(nproc)" --target rheomag
else
  scripts/install-deps.sh --tests
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DRHEOMAG_UNITY=ON -DRHEOMAG_TESTS=ON \
    -DRHEOMAG_BENCH=ON -DRHEOMAG_PYTHON=ON >/dev/null
  cmake --build build -j"$(nproc)"
fi
