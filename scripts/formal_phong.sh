#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# Formal proof of phong_stream's handshakes (harness, properties and reduced widths in
# rtl/competitors/phong/formal/phong_stream_fv.sv; overview, depths and run times in
# docs/formal.md#phong_stream-the-span-and-pixel-handshakes). Run by ctest as
# rtl_formal_phong* (tests/rtl/CMakeLists.txt).
#
#   scripts/formal_phong.sh [--bounded | --mutant NAME] [OUT_DIR]
#
# Flow: Yosys reads the sources of rtl/specular.f and the harness with -formal, flattens,
# checks that geo_ready_o has no combinational path from geo_valid_i or px_ready_i
# (registers only, docs/interfaces.md#geometry-span-interface), connects the harness's
# probe wires to the core's control state, cuts the pixel value where it leaves the power
# unit (cutpoint u_dut.intensity: a free value every clock), maps the cells to single bits
# (simplemap) so that opt_clean drops every register bit and gate left without a reader (the
# span setup's multipliers, the accumulators, phong_dot, phong_norm, phong_pow), maps the
# asynchronous reset for the solver (async2sync) and proves with ABC on the model's AIGER
# (scripts/formal_abc.sh): a base case from reset (bmc3, FORMAL_BASE = 4 cycles) and a
# FORMAL_K = 1 step induction (scorr -o, one SAT call per property). A pass is an
# unbounded proof. Exit status 0 when proven, 1 otherwise.
#
# --bounded: the properties alone (FV_PROPERTIES_ONLY, no invariants) checked by a bounded
# model check from reset over FORMAL_DEPTH cycles (default Latency + 6: a span accepted in
# the first cycle after reset has its pixel 0 on the output at cycle Latency + 1), with
# ABC's bmc3 on the AIGER of the model. A bounded result, not a proof. Exit 0 when no
# property fails.
#
# --mutant NAME copies the files of rtl/specular.f into OUT_DIR, applies one mutation to the
# copy of rtl/competitors/phong/phong_stream.sv (never to rtl/), leaves out the invariants and runs a bounded
# check over FORMAL_DEPTH cycles (default Latency + 12; the datapath cut as above); exit 0
# only if the register-only check of geo_ready_o or bmc3 catches it. Mutations (one line
# each):
#   valid_drops        the output buffer sees px_ready_i = 1: px_valid_o drops without a
#                      transfer (P1)
#   span_one_long      the pixel counter loads l + 1: a span gives l + 2 pixels, px_last_o
#                      on the wrong pixel (P3)
#   head_overrun       the span pipe moves while its head waits for the control: a span is
#                      overwritten and lost (P3)
#   tag_line_short     the tag line one register short: a pixel carries the tag of the
#                      pixel behind it (P3)
#   ready_waits_valid  geo_ready_o = sp_adv & geo_valid_i: a combinational path from
#                      geo_valid_i (the register-only check)
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
me=formal_phong.sh
mutant=""
bounded=""
if [ "${1:-}" = "--bounded" ]; then
  bounded=1
  shift
elif [ "${1:-}" = "--mutant" ]; then
  mutant=${2:?"--mutant needs a name"}
  shift 2
fi
out=${1:-$(mktemp -d)}
kind=${FORMAL_K:-1}

cd "$root"
mkdir -p "$out"
out=$(cd "$out" && pwd)

# The sources in compile order and the include directories: rtl/specular.f (rtl/README.md).
# shellcheck source=scripts/rtl_filelist.sh
source scripts/rtl_filelist.sh
rtl_filelist rtl/competitors/phong/phong.f || exit 1
sources=("${RTL_SOURCES[@]}")
incflags=""
for d in "${RTL_INCDIRS[@]+"${RTL_INCDIRS[@]}"}"; do incflags+=" -I$d"; done

