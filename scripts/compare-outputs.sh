#!/bin/bash
# Runs the same commands with two rheomag binaries (e.g. the previous commit's and this one's)
# and compares their outputs byte for byte, timings aside: a restructuring must not change a
# result. Usage: scripts/compare-outputs.sh OLD_BINARY NEW_BINARY [SHARED_DIR] [GROUP...]
# Groups: fe (solve, valve, transient, damper, brake, flow, shear, mesh), study (sweep, optimise),
# ident (fit, fit-family, simulate), diagnose (diagnose, diagnose --baseline); all by default.
# Prints one line per command (same / DIFFERS, with the first differing lines) and exits 1 if any
# output differs.
set -uo pipefail
old=$(realpath "${1:?usage: compare-outputs.sh OLD NEW [SHARED_DIR] [GROUP...]}")
new=$(realpath "${2:?usage: compare-outputs.sh OLD NEW [SHARED_DIR] [GROUP...]}")
cd "$(dirname "$0")/.."
shared=$(realpath "${3:-../shared}")
shift 3 2>/dev/null || shift $#
groups=("$@")
[ ${#groups[@]} -gt 0 ] || groups=(fe study ident diagnose)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
data=$shared/data
failures=0

# Lines that carry a wall-clock time or a temporary path, removed before comparing; the JSON
# documents' "version" (the build's git revision) masked.
mask() {
  sed -E -e 's#'"$work"'/(old|new)#OUT#g' \
    -e 's/"version": ?"[^"]*"/"version": VERSION/g' \
    -e '/"([a-z_]*seconds|elapsed[a-z_]*|time_s|solve_time[a-z_]*)"/d' \
    -e 's/, [0-9.]+ s$//' \
    -e 's/[0-9.]+ ?(s|ms) (wall|cpu|elapsed)//g' -e 's/(in|took) [0-9.]+ ?s\b//g' \
    -e 's/[0-9.]+ s, [0-9.]+ designs\/min/TIME/' \
    -e '/(left|ETA|elapsed)/d' "$1"
}

# run NAME ARGS...: runs both binaries in their own output folder (OUT stands for it), compares
# stdout and every file written there.
run() {
  local name=$1
  shift
  local side bin
  for side in old new; do
    bin=$old
    [ "$side" = new ] && bin=$new
    mkdir -p "$work/$side/$name"
    local args=("${@//OUT/$work/$side/$name}")
    (cd "$work/$side/$name" && OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 "$bin" "${args[@]}" \
      >"$work/$side/$name.stdout" 2>"$work/$side/$name.stderr")
    echo "exit $?" >>"$work/$side/$name.stdout"
  done
  local differs=""
  for f in "$work/old/$name.stdout" $(cd "$work/old/$name" && find . -type f | sort); do
    local rel=${f#"$work/old/"}
    [ "$f" = "$work/old/$name.stdout" ] && rel=$name.stdout || rel=$name/${f#./}
    if ! cmp -s <(mask "$work/old/$rel") <(mask "$work/new/$rel" 2>/dev/null); then
      differs+=" $rel"
    fi
  done
  local extra
  extra=$(diff <(cd "$work/old/$name" && find . -type f | sort) \
    <(cd "$work/new/$name" && find . -type f | sort))
  [ -n "$extra" ] && differs+=" (files differ: $extra)"
  if [ -z "$differs" ]; then
    echo "same     $name"
  else
    echo "DIFFERS  $name:$differs"
    for rel in $differs; do
      [ -f "$work/old/$rel" ] && diff <(mask "$work/old/$rel") <(mask "$work/new/$rel") | head -6
    done
    failures=$((failures + 1))
  fi
}

in_group() { [[ " ${groups[*]} " == *" $1 "* ]]; }
src=$PWD

if in_group fe; then
  run solve_text solve "$src/cases/annular_valve.toml" --current 1 --vtk OUT/valve.vtu
  run solve_json solve "$src/cases/annular_valve.toml" --sweep 0.5,1 --json
  run solve_radial solve "$src/cases/radial_valve.toml" --current 1 --json
  run solve_fem solve "$src/tests/data/pot_core.fem" --json
  run mesh mesh "$src/cases/meandering_valve.toml" --json
  run valve valve "$src/cases/annular_valve.toml" --current 0,1 --flow 1e-6,5e-6 --json
  run valve_text valve "$src/cases/annular_valve.toml" --current 0,1 --flow 1e-6,5e-6
  run transient transient "$src/cases/annular_valve.toml" --current 1 --duration 0.02 --steps 10 --json
  run transient_text transient "$src/cases/annular_valve.toml" --voltage 12 --duration 0.02 --steps 10
  run damper damper "$src/cases/damper_paper004.toml" --current 0,1 --velocity 0.05,0.1 --json
  run damper_text damper "$src/cases/damper_paper004.toml" --current 0,1 --velocity 0.05,0.1
  run brake brake "$src/cases/rotary_damper_paper002.toml" --current 0,1 --speed 1,5 --json
  run brake_text brake "$src/cases/rotary_damper_paper002.toml" --current 0,1 --speed 1,5
  run flow flow --kind annular --r-in 0.01 --r-out 0.0108 --length 0.02 --tau-y 30e3 \
    --viscosity 0.1 --flow 5e-6 --json
  run flow_text flow --kind slit --width 0.05 --gap 1e-3 --length 0.02 --tau-y 30e3 \
    --viscosity 0.1 --flow 5e-6 --wall-velocity 0.05
  run shear shear --kind drum --r-in 0.03 --r-out 0.031 --length 0.02 --tau-y 30e3 \
    --viscosity 0.1 --speed 10 --json
  # The two flow commands above stop at option parsing (no --gap); these reach the gap laws.
  run flow_annular_json flow --kind annular --gap 1e-3 --length 0.01 --radius 0.0195 \
    --tau-y 20000 --viscosity 0.106 --flow 1e-6 --json
  run flow_annular_text flow --kind annular --gap 1e-3 --length 0.01 --radius 0.0195 \
    --tau-y 20000 --viscosity 0.106 --flow 1e-6 --model approx
  run flow_slit_json flow --kind slit --gap 1e-3 --width 0.05 --length 0.02 --tau-y 30e3 \
    --viscosity 0.1 --flow 1e-7 --wall-velocity 0.1 --json
  run flow_slit_text flow --kind slit --gap 1e-3 --width 0.05 --length 0.02 --tau-y 30e3 \
    --viscosity 0.1 --flow 1e-7 --wall-velocity 0.1
  run flow_radial_text flow --kind radial --gap 0.5e-3 --r-in 0.005 --r-out 0.02 --tau-y 3e4 \
    --viscosity 0.11 --flow 2e-5
  run shear_disc_text shear --kind disc --r-in 0.01 --r-out 0.05 --gap 1e-3 --faces 2 \
    --tau-y 3e4 --viscosity 0.1 --speed -50
  run solve_point solve "$src/cases/annular_valve.toml" --current 1 --point 0.019,0,0.015,0.005 \
    --sweep 0,1
  run solve_point_json solve "$src/cases/annular_valve.toml" --current 1 --point 0.019,0 --json
  run mesh_text mesh "$src/cases/annular_valve.toml" --vtk OUT/mesh.vtu
  run export export "$src/cases/annular_valve.toml" --fem OUT/valve.fem
  run valve_wire valve "$src/cases/annular_valve.toml" --current 0.5,1 --flow 1e-6 \
    --wire "AWG 26" --temperature 60
  run valve_nowire_json valve "$src/cases/radial_valve.toml" --current 1 --flow 1e-6 --json
  run transient_series transient "$src/cases/annular_valve.toml" --voltage 12 --duration 0.01 \
    --steps 4 --vtk-series OUT/series --quiet
  run damper_piston damper "$src/cases/damper_piston.toml" --current 0.5 --velocity -0.1,0.1
  run brake_drum brake "$src/cases/brake_drum.toml" --current 1 --speed 0,10 --json
fi
if in_group study; then
  run sweep sweep "$src/cases/sweeps/annular_gap_current.toml" --jobs 1 --out OUT/sweep
  run optimise optimise "$src/cases/optimise_annular.toml" --out OUT/opt --json --quiet
fi
if in_group ident; then
  run fit_bingham fit "$data/mrdamper/mrdamper.csv" --model bingham --json --quiet
  run fit_arx fit "$data/mrdamper/mrdamper.csv" --model arx --train 0:3000 --validate 3000:5000 \
    --plot OUT/fit.png --quiet
  run fit_damper fit "$data/utfsm/10mm1Hz0x5A.csv" --model damper --json --quiet
  run fit_family fit-family "$data/utfsm/10mm1Hz0A.csv" "$data/utfsm/10mm1Hz0x5A.csv" \
    "$data/utfsm/10mm1Hz1A.csv" --model bingham --predict "$data/utfsm/10mm1Hz0x25A.csv" \
    --report OUT/report --json --quiet
  run simulate simulate "$data/mrdamper/mrdamper.toml" --input "$data/mrdamper/mrdamper.csv" \
    --out OUT/sim.csv
  # Text reports of fit / fit-family, a validation recording, and a rig whose valve map and field
  # lag come from an FE case (coupling/).
  run fit_bingham_text fit "$data/mrdamper/mrdamper.csv" --model bingham --quiet
  run fit_arx_validate_file fit "$data/utfsm/10mm1Hz0A.csv" --model arx:2,2,1 \
    --validate "$data/utfsm/10mm1Hz0x5A.csv"
  run fit_family_text fit-family "$data/utfsm/10mm1Hz0A.csv" "$data/utfsm/10mm1Hz1A.csv" \
    --model bingham --predict "$data/utfsm/10mm1Hz0x5A.csv" --quiet
  run simulate_chain simulate "$src/cases/rigs/constant_velocity_pump_chain.toml" \
    --signal velocity=constant:value=0.01 --signal current=steps:levels=0/0.5/1,period=0.2 \
    --duration 0.6 --rate 200 --out OUT/chain.csv
fi
if in_group diagnose; then
  run diagnose diagnose "$data/mrdamper/mrdamper.csv" --meta "$src/tests/data/diagnosis/mrdamper.toml" \
    --samples 0:3000 --out OUT/diag --json --quiet
  "$old" fit "$data/mrdamper/mrdamper.csv" --model bingham --json --quiet >"$work/model.json" 2>/dev/null
  run diagnose_baseline diagnose "$data/mrdamper/mrdamper.csv" --baseline "$work/model.json" \
    --samples 0:3000 --out OUT/diagb --json --quiet
  # Whole real recordings (each under a minute on an idle machine): the constant-field damper,
  # a current-driven damper, and a fitted damper model as the baseline.
  run diagnose_mrdamper diagnose "$data/mrdamper/mrdamper.csv" \
    --meta "$src/tests/data/diagnosis/mrdamper.toml" --out OUT/diag --json --quiet
  run diagnose_utfsm diagnose "$data/utfsm/10mm1Hz0x5A.csv" \
    --meta "$src/tests/data/diagnosis/utfsm_damper.toml" --json --quiet
  "$old" fit "$data/utfsm/10mm1Hz0x5A.csv" --model damper --json --quiet >"$work/damper.json" \
    2>/dev/null
  run diagnose_baseline_damper diagnose "$data/utfsm/10mm1Hz0x5A.csv" \
    --meta "$src/tests/data/diagnosis/utfsm_damper.toml" --baseline "$work/damper.json" --json --quiet
fi

echo "$failures command(s) differ"
[ "$failures" -eq 0 ]
