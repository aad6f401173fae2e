#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# The formal driver: one flow for every formal target, a table of what differs
# (target_<name> below). What each target proves, why the parameters are reduced, the
# abstractions and how a false property fails: docs/formal.md. Run by the ctests
# rtl_formal_* (tests/rtl/CMakeLists.txt).
#
#   scripts/formal.sh TARGET [--bounded | --mutant NAME] [OUT_DIR]
#
#   TARGET     stream (specular_stream), axil (specular_axil), phong (phong_stream),
#              phong_cross (phong_stream, Cross = 1), setup (specular_setup), delay
#              (specular_delay's ring against its register line)
#   (none)     the unbounded proof: the harness's properties and strengthening invariants,
#              base case from reset (ABC bmc3, FORMAL_BASE = 4 cycles) and FORMAL_K = 1
#              step induction (ABC scorr -o, one SAT call per property;
#              scripts/formal_abc.sh). Exit 0 when proven.
#   --bounded  the properties alone (FV_PROPERTIES_ONLY) on the intact RTL, a bounded model
#              check from reset over the target's depth (FORMAL_DEPTH overrides): a bounded
#              result, not a proof. Exit 0 when no property fails.
#   --mutant   one sed-edited line of a copy of the RTL (OUT_DIR/rtl_NAME/; rtl/ is never
#              touched), the properties alone, the same bounded check: exit 0 only if a
#              property fails (the mutant is caught), 1 if it passes or a tool fails.
#
# The flow: Yosys reads the target's filelist (scripts/rtl_filelist.sh), the property
# modules rtl/prim/formal/specular_{axis,streak}_props.sv, specular_px_ghost.sv and the harness with -formal; an
# elaboration pass reads the pipeline depths off the netlist (the widths of named
# registers) and hands them to the harness (chparam); the model pass cuts what the target
# abstracts, flattens, connects the harness's probe wires to the core's state, maps the
# asynchronous reset (async2sync) and writes the model, whose AIGER ABC checks
# (scripts/formal_abc.sh). A port whose width differs between harness and core fails the
# run (Yosys would resize it in silence).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
me=formal.sh

usage() {
  echo "usage: $me TARGET [--bounded | --mutant NAME] [OUT_DIR]; TARGET: stream, axil, phong, phong_cross, setup, delay" >&2
  exit 2
}

