#!/bin/bash
# Re-runs the bad-input classes of docs/bad-input.md against a built rheomag: prints each class,
# the exit code it should end in, the one it ended in and the first stderr line. The full-disk
# class needs root (a 16 KiB tmpfs) and is skipped otherwise.
# Usage: scripts/bad-input-classes.sh build/app/rheomag .
set -u
B=$(realpath "${1:-build/app/rheomag}"); S=$(realpath "${2:-.}"); D=$(mktemp -d); cd "$D"
MISMATCHES=0
run() { local name=$1 want=$2; shift 2; "$@" >out.txt 2>err.txt; local rc=$?
  [ "$rc" = "$want" ] || MISMATCHES=$((MISMATCHES + 1))
  printf '%-42s want %s got %s  %s\n' "$name" "$want" "$rc" "$(head -c 230 err.txt | head -1)"; }
py() { python3 -c "$1"; }
py "
import math
def rec(stem, side, force):
  with open(stem+'.csv','w') as f:
    f.write('t,velocity,force\n')
    for k in range(400): f.write(f'{k*0.005},{0.05*math.sin(0.1*k)},{force(k)}\n')
  open(stem+'.toml','w').write(side)
side='[recording]\ndrive = [\"velocity\"]\noutput = \"force\"\n[rig]\nkind = \"damper\"\npiston_area = AREA\nchamber_volume = VOL\n[valve]\nyield_current = [0.0, 1.0]\nyield_pressure = [0.0, 6.0e4]\nviscous_resistance = VR\n'
def s(a='1.0e-3', v='2.0e-5', r='1.3e8'): return side.replace('AREA',a).replace('VOL',v).replace('VR',r)
sine=lambda k: 400*math.tanh(math.sin(0.1*k)/0.3)
rec('flat', s(), lambda k: 5.0)
rec('zero', s('0.0'), sine); rec('neg', s('-1e-3'), sine); rec('absurd', s('1.0e300'), sine)
rec('negvol', s(v='-2e-5'), sine); rec('negvr', s(r='-1.3e8'), sine); rec('ok', s(), sine)
rec('big', s(), lambda k: 1e200*math.sin(0.1*k))
rec('selfdrive', s().replace('drive = [\"velocity\"]', 'drive = [\"velocity\", \"force\"]'), sine)
rec('nearflat', s(), lambda k: 5.0 + 1e-13*(k%2))
open('bom.csv','w',encoding='utf-8-sig').write(open('ok.csv').read()); open('bom.toml','w').write(s())
open('semi.csv','w').write(open('ok.csv').read().replace(',',';')); open('semi.toml','w').write(s())
open('typo.csv','w').write(open('ok.csv').read()); open('typo.toml','w').write(s().replace('piston_area','piston_aera'))
"
C=$S/cases/annular_valve.toml
sed 's/^turns = .*/turns = 600.5/' $C > turns.toml
sed 's/^fluid_material = .*/fluid_material = "AISI 1010"/' $C > steel.toml
grep -q outer_radius_factor $C && sed 's/^outer_radius_factor = .*/outer_radius_factor = 1e9/' $C > orf.toml || { cp $C orf.toml; printf '\n' >> orf.toml; }
run "narx of a constant output"               2 $B fit flat.csv --model narx:2,2,1
run "constant output, bingham"                2 $B fit flat.csv --model bingham
run "zero piston area (diagnose)"             2 $B diagnose zero.csv --quiet
run "negative piston area (diagnose)"         2 $B diagnose neg.csv --quiet
run "negative chamber volume"                 2 $B diagnose negvol.csv --quiet
run "negative viscous resistance"             2 $B diagnose negvr.csv --quiet
run "piston area 1e300"                       2 $B diagnose absurd.csv --quiet
echo "   stderr lines of the 1e300 run: $(wc -l < err.txt)"
run "force 1e200 refused at its line (bingham)" 2 $B fit big.csv --model bingham
run "force 1e200 refused at its line (arx)"     2 $B fit big.csv --model arx:2,2,1 --json
echo "   stdout bytes of that run: $(wc -c < out.txt)"
run "flow --length 1e300 (dp = inf)"          3 $B flow --kind annular --gap 1e-3 --length 1e300 --radius 0.01 --tau-y 1e5 --viscosity 1 --flow 1e-5
run "turns = 600.5"                           2 $B solve turns.toml
run "steel fluid_material"                    2 $B solve steel.toml
run "outer_radius_factor 1e9"                 2 $B mesh orf.toml
run "CSV with UTF-8 BOM (valid)"              0 $B fit bom.csv --model arx:2,2,1
run "semicolon CSV"                           2 $B fit semi.csv --model arx:2,2,1
run "misspelt sidecar key"                    2 $B fit typo.csv --model arx:2,2,1
run "--vtk ''"                                2 $B mesh $C --vtk ''
mkfifo node.vtu
run "--vtk onto a FIFO (non-regular)"         2 $B mesh $C --vtk node.vtu
[ -p node.vtu ] && echo "   node.vtu still a FIFO"
run "--vtk /dev/null"                         2 $B mesh $C --vtk /dev/null
[ -c /dev/null ] && echo "   /dev/null still a character device"
run "simulate --out into a missing folder"    2 $B simulate $S/cases/rigs/bypass_cylinder.toml --signal displacement=sine:amplitude=0.025,frequency=0.75 --signal current=constant:value=1 --duration 1 --out nowhere/rec.csv
run "diagnose --out onto a file"              2 $B diagnose ok.csv --quiet --out ok.csv
echo "   temporaries left: $(ls -a | grep -c '\.tmp')"
printf '\xEF\xBB\xBF' | cat - $S/tests/data/pot_core.fem > bom.fem
run ".fem with a UTF-8 BOM (valid)"           0 $B mesh bom.fem
sed 's/^turns = .*/turns = 1e15/' $C > manyturns.toml
run "turns = 1e15"                            2 $B solve manyturns.toml
printf '[sweep]\nbase = "%s"\n[[axis]]\nkey = "circuit.99999999999999999999.current"\nvalues = [1.0]\n' "$C" > idx.toml
run "sweep key index of 20 digits"            2 $B sweep idx.toml -q -o sweep_out
run "output among the drives"                 2 $B fit selfdrive.csv --model arx:2,2,1
run "output constant but for 1e-13"           2 $B fit nearflat.csv --model arx:2,2,1
run "empty option value (valve --wire '')"    2 $B valve $C --wire ''
run "empty option value (diagnose --out '')"  2 $B diagnose ok.csv --quiet --out ''
run "--vtk into a missing folder"             2 $B mesh $C --vtk nowhere/field.vtu
run "solve --current 1e300 (source overflow)" 3 $B solve $S/tests/data/pot_core_equivalent.toml --current 1e300
run "transient step to the same current"      2 $B transient $S/tests/data/pot_core_equivalent.toml --current 1 --from 1 --duration 0.01 --quiet
run "valve --temperature -250 (below copper)" 2 $B valve $C --temperature -250
$B fit ok.csv --model bingham --json > model.json 2>/dev/null
for edit in "viscous=-1e308" "transition=-0.1" "output_smoothing=5"; do
  py "
