#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# Formal proof of specular_setup's handshakes (harness and properties in
# rtl/setup/formal/specular_setup_fv.sv, overview in docs/formal.md#specular_setup-the-span-handshakes).
# Run by ctest as rtl_formal_setup and rtl_formal_setup_mutant.
#
#   scripts/formal_setup.sh [--bounded | --mutant NAME] [OUT_DIR]
#
# Flow: Yosys reads the sources of rtl/specular.f and the harness with -formal, flattens,
# connects the harness's probe wires to the core's control state, cuts the arithmetic
# datapath where it reaches the descriptor (cutpoint: the wires below become free values
# every clock), maps the cells to single bits (simplemap) so that opt_clean drops every
# register bit and gate left without a reader (the normalizers, CORDICs, log2, exp2, ROMs
# and the sideband bits of the delay lines), maps the asynchronous reset for the solver
# (async2sync) and proves with ABC on the model's AIGER (scripts/formal_abc.sh): a base
# case from reset (bmc3, FORMAL_BASE = 4 cycles) and a FORMAL_K = 1 step induction
# (scorr -o, one SAT call per property). A pass is an unbounded proof.
# Exit status 0 when proven, 1 otherwise. The bounded and mutant runs use Yosys's sat.
#
# --bounded: the bounded fallback on the intact RTL: the properties alone
# (FV_PROPERTIES_ONLY, no invariants) checked by a bounded model check from reset over
# FORMAL_DEPTH cycles (default Latency + 6 = 104: a span accepted in the first cycle after
# reset reaches the output at cycle Latency + 1). Exit 0 when no property fails.
#
# --mutant NAME copies the files of rtl/specular.f into OUT_DIR, applies one mutation to the
# copy of rtl/setup/specular_setup.sv (never to rtl/), leaves out the strengthening invariants
# (FV_PROPERTIES_ONLY) and runs a bounded model check from reset (FORMAL_DEPTH cycles,
# default Latency + 6 = 104, as --bounded); exit 0 only if the solver finds a counterexample. The mutant
# runs keep the datapath cut (the mutations are in the control).
# Mutations (one line each):
#   valid_no_reset       the valid delay line has no reset: a span in flight survives a
#                        reset (P3; the ctest)
#   ready_ignores_stall  geo_ready_o = 1: spans are accepted while the pipeline is stalled
#                        and lost (P4); not caught within 104 cycles, it needs about
#                        2 x Latency (docs/formal.md#specular_setup-the-span-handshakes)
#   tag_one_short        the sideband line (tag) is one register short: a span gets the tag
#                        of the span behind it (P4)
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
me=formal_setup.sh
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
rtl_filelist rtl/setup/setup.f || exit 1
sources=("${RTL_SOURCES[@]}")
incflags=""
for d in "${RTL_INCDIRS[@]+"${RTL_INCDIRS[@]}"}"; do incflags+=" -I$d"; done

if [ -n "$mutant" ]; then
  file=rtl/setup/specular_setup.sv
  case "$mutant" in
    ready_ignores_stall)
      sed_expr='s/assign geo_ready_o = adv;/assign geo_ready_o = 1'"'"'b1;/' ;;
    valid_no_reset)
      sed_expr='s/specular_delay #(.Width(1), .Depth(TC), .Reset(1'"'"'b1)) u_dly_valid/specular_delay #(.Width(1), .Depth(TC), .Reset(1'"'"'b0)) u_dly_valid/' ;;
    tag_one_short)
      sed_expr='s/specular_delay #(.Width(LenBits + NBits + TagBits + 3), .Depth(TC), /specular_delay #(.Width(LenBits + NBits + TagBits + 3), .Depth(TC - 1), /' ;;
    *) echo "$me: unknown mutant '$mutant'" >&2; exit 2 ;;
  esac
  # The copy keeps the filelist's relative paths under OUT_DIR/rtl_NAME/.
  echo "$me: mutant '$mutant':"
  rtl_mutant_copy "$out/rtl_${mutant}" "$file" "$sed_expr" || exit 1
  sources=("${MUTANT_SOURCES[@]}")
fi

tag=${mutant:-setup}
if [ -n "$bounded" ]; then
  tag=setup_bounded
fi
defines="-DSYNTHESIS"
if [ -n "$mutant" ] || [ -n "$bounded" ]; then
  defines+=" -DFV_PROPERTIES_ONLY"
fi
read_cmd="read_verilog -sv -formal ${defines}${incflags} ${sources[*]} rtl/prim/formal/specular_axis_props.sv rtl/setup/formal/specular_setup_fv.sv"

# Depth of the harness: the length of the valid delay line (one bit per register after the
# input register; rtl/prim/specular_delay.sv), the descriptor's tau.
yosys -q -p "
  ${read_cmd}
  hierarchy -check -top specular_setup_fv
  proc
  flatten
  tee -q -o $out/vline_${tag}.txt dump w:u_dut.u_dly_valid.gen_regs.line_q