# ---------------------------------------------------------------------------------------
# The table. Each target sets:
#   filelist, harness, top   the RTL (rtl/README.md#filelists), the harness file and module
#   measure                  lines "PARAM WIRE DIV ADD": PARAM = width(WIRE) / DIV + ADD,
#                            read after flatten and set on the harness
#   bmc_depth                the bounded check's cycles, an arithmetic expression over the
#                            measured parameters; bmc_depth_mutant likewise for mutants
#   bmc_engine               abc (bmc3 on the AIGER) or sat (Yosys sat -seq, which on this
#                            target's 104-cycle check is the one measured)
#   pre_flatten              Yosys commands before flatten (cutting whole modules)
#   checks                   structural checks after flatten: select -assert-none lines;
#                            a failing one catches a mutant meant for it
#   probes                   lines "PROBE WIRE": the harness's probe wire, the core's state
#                            (proof runs only; FV_PROPERTIES_ONLY leaves the probes out)
#   cuts, cuts_proof         wires made free values every clock ($anyseq): in every run,
#                            in the proof only
#   map                      the commands that map the flattened model ("bits": simplemap,
#                            so opt_clean drops every register bit without a reader;
#                            "memory": prep and memory_map)
#   prove_engine             induction (the default: base case and K-step induction with the
#                            harness's invariants) or pdr (ABC finds the invariant)
#   mutants                  lines "NAME FILE SED": one-line edits of a copy of the RTL
#   cex_ports                the inputs printed cycle by cycle from an ABC counterexample
# ---------------------------------------------------------------------------------------
target_stream() {
  filelist=rtl/core/core.f
  harness=rtl/core/formal/specular_stream_fv.sv
  top=specular_stream_fv
  # The tag delay line: stages 1 .. PipeDepth - 1, TagBits (2) each; Latency = PipeDepth + 1.
  measure="Latency u_dut.u_tag_line.gen_regs.line_q 2 2"
  bmc_depth=22
  bmc_depth_mutant=22
  bmc_engine=abc
  probes="p_vld u_dut.u_control14.vld_q
p_last u_dut.u_control14.last_q
p_cnt u_dut.cnt0
p_zero u_dut.u_counter5.zero_q
p_tag0 u_dut.tag0
p_count u_dut.u_out_buf.count_q
p_head u_dut.u_out_buf.head_q
p_tail u_dut.u_out_buf.tail_q
p_adv u_dut.u_out_buf.adv_q
p_tagline u_dut.u_tag_line.gen_regs.line_q"
  # The datapath where it enters the output buffer (the proof only: mutant traces are real).
  cuts_proof="u_dut.intensity"
  map=memory
  mutants="adv_ignores_room rtl/prim/specular_out_buf.sv s/adv_q *<= adv_d;/adv_q   <= 1'b1;/
pop_ignores_ready rtl/prim/specular_out_buf.sv s/assign pop *= (count_q != 2'd0) & px_ready_i;/assign pop  = (count_q != 2'd0);/
no_last_shift rtl/core/specular_control.sv s/vld_q\[0\] & cnt_zero_i}/1'b0}/
ready_ignores_busy rtl/core/specular_control.sv s/assign free0 *= ~vld_q\[0\] | cnt_zero_i;/assign free0 = 1'b1;/"
  cex_ports="rst_ni span_valid_i span_len_i span_tag_i px_ready_i"
}

target_axil() {
  filelist=rtl/axi/axi.f
  harness=rtl/axi/formal/specular_axil_fv.sv
  top=specular_axil_fv
  bmc_depth=10
  bmc_depth_mutant=10
  bmc_engine=abc
  # The stream core cut out: every output of specular_axis's specular_stream a free value.
  pre_flatten="select -assert-count 1 */u_stream
  cutpoint */u_stream %M"
  probes="p_aw_full u_dut.aw_full_q
p_w_full u_dut.w_full_q
p_awaddr u_dut.awaddr_q"
  map=memory
  mutants="write_without_w rtl/axi/specular_axil.sv s/assign do_write *= aw_full_q & w_full_q & ~bvalid_q;/assign do_write = aw_full_q \& ~bvalid_q;/
b_ignores_ready rtl/axi/specular_axil.sv s/if (s_axil_bvalid && s_axil_bready) begin/if (s_axil_bvalid) begin/
r_ignores_ready rtl/axi/specular_axil.sv s/if (s_axil_rvalid && s_axil_rready) begin/if (s_axil_rvalid) begin/
aw_while_b rtl/axi/specular_axil.sv s/assign s_axil_awready = ~aw_full_q & ~bvalid_q;/assign s_axil_awready = ~aw_full_q;/
ro_write_okay rtl/axi/specular_axil.sv s/default: bresp_d = RespSlverr;  \/\/ read-only or unmapped/default: bresp_d = RespOkay;/"
  cex_ports="rst_ni s_axil_awvalid s_axil_wvalid s_axil_bready s_axil_arvalid s_axil_rready"
}

