#!/usr/bin/env bash
# Yosys smoke run (part of `make lint`): ROM 9 and ROM 12 must be inferred as iCE40 block RAM
# (SB_RAM40_4K), not as LUTs (a LUT ROM of this size would take thousands; the cascade mux of
# ROM 12 takes under a hundred), and spec_unit must synthesize with synth_ice40.
# Usage: syn/ice40_smoke.sh OUTDIR        (run from the repository root)
set -euo pipefail
out=${1:-build/syn}
mkdir -p "$out"
YOSYS=${YOSYS:-yosys}

count() {  # count CELL LOG: the number of CELL cells in the last stat of LOG
    awk -v c="$1" '$1 == c {n = $2} END {print n + 0}' "$2"
}

check_rom() {  # check_rom MODULE FILES... : synthesize MODULE alone
    local top=$1 file=$2; shift 2
    "$YOSYS" -q -l "$out/$top.log" -p "read_verilog -defer $*; chparam -set INIT_FILE \"$file\" $top;
        synth_ice40 -top $top; tee -o $out/$top.stat stat" >/dev/null
    local bram lut
    bram=$(count SB_RAM40_4K "$out/$top.stat")
    lut=$(count SB_LUT4 "$out/$top.stat")
    printf '  %-12s SB_RAM40_4K %3d   SB_LUT4 %4d\n' "$top" "$bram" "$lut"
    if [ "$bram" -lt 1 ] || [ "$lut" -gt 512 ]; then
        echo "ice40_smoke: $top was not mapped to block RAM (see $out/$top.log)" >&2
        exit 1
    fi
}

echo "yosys synth_ice40 smoke run:"
# Yosys skips the RTL's image checks (SYNTHESIS): the images must fit the default parameters
python3 syn/rom_check.py --header rom/spec_params.vh --rom9 rom/rom9_scale.hex --rom12 rom/rom12_cosk.hex
check_rom spec_rom9 rom/rom9_scale.hex rtl/spec_rom.v rtl/spec_rom9.v
check_rom spec_rom12 rom/rom12_cosk.hex rtl/spec_rom.v rtl/spec_rom12.v
"$YOSYS" -q -l "$out/spec_unit.log" -p "read_verilog -defer -Irom $(sed 's|^|rtl/|' rtl/spec_core.f | tr '\n' ' ');
    synth_ice40 -top spec_unit; tee -o $out/spec_unit.stat stat" >/dev/null
printf '  %-12s SB_RAM40_4K %3d   SB_LUT4 %4d   flip-flops %d\n' spec_unit \
    "$(count SB_RAM40_4K "$out/spec_unit.stat")" "$(count SB_LUT4 "$out/spec_unit.stat")" \
    "$(grep -E '^ +SB_DFF' "$out/spec_unit.stat" | awk '{s += $2} END {print s + 0}')"
[ "$(count SB_RAM40_4K "$out/spec_unit.stat")" -ge 2 ] || { echo "ice40_smoke: spec_unit has no block RAM" >&2; exit 1; }
