#!/usr/bin/env bash
# Place and route of rtl/specular_unit on an iCE40 with nextpnr-ice40, to measure the
# clock frequency (SPEC section 8, "clock frequency after place and route").
#
#   scripts/synth_pnr.sh ROMGEN [COS_ADDR_BITS] [OUT_DIR]
#
# ROMGEN is the built romgen tool (build/bin/romgen). The default configuration
# (CosAddrBits = 12: 4 banks x 4096 x 16 bits = 256 Kbit of ROM 12, 69 SB_RAM40_4K) does
# not fit any iCE40 (the HX8K has 32 block RAMs), so this script regenerates ROM 12 with
# fewer address bits (default 10: 16 + 5 block RAMs) into OUT_DIR and overrides the
# CosAddrBits / CosRomFile parameters; the logic, and so the critical path, is otherwise
# the default one. Target: iCE40-HX8K, package ct256. Prints LUTs, FFs, BRAMs and the
# maximum frequency nextpnr reports.
set -euo pipefail

romgen=${1:-}
bits=${2:-10}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=${3:-$(mktemp -d)}

if [ -z "$romgen" ] || [ ! -x "$romgen" ]; then
  echo "usage: $0 ROMGEN [COS_ADDR_BITS] [OUT_DIR]: ROMGEN must be the built romgen tool (got '${romgen}')" >&2
  exit 2
fi
if ! [[ "$bits" =~ ^[0-9]+$ ]] || [ "$bits" -lt 4 ] || [ "$bits" -gt 12 ]; then
  echo "$0: COS_ADDR_BITS must be an integer in [4, 12] (got '${bits}')" >&2
  exit 2
fi

mkdir -p "$out"
out=$(cd "$out" && pwd)
"$romgen" --out-dir "$out/roms" --cos-addr-bits "$bits" --quiet
cos_rom=$(ls "$out"/roms/cos_k_*.hex | head -n 1)

cd "$root"
sources=(rtl/*.sv)
cat > "$out/pnr.ys" <<YS
read_verilog -sv ${sources[*]}
chparam -set CosAddrBits ${bits} -set CosRomFile "${cos_rom}" specular_unit
synth_ice40 -top specular_unit -json ${out}/specular_unit.json
tee -q -o ${out}/stat.txt stat
YS
yosys -q -l "$out/yosys.log" -s "$out/pnr.ys" > /dev/null
# nextpnr exits non-zero when the target frequency is missed; the report is what we want.
nextpnr-ice40 --hx8k --package ct256 --json "$out/specular_unit.json" --freq 25 \
  --pcf-allow-unconstrained --seed 1 > "$out/nextpnr.log" 2>&1 || true

luts=$(awk '$1=="SB_LUT4"{s+=$2} END{print s+0}' "$out/stat.txt")
ffs=$(awk '$1 ~ /^SB_DFF/{s+=$2} END{print s+0}' "$out/stat.txt")
brams=$(awk '$1 ~ /^SB_RAM40_4K/{s+=$2} END{print s+0}' "$out/stat.txt")
fmax=$(grep -o "Max frequency for clock[^:]*: [0-9.]* MHz" "$out/nextpnr.log" | tail -n 1 | grep -o "[0-9.]* MHz" || true)
if [ -z "$fmax" ]; then
  echo "$0: nextpnr did not report a frequency; see $out/nextpnr.log" >&2
  tail -n 20 "$out/nextpnr.log" >&2
  exit 1
fi
echo "iCE40-HX8K, CosAddrBits=${bits}: LUT4 ${luts}, FF ${ffs}, SB_RAM40_4K ${brams}, Fmax ${fmax}"