target_phong() {
  filelist=rtl/competitors/phong/phong.f
  harness=rtl/competitors/phong/formal/phong_stream_fv.sv
  top=phong_stream_fv
  # The span pipe's valid line and the control's stage valids; Latency = SpDepth + Depth + 1.
  measure="SpDepth u_dut.u_setup.vld_q 1 0
Depth u_dut.u_control.vld_q 1 0"
  bmc_depth="SpDepth + Depth + 1 + 6"
  bmc_depth_mutant="SpDepth + Depth + 1 + 12"
  bmc_engine=abc
  # geo_ready_o depends on registers only: no combinational path from geo_valid_i or
  # px_ready_i (%cie*: the input cone over combinational cells).
  checks="w:geo_ready_o %cie* w:geo_valid_i w:px_ready_i %u %i"
  probes="p_sp_vld u_dut.u_setup.vld_q
p_len1 u_dut.u_setup.len_1
p_tag1 u_dut.u_setup.tag_1
p_len2 u_dut.u_setup.len_2
p_tag2 u_dut.u_setup.tag_2
p_side u_dut.u_setup.u_side.gen_regs.line_q
p_lenh u_dut.len_h
p_tagh u_dut.tag_h
p_vld u_dut.u_control.vld_q
p_last u_dut.u_control.last_q
p_cnt u_dut.u_counter.cnt_q
p_zero u_dut.u_counter.zero_q
p_tag0 u_dut.tag0
p_tagline u_dut.u_tag_line.gen_regs.line_q
p_count u_dut.u_out_buf.count_q
p_head u_dut.u_out_buf.head_q
p_tail u_dut.u_out_buf.tail_q
p_adv u_dut.u_out_buf.adv_q"
  cuts="u_dut.intensity"
  map=bits
  mutants="valid_drops rtl/competitors/phong/phong_stream.sv s/\.px_ready_i (px_ready_i),/.px_ready_i (1'b1),/
span_one_long rtl/competitors/phong/phong_stream.sv s/\.len_i    (len_h),/.len_i    (len_h + 1'b1),/
head_overrun rtl/competitors/phong/phong_stream.sv s/assign sp_adv      = ctrl_ready | (adv & ~head_valid);/assign sp_adv      = ctrl_ready | adv;/
tag_line_short rtl/competitors/phong/phong_stream.sv s/\.Depth (PipeDepth - 1)) u_tag_line/.Depth (PipeDepth - 2)) u_tag_line/
ready_waits_valid rtl/competitors/phong/phong_stream.sv s/assign geo_ready_o = sp_adv;/assign geo_ready_o = sp_adv \& geo_valid_i;/"
  cex_ports="rst_ni geo_valid_i geo_len_i geo_tag_i px_ready_i"
}

# The cancellation-free form (phong_stream Cross = 1, docs/phong_hw.md#the-cancellation-free-form):
# the same harness, properties, probes, cut and mutants at its own reduced widths.
target_phong_cross() {
  target_phong
  harness_params="-set Cross 1"
  probes+="
p_lenr1 u_dut.u_setup.gen_headroom.len_h
p_tagr1 u_dut.u_setup.gen_headroom.tag_h
p_lenr2 u_dut.u_setup.len_3
p_tagr2 u_dut.u_setup.tag_3"
}

target_setup() {
  filelist=rtl/setup/setup.f
  harness=rtl/setup/formal/specular_setup_fv.sv
  top=specular_setup_fv
  # The valid delay line: one bit per register after the input register (the tau TOUT).
  measure="Depth u_dut.u_dly_valid.gen_regs.line_q 1 0"
  bmc_depth="Depth + 8"
  bmc_depth_mutant="Depth + 8"
  bmc_engine=abc
  probes="p_vld0 u_dut.in_valid_q
p_tag0 u_dut.tag_q
p_vline u_dut.u_dly_valid.gen_regs.line_q
p_oline u_dut.u_dly_side.gen_regs.line_q
p_count u_dut.u_out_buf.count_q
p_head u_dut.u_out_buf.head_q
p_tail u_dut.u_out_buf.tail_q
p_adv u_dut.u_out_buf.adv_q"
  # The datapath where it reaches the descriptor (tau TOUT), and the tau-0 flags.
  cuts="u_dut.c_out u_dut.psi0_out u_dut.dpsi_out
u_dut.a_pos_out u_dut.opph_out u_dut.oppn_out u_dut.n_out
u_dut.len_out u_dut.invalid_out u_dut.undefined_out
u_dut.invalid u_dut.undefined"
  map=bits
  mutants="valid_no_reset rtl/setup/specular_setup.sv s/specular_delay #(.Width(1), .Depth(TOUT), .Reset(1'b1)) u_dly_valid/specular_delay #(.Width(1), .Depth(TOUT), .Reset(1'b0)) u_dly_valid/"
  cex_ports="rst_ni geo_valid_i geo_tag_i span_ready_i"
}