if [ -n "$mutant" ]; then
  file=rtl/competitors/phong/phong_stream.sv
  case "$mutant" in
    valid_drops)
      sed_expr='s/\.px_ready_i (px_ready_i),/.px_ready_i (1'"'"'b1),/' ;;
    span_one_long)
      sed_expr='s/\.len_i    (len_h),/.len_i    (len_h + 1'"'"'b1),/' ;;
    head_overrun)
      sed_expr='s/assign sp_adv      = ctrl_ready | (adv & ~head_valid);/assign sp_adv      = ctrl_ready | adv;/' ;;
    tag_line_short)
      sed_expr='s/\.Depth (PipeDepth - 1)) u_tag_line/.Depth (PipeDepth - 2)) u_tag_line/' ;;
    ready_waits_valid)
      sed_expr='s/assign geo_ready_o = sp_adv;/assign geo_ready_o = sp_adv \& geo_valid_i;/' ;;
    *) echo "$me: unknown mutant '$mutant'" >&2; exit 2 ;;
  esac
  # The copy keeps the filelist's relative paths under OUT_DIR/rtl_NAME/.
  echo "$me: mutant '$mutant':"
  rtl_mutant_copy "$out/rtl_${mutant}" "$file" "$sed_expr" || exit 1
  sources=("${MUTANT_SOURCES[@]}")
fi

tag=${mutant:-phong}
if [ -n "$bounded" ]; then
  tag=phong_bounded
fi
defines="-DSYNTHESIS"
if [ -n "$mutant" ] || [ -n "$bounded" ]; then
  defines+=" -DFV_PROPERTIES_ONLY"
fi
read_cmd="read_verilog -sv -formal ${defines}${incflags} ${sources[*]} rtl/prim/formal/specular_axis_props.sv rtl/competitors/phong/formal/phong_stream_fv.sv"

# The depths of the harness: the span pipe's valid line (u_setup.vld_q, setup_stages) and
# the control's stage valids (u_control.vld_q, PipeDepth). Latency: from the accept edge to
# pixel 0 on the output, SpDepth + PipeDepth + 1 (the output buffer).
yosys -q -p "
  ${read_cmd}
  hierarchy -check -top phong_stream_fv
  proc
  flatten
  tee -q -o $out/depths_${tag}.txt dump w:u_dut.u_setup.vld_q w:u_dut.u_control.vld_q
" > "$out/elab_${tag}.log" 2>&1 || { cat "$out/elab_${tag}.log" >&2; exit 1; }
sp_depth=$(sed -n 's/^ *wire width \([0-9]*\) .*u_setup.vld_q$/\1/p' "$out/depths_${tag}.txt" | head -1)
depth=$(sed -n 's/^ *wire width \([0-9]*\) .*u_control.vld_q$/\1/p' "$out/depths_${tag}.txt" | head -1)
if [ -z "$sp_depth" ] || [ -z "$depth" ]; then
  echo "$me: no u_dut.u_setup.vld_q or u_dut.u_control.vld_q (RTL changed?)" >&2
  exit 1
fi
latency=$((sp_depth + depth + 1))
# Bounded check: Latency + 6; mutants: Latency + 12 (bmc3 stops at the first failure).
if [ -n "$mutant" ]; then
  bmc_depth=${FORMAL_DEPTH:-$((latency + 12))}
else
  bmc_depth=${FORMAL_DEPTH:-$((latency + 6))}
fi

# Probe wire -> state of the flattened core (see the harness header). The bounded and
# mutant runs have no probes (FV_PROPERTIES_ONLY).
probes=""
if [ -z "$mutant" ] && [ -z "$bounded" ]; then
  probes="
  connect -nounset -set p_sp_vld  u_dut.u_setup.vld_q
  connect -nounset -set p_len1    u_dut.u_setup.len_1
  connect -nounset -set p_tag1    u_dut.u_setup.tag_1
  connect -nounset -set p_len2    u_dut.u_setup.len_2
  connect -nounset -set p_tag2    u_dut.u_setup.tag_2
  connect -nounset -set p_side    u_dut.u_setup.u_side.gen_regs.line_q
  connect -nounset -set p_lenh    u_dut.len_h
  connect -nounset -set p_tagh    u_dut.tag_h
  connect -nounset -set p_vld     u_dut.u_control.vld_q
  connect -nounset -set p_last    u_dut.u_control.last_q
  connect -nounset -set p_cnt     u_dut.u_counter.cnt_q
  connect -nounset -set p_zero    u_dut.u_counter.zero_q
  connect -nounset -set p_tag0    u_dut.tag0
  connect -nounset -set p_tagline u_dut.u_tag_line.gen_regs.line_q
  connect -nounset -set p_count   u_dut.u_out_buf.count_q
  connect -nounset -set p_head    u_dut.u_out_buf.head_q
  connect -nounset -set p_tail    u_dut.u_out_buf.tail_q
  connect -nounset -set p_adv     u_dut.u_out_buf.adv_q
