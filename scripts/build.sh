#!/bin/bash
# Configures rheomag (Release) into build/ and builds the given targets, or everything when none
# is given; installs missing packages first. `scripts/build.sh rheomag` builds the executable
# and the libraries it links, nothing else (the main job).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build -j"$(nproc)" "${targets[@]}"