# specular_delay's ring buffer (Ram = 1) against its register line, a pair per depth
# (rtl/prim/formal/specular_delay_fv.sv); the setup's harness reads its lines as registers.
target_delay() {
  filelist=rtl/prim/prim.f
  harness=rtl/prim/formal/specular_delay_fv.sv
  top=specular_delay_fv
  # The deepest pair's fill (17) and a few cycles: the mutant fails within them.
  bmc_depth=24
  bmc_depth_mutant=24
  bmc_engine=abc
  prove_engine=pdr
  map=memory
  mutants="read_one_late rtl/prim/specular_delay.sv s/rp_q <= wp_q + AW'(Words + 3 - Depth);/rp_q <= wp_q + AW'(Words + 2 - Depth);/"
  cex_ports="en_i d_i"
}

# ---------------------------------------------------------------------------------------
# Arguments
# ---------------------------------------------------------------------------------------
target=${1:-}
[ -n "$target" ] || usage
shift
filelist="" harness="" top="" measure="" bmc_depth="" bmc_depth_mutant="" bmc_engine=abc prove_engine=induction
pre_flatten="" checks="" probes="" cuts="" cuts_proof="" map="" mutants="" cex_ports="" harness_params=""
case "$target" in
  stream | axil | phong | phong_cross | setup | delay) "target_$target" ;;
  *) echo "$me: unknown target '$target'" >&2; usage ;;
esac
mode=proof
mutant=""
if [ "${1:-}" = "--bounded" ]; then
  mode=bounded
  shift
elif [ "${1:-}" = "--mutant" ]; then
  mode=mutant
  mutant=${2:?"--mutant needs a name"}
  shift 2
fi
out=${1:-$(mktemp -d)}
kind=${FORMAL_K:-1}
base=${FORMAL_BASE:-4}

cd "$root"
mkdir -p "$out"
out=$(cd "$out" && pwd)
tag=$target
[ "$mode" = proof ] || tag=${mutant:-${target}_bounded}

# shellcheck source=scripts/rtl_filelist.sh
source scripts/rtl_filelist.sh
rtl_filelist "$filelist" || exit 1
sources=("${RTL_SOURCES[@]}")
incflags=""
for d in "${RTL_INCDIRS[@]+"${RTL_INCDIRS[@]}"}"; do incflags+=" -I$d"; done

if [ "$mode" = mutant ]; then
  line=$(printf '%s\n' "$mutants" | awk -v m="$mutant" '$1 == m' | head -1)
  if [ -z "$line" ]; then
    echo "$me: unknown mutant '$mutant' of target '$target'" >&2
    exit 2
  fi
  read -r _ file sed_expr <<< "$line"
  echo "$me: $target: mutant '$mutant':"
  rtl_mutant_copy "$out/rtl_${mutant}" "$file" "$sed_expr" || exit 1
  sources=("${MUTANT_SOURCES[@]}")
fi

defines="-DSYNTHESIS"
[ "$mode" = proof ] || defines+=" -DFV_PROPERTIES_ONLY"
read_cmd="read_verilog -sv -formal ${defines}${incflags} ${sources[*]} rtl/prim/formal/specular_axis_props.sv rtl/prim/formal/specular_streak_props.sv rtl/prim/formal/specular_px_ghost.sv ${harness}"