"
fi

# geo_ready_o depends on registers only: no combinational cell path from geo_valid_i or
# px_ready_i into it (%cie*: the input cone over combinational cells).
status=0
yosys -q -l "$out/yosys_${tag}.log" -p "
  ${read_cmd}
  chparam -set SpDepth ${sp_depth} -set Depth ${depth} phong_stream_fv
  hierarchy -check -top phong_stream_fv
  proc
  flatten
  opt_clean
  tee -o $out/ready_cone_${tag}.txt select -list w:geo_ready_o %cie* w:geo_valid_i w:px_ready_i %u %i
  select -assert-none w:geo_ready_o %cie* w:geo_valid_i w:px_ready_i %u %i
  ${probes}
  select -assert-count 1 w:u_dut.intensity
  cutpoint w:u_dut.intensity
  opt_clean
  simplemap
  opt_clean
  tee -o $out/stat_${tag}.txt stat
  async2sync
  dffunmap
  opt -keepdc -fast
  check -assert
  write_rtlil $out/model_${tag}.il
" > "$out/elab_${tag}.log" 2>&1 || status=1
if [ $status -ne 0 ]; then
  if grep -q "Assertion failed: selection is not empty" "$out/yosys_${tag}.log"; then
    echo "$me: geo_ready_o has a combinational path from an input:" >&2
    cat "$out/ready_cone_${tag}.txt" >&2
    if [ -n "$mutant" ]; then
      echo "$me: PASS: mutant '$mutant' is caught (geo_ready_o not from registers only)"
      exit 0
    fi
  fi
  tail -20 "$out/yosys_${tag}.log" >&2
  echo "$me: FAIL: elaboration (logs in $out)" >&2
  exit 1
fi
# The harness declares the core's ports again: a width that differs fails here.
if grep -q "Resizing cell port" "$out/yosys_${tag}.log"; then
  grep "Resizing cell port" "$out/yosys_${tag}.log" | head -5 >&2
  echo "$me: a port of the harness differs in width from the core's (above)" >&2
  exit 1
fi

# shellcheck source=scripts/formal_abc.sh
source scripts/formal_abc.sh
if [ -z "$mutant" ] && [ -z "$bounded" ]; then
  # The unbounded proof with ABC (scripts/formal_abc.sh): base case bmc3 from reset over
  # FORMAL_BASE = 4 cycles, induction step scorr -o, FORMAL_K = 1 step, on the same AIGER.
  echo "$me: ABC proof (span pipe ${sp_depth}, PipeDepth ${depth})"
  formal_abc_export "$me" "$out/model_${tag}.il" "$out/model_${tag}" || exit 1
  formal_abc_prove "$me" "$out/model_${tag}" "${FORMAL_BASE:-4}" "$kind" || exit 1
  exit 0
fi

# Bounded runs: ABC's bmc3 on the same AIGER as the proof's (formal_abc_export: registers start
# at 0, the assumptions become constraints, folded here, and the asserts one output, orpos).
# On this model bmc3 is far faster than Yosys's sat -seq (docs/formal.md).
log="$out/bmc_${tag}.log"
echo "$me: ABC bmc3 from reset, ${bmc_depth} cycles (span pipe ${sp_depth}, PipeDepth ${depth}, latency ${latency})"
formal_abc_export "$me" "$out/model_${tag}.il" "$out/model_${tag}" || exit 1
status=0
yosys-abc -c "read_aiger $out/model_${tag}.aig; fold; orpos; strash; dc2; bmc3 -F ${bmc_depth}" > "$log" 2>&1 || status=1
grep -E "asserted|No output" "$log" || true

if [ -n "$mutant" ]; then
  if [ $status -eq 0 ] && grep -q "was asserted in frame" "$log"; then
    echo "$me: PASS: mutant '$mutant' is caught (a property fails; $log)"
    exit 0
  fi
  echo "$me: FAIL: mutant '$mutant' was not caught (see $log)" >&2
  exit 1
fi
if [ $status -ne 0 ] || ! grep -q "No output asserted in ${bmc_depth} frames" "$log"; then
  echo "$me: FAIL (logs in $out)" >&2
  exit 1
fi
echo "$me: PASS: no property fails within ${bmc_depth} cycles from reset (bounded)"
