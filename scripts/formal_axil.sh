#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# Formal proof of specular_axil's AXI4-Lite handshake rules (harness and properties in
# rtl/axi/formal/specular_axil_fv.sv, overview in docs/formal.md). Run by ctest as
# rtl_formal_axil and rtl_formal_axil_mutant.
#
#   scripts/formal_axil.sh [--mutant NAME] [OUT_DIR]
#
# Flow: Yosys reads the sources of rtl/specular.f and the harness with -formal, cuts the
# stream core out (cutpoint on specular_stream: its outputs become free values every clock,
# so the proof covers any behaviour of the core), flattens, connects the harness's probe
# wires to the slave's holding registers, maps the asynchronous reset for the solver
# (async2sync) and proves with Yosys's own SAT solver: sat -tempinduct (base case from
# reset and induction step, up to FORMAL_K = 4 steps). A pass is an unbounded proof.
# Exit status 0 when proven, 1 otherwise.
#
# --mutant NAME copies the files of rtl/specular.f into OUT_DIR, applies one mutation to
# the copy of rtl/axi/specular_axil.sv (never to rtl/), leaves out the strengthening
# invariants (FV_PROPERTIES_ONLY) and runs a bounded model check from reset
# (FORMAL_DEPTH = 10 cycles); exit 0 only if the solver finds a counterexample.
# Mutations (one line each):
#   write_without_w    the write (and its B) happens once the AW is held, without the W (P1)
#   b_ignores_ready    bvalid falls without bready (P3: B not held under backpressure)
#   r_ignores_ready    rvalid falls without rready (P4)
#   aw_while_b         awready ignores a pending B: a second write is accepted (P2)
#   ro_write_okay      writes to read-only and unmapped addresses answer OKAY (P7)
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
me=formal_axil.sh
mutant=""
if [ "${1:-}" = "--mutant" ]; then
  mutant=${2:?"--mutant needs a name"}
  shift 2
fi
out=${1:-$(mktemp -d)}
depth=${FORMAL_DEPTH:-10}
kind=${FORMAL_K:-4}

cd "$root"
mkdir -p "$out"
out=$(cd "$out" && pwd)

# The sources in compile order and the include directories: rtl/specular.f (rtl/README.md).
# shellcheck source=scripts/rtl_filelist.sh
source scripts/rtl_filelist.sh
rtl_filelist rtl/axi/axi.f || exit 1
sources=("${RTL_SOURCES[@]}")
incflags=""
for d in "${RTL_INCDIRS[@]+"${RTL_INCDIRS[@]}"}"; do incflags+=" -I$d"; done

if [ -n "$mutant" ]; then
  file=rtl/axi/specular_axil.sv
  case "$mutant" in
    write_without_w)
      sed_expr='s/assign do_write *= aw_full_q & w_full_q & ~bvalid_q;/assign do_write = aw_full_q \& ~bvalid_q;/' ;;
    b_ignores_ready)
      sed_expr='s/if (s_axil_bvalid && s_axil_bready) begin/if (s_axil_bvalid) begin/' ;;
    r_ignores_ready)
      sed_expr='s/if (s_axil_rvalid && s_axil_rready) begin/if (s_axil_rvalid) begin/' ;;
    aw_while_b)
      sed_expr='s/assign s_axil_awready = ~aw_full_q & ~bvalid_q;/assign s_axil_awready = ~aw_full_q;/' ;;
    ro_write_okay)
      sed_expr='s/default: bresp_d = RespSlverr;  \/\/ read-only or unmapped/default: bresp_d = RespOkay;/' ;;
    *) echo "$me: unknown mutant '$mutant'" >&2; exit 2 ;;
  esac
  # The copy keeps the filelist's relative paths under OUT_DIR/rtl_NAME/.
  echo "$me: mutant '$mutant':"
  rtl_mutant_copy "$out/rtl_${mutant}" "$file" "$sed_expr" || exit 1
  sources=("${MUTANT_SOURCES[@]}")