import json; k, v = '$edit'.split('='); j = json.load(open('model.json'))
for p in j['parameters']:
  if p['name'] == k: p['value'] = float(v)
json.dump(j, open('bad_model.json', 'w'))"
  run "model JSON $edit"                     2 $B simulate bad_model.json --input ok.csv --out sim.csv
done
run "sweep -j -1 (range named readably)"   2 $B sweep idx.toml -j -1
[ "$(wc -c < err.txt)" -lt 200 ] && echo "   message under 200 bytes"
mkdir -p esc_out esc_elsewhere; ln -sfn ../esc_elsewhere esc_out/link
for csv in "$D/abs.csv" "../x.csv" "link/x.csv"; do
  printf '[sweep]\nbase = "%s"\n[[axis]]\nkey = "circuit.0.current"\nvalues = [1.0]\n[output]\ncsv = "%s"\nvtu = true\n' "$C" "$csv" > esc.toml
  run "sweep [output] csv = $csv"           2 $B sweep esc.toml -q -o esc_out
done
echo "   files written outside --out: $(ls esc_elsewhere | wc -l) $(ls abs.csv ../x.csv 2>/dev/null | wc -l)"
cp ok.csv dup.csv; cp ok.toml dup.toml
run "fit-family, one recording twice"       2 $B fit-family ok.csv ./ok.csv --model bingham --quiet
run "fit-family, a copy of a recording"     2 $B fit-family ok.csv dup.csv --model bingham --quiet
ln -sf /dev/zero zero.fem
run "solve of a .fem link to /dev/zero"       2 $B solve zero.fem
run "sweep /dev/zero"                         2 $B sweep /dev/zero -q -o sweep_out
run "diagnose --meta /dev/zero"               2 $B diagnose ok.csv --quiet --meta /dev/zero
mkfifo fifo.toml
run "solve of a FIFO without a writer"        2 timeout 10 $B solve fifo.toml
cp $S/tests/data/magnetostatics3d/small_valve.toml holed.toml
printf '\n[[feature]]\nkind = "hole"\nregion = "air"\nradius = 1.0\nposition = 20.0\nangle = 30\n' >> holed.toml
run "3D mesh beyond the memory limit"         2 $B solve holed.toml --3d --full --mesher swept --max-memory 16G
printf '\n[[feature]]\nkind = "hole"\nregion = "air"\nradius = 6.0\nposition = 20.0\nangle = 30\n' > hole6.part
sed '/^\[\[feature\]\]/,$d' holed.toml > big3d.toml; cat hole6.part >> big3d.toml
$B solve big3d.toml --3d --full --mesher swept >out.txt 2>err.txt & P=$!
for k in $(seq 100); do grep -q "3d: solve" err.txt && break; sleep 0.1; done; sleep 4; kill -TERM $P; wait $P
rc=$?; [ "$rc" = 143 ] || MISMATCHES=$((MISMATCHES + 1))
printf '%-42s want %s got %s  %s\n' "SIGTERM during a 3D factorisation" 143 "$rc" "$(tail -1 err.txt | head -c 150)"
run "2D mesh beyond --max-memory"            2 $B solve $C --max-memory 8M
run "3D case under ulimit -v 3 GB"            2 bash -c "ulimit -v 3000000; exec $B solve holed.toml --3d --full --mesher swept"
sed -e 's/^name = "coil"$/name = "co\\nil"/' -e 's/circuit = "coil"/circuit = "co\\nil"/' $S/tests/data/pot_core_equivalent.toml > newline_name.toml
run "export of a circuit name with a line break" 2 $B export newline_name.toml --fem newline_name.fem
[ -e newline_name.fem ] && echo "   a .fem was written"
py "
import math
with open('long.csv','w') as f:
  f.write('t,velocity,force\n')
  for k in range(1000000):
    v = 0.05*math.sin(2*math.pi*2*k*1e-4); f.write(f'{k*1e-4:.6f},{v:.6g},{400*math.tanh(v/0.01)+2000*v:.6g}\n')
