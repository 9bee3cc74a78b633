#!/bin/bash
# The main job: builds the rheomag executable (and only the libraries it links), solves the
# bundled reference valve at 1 A and writes its VTK file.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh --main
mkdir -p out
build/app/rheomag solve cases/annular_valve.toml --current 1 --vtk out/annular_valve.vtu
