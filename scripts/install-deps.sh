#!/bin/bash
# Installs the Debian 12 packages rheomag builds against (idempotent; needs root or sudo).
# Without options, what building and running the rheomag executable needs (the main job); with
# --tests, also what only the test suite, the benchmarks and the format check use.
set -euo pipefail
pkgs=(build-essential cmake pkg-config git ca-certificates
  libeigen3-dev libsuitesparse-dev libcgal-dev libvtk9-dev libcairo2-dev
  libtomlplusplus-dev nlohmann-json3-dev libcli11-dev
  libboost-dev libtet1.5-dev libmuparser-dev libopenblas0-pthread coinor-libipopt-dev libceres-dev libsvm-dev gnuplot-nox)
pkgs+=(libopenmpi-dev openmpi-bin)  # rheomag sweep under mpirun; hypre's MPI (below)
pkgs+=(libhypre-dev)  # the 3D solver's AMS-preconditioned CG (--linear-solver ams; MIT/Apache-2.0)
if [ "${1:-}" = --tests ]; then
  pkgs+=(libgtest-dev libgmock-dev libbenchmark-dev clang-format)
  pkgs+=(chromium)  # headless screenshot test of the diagnosis report (skipped when absent)
  # the Python module (python/, built by scripts/build.sh without --main), its tests and example
  pkgs+=(python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest python3-matplotlib)
fi
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "installing: ${missing[*]}" >&2
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi
