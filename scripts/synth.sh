#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# Yosys synthesis check of a top of the core, specular_unit by default (run by ctest as
# rtl_yosys_synth, rtl_yosys_ice40 and rtl_yosys_ice40_{stream,axis,axil}, and by `make lint`).
#
#   scripts/synth.sh generic|ice40 [OUT_DIR]
#
# Reads the sources of rtl/specular.f with Yosys' SystemVerilog frontend, elaborates the top with
# its default parameters (ROM hex files relative to the repository root, so this runs
# from there), fails on any error, on any inferred latch (checked right after `proc`, and
# again on the mapped netlist) and on `check -assert` problems (undriven or multiply
# driven nets, combinational loops), then prints the cell counts.
# SYNTH_COEF_ROM / SYNTH_COS_ROM override the ROM files (paths relative to the root);
# SYNTH_TOP picks the top module (default specular_unit; specular_stream, specular_axis,
# specular_axil for the others).
set -euo pipefail

mode=${1:-}
top=${SYNTH_TOP:-specular_unit}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=${2:-$(mktemp -d)}

case "$mode" in
  generic) synth_cmd="synth -top ${top} -flatten"
           latch_cells='t:$_DLATCH* t:$_SR_* t:$dlatch* t:$adlatch' ;;
  ice40)   synth_cmd="synth_ice40 -top ${top}"
           latch_cells='t:$_DLATCH* t:$dlatch* t:$adlatch' ;;
  *) echo "usage: $0 generic|ice40 [OUT_DIR] (got mode '${mode}')" >&2; exit 2 ;;
esac

cd "$root"
mkdir -p "$out"
# The sources in compile order and the include directories: rtl/specular.f (rtl/README.md).
# shellcheck source=scripts/rtl_filelist.sh
source scripts/rtl_filelist.sh
rtl_filelist || exit 1
sources=("${RTL_SOURCES[@]}")
incflags=""
for d in "${RTL_INCDIRS[@]+"${RTL_INCDIRS[@]}"}"; do incflags+=" -I$d"; done

chparam=""
if [ -n "${SYNTH_COEF_ROM:-}" ]; then
  chparam+="chparam -set CoefRomFile \"${SYNTH_COEF_ROM}\" ${top}"$'\n'
fi
if [ -n "${SYNTH_COS_ROM:-}" ]; then
  chparam+="chparam -set CosRomFile \"${SYNTH_COS_ROM}\" ${top}"$'\n'
fi

suffix=""
[ "$top" = specular_unit ] || suffix="_${top}"
script="$out/synth_${mode}${suffix}.ys"
log="$out/synth_${mode}${suffix}.log"
stat="$out/stat_${mode}${suffix}.txt"
cat > "$script" <<YS
read_verilog -sv${incflags} ${sources[*]}
${chparam}hierarchy -check -top ${top}
proc
select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr
${synth_cmd}
select -assert-none ${latch_cells}
check -assert
tee -q -o ${stat} stat
YS

if ! yosys -q -l "$log" -s "$script" > /dev/null; then
  echo "synth.sh ($mode): Yosys failed; last lines of $log:" >&2
  tail -n 30 "$log" >&2
  exit 1
fi
if grep -q "Latch inferred" "$log"; then
  echo "synth.sh ($mode): latch inferred:" >&2
  grep "Latch inferred" "$log" >&2
  exit 1
fi

echo "synth.sh ($mode, $top): OK, no latches; netlist statistics ($stat):"
sed -n '/Number of cells/,$p' "$stat"
if [ "$mode" = ice40 ]; then
  luts=$(awk '$1=="SB_LUT4"{s+=$2} END{print s+0}' "$stat")
  ffs=$(awk '$1 ~ /^SB_DFF/{s+=$2} END{print s+0}' "$stat")
  brams=$(awk '$1 ~ /^SB_RAM40_4K/{s+=$2} END{print s+0}' "$stat")
  carries=$(awk '$1=="SB_CARRY"{s+=$2} END{print s+0}' "$stat")
  echo "ice40 summary: LUT4 ${luts}, FF ${ffs}, SB_RAM40_4K ${brams}, SB_CARRY ${carries}"
else
  cells=$(awk '/Number of cells/{n=$4} END{print n+0}' "$stat")
  echo "generic summary: ${cells} cells"
fi
