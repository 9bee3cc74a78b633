#!/bin/bash
# Builds everything (the executable, the tests, the benchmarks) and runs the whole test suite
# (CTest).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh  # installs the test packages too (install-deps.sh --tests)
scripts/check-format.sh
# Tests run two at a time on the two cores: keep BLAS/OpenMP single-threaded in each, or the
# threads of parallel tests oversubscribe the cores (measured 20x slower solves under load).
export OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1
ctest --test-dir build --output-on-failure -j"$(nproc)"