# ---------------------------------------------------------------------------------------
# Elaboration: the depths of the harness, read off the netlist
# ---------------------------------------------------------------------------------------
chparams=""
[ -z "$harness_params" ] || chparams=" $harness_params"
if [ -n "$measure" ]; then
  dumps=$(printf '%s\n' "$measure" | awk '{printf " w:%s", $2}')
  yosys -q -p "
    ${read_cmd}
    ${harness_params:+chparam ${harness_params} ${top}}
    hierarchy -check -top ${top}
    proc
    flatten
    tee -q -o $out/depths_${tag}.txt dump${dumps}
  " > "$out/elab_${tag}.log" 2>&1 || { tail -20 "$out/elab_${tag}.log" >&2; exit 1; }
  while read -r param wire div add; do
    width=$(awk -v w="$wire" '$1 == "wire" && $2 == "width" && $NF == "\\" w { print $3; exit }' \
              "$out/depths_${tag}.txt")
    if [ -z "$width" ] || [ $((width / div)) -lt 1 ]; then
      echo "$me: no register $wire (RTL changed?)" >&2
      exit 1
    fi
    declare "$param=$((width / div + add))"
    chparams+=" -set $param ${!param}"
  done <<< "$measure"
  echo "$me: $target:${chparams// -set / }"
fi

# ---------------------------------------------------------------------------------------
# The model
# ---------------------------------------------------------------------------------------
checks_cmd="" probes_cmd="" cuts_cmd=""
if [ -n "$checks" ]; then
  while read -r sel; do
    checks_cmd+="  tee -o $out/check_${tag}.txt select -list ${sel}
  select -assert-none ${sel}
"
  done <<< "$checks"
fi
if [ "$mode" = proof ] && [ -n "$probes" ]; then
  while read -r probe wire; do
    probes_cmd+="  connect -nounset -set ${probe} ${wire}
"
  done <<< "$probes"
fi
cut_wires="$cuts"
[ "$mode" != proof ] || cut_wires+=" $cuts_proof"
for w in $cut_wires; do
  cuts_cmd+="  select -assert-count 1 w:${w}
  cutpoint w:${w}
"
done
case "$map" in
  memory) map_cmd="prep -top ${top}
  memory_map
  opt -keepdc -fast" ;;
  bits) map_cmd="opt_clean
  simplemap
  opt_clean
  tee -q -o $out/stat_${tag}.txt stat" ;;
  *) echo "$me: target '$target' has no map" >&2; exit 2 ;;
esac
[ -z "$chparams" ] || chparam_cmd="chparam${chparams} ${top}"

status=0
yosys -q -l "$out/yosys_${tag}.log" -p "
  ${read_cmd}
  ${chparam_cmd:-}
  hierarchy -check -top ${top}
  proc
  ${pre_flatten}
  flatten
  opt_clean
${checks_cmd}${probes_cmd}${cuts_cmd}  ${map_cmd}
  async2sync
  dffunmap
  opt -keepdc -fast
  check -assert
  write_rtlil $out/model_${tag}.il
" > "$out/model_${tag}.log" 2>&1 || status=1
if [ $status -ne 0 ]; then
  if [ -n "$checks" ] && grep -q "Assertion failed: selection is not empty" "$out/yosys_${tag}.log"; then
    echo "$me: a structural check failed (${checks}):" >&2
    cat "$out/check_${tag}.txt" >&2
    if [ "$mode" = mutant ]; then
      echo "$me: PASS: mutant '$mutant' is caught (the structural check)"
      exit 0
    fi
  fi
  tail -20 "$out/yosys_${tag}.log" >&2
  echo "$me: FAIL: elaboration (logs in $out)" >&2
  exit 1
fi
if grep -q "Resizing cell port" "$out/yosys_${tag}.log"; then
  grep "Resizing cell port" "$out/yosys_${tag}.log" | head -5 >&2
  echo "$me: a port of the harness differs in width from the core's (above)" >&2
  exit 1
