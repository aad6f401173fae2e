#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# Yosys synthesis counts of phong_stream, the per-pixel Blinn-Phong competitor
# (docs/phong_hw.md#cost), in one of its configurations (roms/phong/phong_configs.cmake):
#
#   scripts/phong_synth.sh CONFIG ice40|ice40-dsp|ecp5 [OUT_DIR]
#
#   ice40      synth_ice40 (LUT multipliers, as the HX8K build of the device)
#   ice40-dsp  synth_ice40 -dsp (SB_MAC16 multipliers, as the UP5K build)
#   ecp5       synth_ecp5 (MULT18X18D multipliers)
# Synthesis only: the counts are Yosys' cells before placement (no packing, no Fmax).
# Prints one line "phong_synth CONFIG MODE: ..." with the cell counts; exit 2 on bad
# arguments, 1 when Yosys fails.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cfg=${1:-}
mode=${2:-}
out=${3:-$(mktemp -d)}
case "$mode" in
  ice40)     synth_cmd="synth_ice40 -top phong_stream" ;;
  ice40-dsp) synth_cmd="synth_ice40 -dsp -top phong_stream" ;;
  ecp5)      synth_cmd="synth_ecp5 -top phong_stream" ;;
  *) echo "usage: $0 CONFIG ice40|ice40-dsp|ecp5 [OUT_DIR] (got mode '${mode}')" >&2; exit 2 ;;
esac
cd "$root"
cmake_cfg=roms/phong/phong_configs.cmake
line=$(grep "^set(PHONG_CONFIG_${cfg}_RTL_ARGS " "$cmake_cfg" || true)
if [ -z "$cfg" ] || [ -z "$line" ]; then
  echo "$0: unknown configuration '${cfg}'; the configurations: $(sed -n 's/^set(PHONG_CONFIGS \(.*\))$/\1/p' "$cmake_cfg")" >&2
  exit 2
fi
# "-GName=Value" -> chparam -set Name Value phong_stream (strings keep their quotes).
chparam=""
while read -r arg; do
  name=${arg%%=*}
  name=${name#-G}
  value=${arg#*=}
  value=${value//\\\"/\"}
  chparam+="chparam -set ${name} ${value} phong_stream"$'\n'
done < <(echo "$line" | grep -o '"-G[^ ]*"' | sed 's/^"//; s/"$//')

# shellcheck source=scripts/rtl_filelist.sh
source scripts/rtl_filelist.sh
rtl_filelist rtl/competitors/phong/phong.f || exit 1
incflags=""
for d in "${RTL_INCDIRS[@]+"${RTL_INCDIRS[@]}"}"; do incflags+=" -I$d"; done
mkdir -p "$out"
script="$out/phong_${cfg}_${mode}.ys"
log="$out/phong_${cfg}_${mode}.log"
stat="$out/phong_${cfg}_${mode}.txt"
cat > "$script" <<YS
read_verilog -sv${incflags} ${RTL_SOURCES[*]}
${chparam}hierarchy -check -top phong_stream
${synth_cmd}
tee -q -o ${stat} stat
YS
if ! yosys -q -l "$log" -s "$script" > /dev/null; then
  echo "phong_synth.sh: Yosys failed; last lines of $log:" >&2
  tail -n 30 "$log" >&2
  exit 1
fi
sum() { awk -v re="$1" '$1 ~ re {s+=$2} END{print s+0}' "$stat"; }
case "$mode" in
  ice40|ice40-dsp)
    echo "phong_synth ${cfg} ${mode}: SB_LUT4 $(sum '^SB_LUT4$') SB_CARRY $(sum '^SB_CARRY$') SB_DFF* $(sum '^SB_DFF')" \
         "SB_RAM40_4K $(sum '^SB_RAM40_4K') SB_MAC16 $(sum '^SB_MAC16$')" ;;
  ecp5)
    echo "phong_synth ${cfg} ${mode}: LUT4 $(sum '^LUT4$') CCU2C $(sum '^CCU2C$') TRELLIS_FF $(sum '^TRELLIS_FF$')" \
         "DP16KD $(sum '^DP16KD$') MULT18X18D $(sum '^MULT18X18D$')" ;;
esac
