#!/usr/bin/env bash
# make fusesoc: the FuseSoC core (ua71489_spec.core) tried through FuseSoC's own flows, when FuseSoC is
# installed (pip install fusesoc): Verilator lint, Icarus simulation against the bit-exact model's
# vectors, and the iCE40 UP5K synthesis of spec_stream in its UP5K configuration.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD:-$root/build}
case "$build" in /*) ;; *) build=$root/$build ;; esac
if ! command -v fusesoc >/dev/null 2>&1; then
    echo "fusesoc: not installed (pip install fusesoc); skipped"
    exit 0
fi
work=$build/fusesoc
rm -rf "$work"
mkdir -p "$work"
cd "$work"
core=ua71489:shading:spec_core
"$build/specsim" vectors --out "$work/vectors.hex" --spans 300 --seed 11
"$build/specrom" --config up5k --out "$work/rom_up5k"
echo "fusesoc: lint (Verilator)"
fusesoc --cores-root "$root" run --target lint $core > lint.log 2>&1 || { tail -20 lint.log; exit 1; }
echo "fusesoc: sim (Icarus, spec_stream with 30 % stalls)"
fusesoc --cores-root "$root" run --target sim $core --vectors="$work/vectors.hex" > sim.log 2>&1 || { tail -20 sim.log; exit 1; }
grep -q PASS sim.log || { echo "fusesoc: the simulation did not report PASS" >&2; exit 1; }
grep PASS sim.log
echo "fusesoc: synth (icestorm flow, UP5K configuration)"
python3 "$root/syn/rom_check.py" --header "$root/rom/spec_params.vh" --rom9 "$work/rom_up5k/rom9_scale.hex" \
    --rom12 "$work/rom_up5k/rom12_cosk.hex" -GTBL_AW=8 -GINTERP=1 -GINTERP_FRAC=10 -GDELTA_W=10 -GSCALE_W=16 \
    -GSCALE_FRAC=13
fusesoc --cores-root "$root" run --target synth $core --ROM9_FILE="$work/rom_up5k/rom9_scale.hex" \
    --ROM12_FILE="$work/rom_up5k/rom12_cosk.hex" > synth.log 2>&1 || { tail -20 synth.log; exit 1; }
grep -E "ICESTORM_(LC|RAM|DSP):|Max frequency" synth.log | tail -4
echo "fusesoc: logs in $work"