fi

tag=${mutant:-axil}
defines="-DSYNTHESIS"
probes=""
if [ -n "$mutant" ]; then
  defines+=" -DFV_PROPERTIES_ONLY"
else
  # Probe wire -> holding register of the flattened slave (see the harness header).
  probes="
  connect -nounset -set p_aw_full u_dut.aw_full_q
  connect -nounset -set p_w_full  u_dut.w_full_q
  connect -nounset -set p_awaddr  u_dut.awaddr_q
"
fi

t0=$(date +%s)
# The stream core is cut out before flatten: cutpoint on the whole module removes its
# contents and drives each of its outputs from an \$anyseq cell. Exactly one cell u_stream
# (specular_axis's specular_stream) must exist, else the RTL changed under the script.
yosys -q -l "$out/yosys_${tag}.log" -p "
  read_verilog -sv -formal ${defines}${incflags} ${sources[*]} rtl/prim/formal/specular_axis_props.sv rtl/axi/formal/specular_axil_fv.sv
  hierarchy -check -top specular_axil_fv
  proc
  select -assert-count 1 */u_stream
  cutpoint */u_stream %M
  flatten
  ${probes}
  prep -top specular_axil_fv
  memory_map
  opt -keepdc -fast
  async2sync
  dffunmap
  check -assert
  write_rtlil $out/model_${tag}.il
" > /dev/null
# The harness declares the core's ports again (docs/formal.md): a width that differs
# from the core's fails here instead of being resized in silence.
if grep -q "Resizing cell port" "$out/yosys_${tag}.log"; then
  grep "Resizing cell port" "$out/yosys_${tag}.log" | head -5 >&2
  echo "formal_axil.sh: a port of the harness differs in width from the core's (above)" >&2
  exit 1
fi

log="$out/sat_${tag}.log"
if [ -z "$mutant" ]; then
  echo "$me: yosys sat -tempinduct, up to ${kind} steps"
  cmd="sat -tempinduct -prove-asserts -set-assumes -set-init-zero -maxsteps ${kind} -dump_vcd $out/cex_${tag}.vcd"
else
  echo "$me: yosys sat BMC from reset, ${depth} cycles"
  cmd="sat -seq ${depth} -prove-asserts -set-assumes -set-init-zero -show-ports -dump_vcd $out/cex_${tag}.vcd"
fi
status=0
yosys -q -l "$log" -p "read_rtlil $out/model_${tag}.il; $cmd" > /dev/null 2>&1 || status=1
t1=$(date +%s)
grep -E "induction|proven|SUCCESS|FAIL|ERROR" "$log" | head -20 || true

if [ -n "$mutant" ]; then
  if grep -q "SAT proof finished - model found: FAIL" "$log"; then
    # The trace, one line per step: reset and the handshake signals of every channel.
    grep -E '^ +[0-9]+ +\\(rst_ni|s_axil_[a-z]*(valid|ready)) ' "$log" | awk '
      { sub(/^\\s_axil_/, "", $2); sub(/^\\/, "", $2); v[$1] = v[$1] " " $2 "=" $4; if ($1 > n) n = $1 }
      END { for (i = 1; i <= n; i++) printf "  step %2d:%s\n", i, v[i] }' || true
    echo "$me: PASS: mutant '$mutant' is caught in $((t1 - t0)) s (counterexample: $out/cex_${tag}.vcd)"
    exit 0
  fi
  echo "$me: FAIL: mutant '$mutant' was not caught (see $log)" >&2
  exit 1
fi

if [ $status -ne 0 ] || ! grep -q "Induction step proven: SUCCESS" "$log" || grep -q "FAIL" "$log"; then
  echo "$me: FAIL (logs in $out)" >&2
  exit 1
fi
echo "$me: PASS: every property proven (temporal induction) in $((t1 - t0)) s"