open('long.toml','w').write('[recording]\ndrive = [\"velocity\"]\noutput = \"force\"\n[rig]\nkind = \"damper\"\n')
"
run "fit of 10^6 rows under ulimit -v 3 GB"   0 bash -c "ulimit -v 3000000; exec $B fit long.csv --model bingham"
grep -m1 "samples:" out.txt | sed 's/^/   /'
mkdir -p full
if mount -t tmpfs -o size=16k tmpfs full 2>/dev/null; then
  echo old > full/rec.csv; echo old > full/rec.toml
  head -c 12000 /dev/zero > full/fill; echo old > full/field.vtu
  run "--vtk on a full disk"                  2 $B mesh $C --vtk full/field.vtu
  echo "   old file kept: $(cat full/field.vtu); temporaries left: $(ls -a full | grep -c '\.tmp')"
  run "simulate --out on a full disk"         2 $B simulate $S/cases/rigs/bypass_cylinder.toml --signal displacement=sine:amplitude=0.025,frequency=0.75 --signal current=constant:value=1 --duration 1 --out full/rec.csv
  echo "   old pair kept: $(cat full/rec.csv) $(cat full/rec.toml); temporaries left: $(ls -a full | grep -c '\.tmp\|staging')"
  umount full
else echo "   (no tmpfs mount here: full-disk class not run)"; fi
cd /; rm -rf "$D"
echo "classes whose exit code differs from the expected one: $MISMATCHES"
[ "$MISMATCHES" = 0 ]