fi

# ---------------------------------------------------------------------------------------
# The checks
# ---------------------------------------------------------------------------------------
# shellcheck source=scripts/formal_abc.sh
source scripts/formal_abc.sh
if [ "$mode" = proof ]; then
  formal_abc_export "$me" "$out/model_${tag}.il" "$out/model_${tag}" || exit 1
  if [ "$prove_engine" = pdr ]; then
    formal_abc_pdr "$me" "$out/model_${tag}" || exit 1
  else
    formal_abc_prove "$me" "$out/model_${tag}" "$base" "$kind" || exit 1
  fi
  exit 0
fi

if [ "$mode" = mutant ]; then
  depth=${FORMAL_DEPTH:-$((bmc_depth_mutant))}
else
  depth=${FORMAL_DEPTH:-$((bmc_depth))}
fi
log="$out/bmc_${tag}.log"
failed=""
if [ "$bmc_engine" = abc ]; then
  formal_abc_export "$me" "$out/model_${tag}.il" "$out/model_${tag}" || exit 1
  echo "$me: ABC bmc3 from reset, ${depth} cycles"
  cex="$out/cex_${tag}.aiw"
  rm -f "$cex"
  yosys-abc -c "read_aiger $out/model_${tag}.aig; fold; orpos; strash; dc2; bmc3 -F ${depth}; write_cex -a $cex" \
    > "$log" 2>&1 || status=1
  grep -E "asserted|No output" "$log" || true
  [ $status -ne 0 ] || ! grep -q "was asserted in frame" "$log" || failed=1
  [ $status -eq 0 ] && { [ -n "$failed" ] || grep -q "No output asserted in ${depth} frames" "$log"; } || status=1
  if [ -n "$failed" ] && [ -f "$cex" ]; then
    # The counterexample's inputs, one line per cycle from reset (the AIGER witness: line 1
    # the initial state, then one line of input bits per cycle, named by the map file).
    awk -v ports="$cex_ports" '
      FNR == NR { if ($1 == "input") { name[$2] = $4; pos[$2] = $3 } next }
      FNR == 1 { next }
      { sub(/#.*/, ""); if ($0 == "") next
        delete v
        for (i = 0; i < length($0); i++) if (i in name) v[name[i]] += substr($0, i + 1, 1) * 2 ^ pos[i]
        line = sprintf("  cycle %2d:", FNR - 2)
        n = split(ports, p, " ")
        for (k = 1; k <= n; k++) line = line sprintf(" %s=%d", p[k], v[p[k]])
        print line }' "$out/model_${tag}.aim" "$cex" || true
  fi
else
  echo "$me: Yosys sat from reset, ${depth} cycles"
  cex="$out/cex_${tag}.vcd"
  yosys -q -l "$log" -p "read_rtlil $out/model_${tag}.il
    sat -seq ${depth} -prove-asserts -set-assumes -set-init-zero -show-ports -dump_vcd $cex" \
    > /dev/null 2>&1 || status=1
  grep -E "SUCCESS|FAIL" "$log" | head -5 || true
  if grep -q "SAT proof finished - model found: FAIL" "$log"; then
    failed=1
    status=0
  elif ! grep -q "SAT proof finished - no model found: SUCCESS" "$log"; then
    status=1
  fi
fi

if [ "$mode" = mutant ]; then
  if [ -n "$failed" ]; then
    echo "$me: PASS: mutant '$mutant' is caught (a property fails; $log, counterexample $cex)"
    exit 0
  fi
  echo "$me: FAIL: mutant '$mutant' was not caught (see $log)" >&2
  exit 1
fi
if [ $status -ne 0 ] || [ -n "$failed" ]; then
  echo "$me: FAIL: a property fails within ${depth} cycles from reset, or no result (see $log)" >&2
  exit 1
fi
echo "$me: PASS: no property fails within ${depth} cycles from reset (bounded)"
