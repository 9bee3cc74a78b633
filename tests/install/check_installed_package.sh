#!/bin/bash
# The installed package (issue 30): `cmake --install BUILD --prefix WORK/prefix`, then
#  - the installed rheomag runs from the prefix (RPATH $ORIGIN/../lib, no build-tree path) and
#    prints its version;
#  - an outside project (tests/install/consumer) configured with find_package(rheomag) builds
#    and solves the bundled reference valve; its inductance must equal, to all 17 digits, that of
#    the installed `rheomag solve --json` (same library, same case: no tolerance);
#  - the same program built with `pkg-config --cflags --libs rheomag` gives the same number;
#  - the installed Python module (when built) gives the same number from the prefix alone.
# usage: check_installed_package.sh BUILD_DIR SOURCE_DIR WORK_DIR [PYTHON (the module's)]
set -euo pipefail
build=$1 src=$2 work=$3 python=${4:-python3}
case_file=$src/cases/annular_valve.toml
rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" >"$work/install.log"
prefix=$work/prefix
libdir=$(dirname "$(find "$prefix" -name 'librheomag_core.*' | head -1)")

if readelf -d "$prefix/bin/rheomag" | grep -E 'R(UN)?PATH' | grep -qF "$build"; then
  echo "FAIL: the installed rheomag's RPATH names the build tree" >&2
  exit 1
fi
version=$("$prefix/bin/rheomag" --version)
echo "$version"
[[ $version =~ ^rheomag\ [0-9]+\.[0-9]+\.[0-9]+\ \(git\ .+\)$ ]] ||
  { echo "FAIL: --version printed '$version'" >&2; exit 1; }

cli=$("$prefix/bin/rheomag" solve "$case_file" --json |
  python3 -c 'import json, sys; d = json.load(sys.stdin); print(d["version"], repr(d["inductance"]))')

cmake -S "$src/tests/install/consumer" -B "$work/consumer" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" >"$work/consumer-config.log"
cmake --build "$work/consumer" >"$work/consumer-build.log"
compare() {  # compare NAME OUTPUT: version and inductance (as Python reads both) equal the CLI's
  local got
  got=$(echo "$2" | python3 -c 'import sys; v, l = sys.stdin.read().split(); print(v, repr(float(l)))')
  if [ "$got" != "$cli" ]; then
    echo "FAIL: $1 printed '$got', the installed CLI '$cli'" >&2
    exit 1
  fi
  echo "$1: $got (CLI: $cli)"
}
compare "find_package(rheomag)" "$("$work/consumer/solve_case" "$case_file")"

export PKG_CONFIG_PATH=$libdir/pkgconfig
# shellcheck disable=SC2046  # pkg-config's flags are words
g++ -O2 -o "$work/solve_case_pc" "$src/tests/install/consumer/solve_case.cpp" \
  $(pkg-config --cflags --libs rheomag)
compare "pkg-config rheomag" "$("$work/solve_case_pc" "$case_file")"

# The installed Python module (built with -DRHEOMAG_PYTHON=ON), from the prefix only.
if [ -d "$libdir/python3/dist-packages/rheomag" ]; then
  compare "installed Python module" "$(cd "$work" && PYTHONPATH=$libdir/python3/dist-packages "$python" -c \
    'import sys, rheomag; s = rheomag.Case.load(sys.argv[1]).solve(); print(rheomag.__version__, repr(s.inductance))' \
    "$case_file")"
fi