" > "$out/elab_${tag}.log" 2>&1
depth=$(sed -n 's/^ *wire width \([0-9]*\) .*u_dly_valid.gen_regs.line_q$/\1/p' "$out/vline_${tag}.txt" | head -1)
if [ -z "$depth" ] || [ "$depth" -lt 1 ]; then
  echo "$me: no valid line u_dut.u_dly_valid.gen_regs.line_q (RTL changed?)" >&2
  exit 1
fi
bmc_depth=${FORMAL_DEPTH:-$((depth + 8))}

# Probe wire -> state of the flattened core (see the harness header). The mutant runs have
# no probes (FV_PROPERTIES_ONLY).
probes=""
if [ -z "$mutant" ] && [ -z "$bounded" ]; then
  probes="
  connect -nounset -set p_vld0  u_dut.in_valid_q
  connect -nounset -set p_tag0  u_dut.tag_q
  connect -nounset -set p_vline u_dut.u_dly_valid.gen_regs.line_q
  connect -nounset -set p_oline u_dut.u_dly_out.gen_regs.line_q
  connect -nounset -set p_count u_dut.u_out_buf.count_q
  connect -nounset -set p_head  u_dut.u_out_buf.head_q
  connect -nounset -set p_tail  u_dut.u_out_buf.tail_q
  connect -nounset -set p_adv   u_dut.u_out_buf.adv_q
"
fi
# The datapath cut: every descriptor field but the tag where it enters the output buffer
# (tau 96), and the flags of tau 0 (their products feed the sideband line). Each becomes a
# free value every clock ($anyseq). No property constrains these values, so the cut model has
# every behaviour of the core and more: a proof of the cut model holds for the core.
cut_wires="c_96 psi0_96 dpsi_96 a_pos_96 opp_h_96 n_96 len_96 invalid_96 undefined_96 opp_n_96 invalid undefined opp_normals"
cuts=""
for w in $cut_wires; do
  cuts+="  select -assert-count 1 w:u_dut.${w}
  cutpoint w:u_dut.${w}
"
done

yosys -q -l "$out/yosys_${tag}.log" -p "
  ${read_cmd}
  chparam -set Depth ${depth} specular_setup_fv
  hierarchy -check -top specular_setup_fv
  proc
  flatten
  ${probes}
  ${cuts}
  opt_clean
  simplemap
  opt_clean
  tee -o $out/stat_${tag}.txt stat
  async2sync
  dffunmap
  opt -keepdc -fast
  check -assert
  write_rtlil $out/model_${tag}.il
" > "$out/elab_${tag}.log" 2>&1
# The harness declares the core's ports again: a width that differs fails here.
if grep -q "Resizing cell port" "$out/yosys_${tag}.log"; then
  grep "Resizing cell port" "$out/yosys_${tag}.log" | head -5 >&2
  echo "$me: a port of the harness differs in width from the core's (above)" >&2
  exit 1
fi

if [ -z "$mutant" ] && [ -z "$bounded" ]; then
  # The unbounded proof with ABC (scripts/formal_abc.sh): base case bmc3 from reset over
  # FORMAL_BASE = 4 cycles, induction step scorr -o, FORMAL_K = 1 step, on the same AIGER.
  echo "$me: ABC proof (Depth ${depth})"
  # shellcheck source=scripts/formal_abc.sh
  source scripts/formal_abc.sh
  formal_abc_export "$me" "$out/model_${tag}.il" "$out/model_${tag}" || exit 1
  formal_abc_prove "$me" "$out/model_${tag}" "${FORMAL_BASE:-4}" "$kind" || exit 1
  exit 0
fi
log="$out/sat_${tag}.log"
echo "$me: yosys sat BMC from reset, ${bmc_depth} cycles (Depth ${depth})"
cmd="sat -seq ${bmc_depth} -prove-asserts -set-assumes -set-init-zero -show-ports -dump_vcd $out/cex_${tag}.vcd"
status=0
yosys -q -l "$log" -p "read_rtlil $out/model_${tag}.il; $cmd" > /dev/null 2>&1 || status=1
grep -E "induction|proven|SUCCESS|FAIL|ERROR" "$log" | head -20 || true

if [ -n "$mutant" ]; then
  if grep -q "SAT proof finished - model found: FAIL" "$log"; then
    echo "$me: PASS: mutant '$mutant' is caught (counterexample: $out/cex_${tag}.vcd)"
    exit 0
  fi
  echo "$me: FAIL: mutant '$mutant' was not caught (see $log)" >&2
  exit 1
fi

if [ -n "$bounded" ]; then
  if [ $status -ne 0 ] || ! grep -q "SAT proof finished - no model found: SUCCESS" "$log"; then
    echo "$me: FAIL (logs in $out)" >&2
    exit 1
  fi
  echo "$me: PASS: no property fails within ${bmc_depth} cycles from reset (bounded)"
  exit 0
fi
echo "$me: FAIL: no mode (internal error)" >&2
exit 1
