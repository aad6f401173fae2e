# SPDX-License-Identifier: Apache-2.0
#
# The unbounded proof with ABC (yosys-abc, which comes with Yosys) on the AIGER of a formal
# model. Sourced by scripts/formal.sh, the formal driver;
# the flow, what was measured and how a false property fails it:
# docs/formal.md#run-time.
#
#   formal_abc_export ME MODEL.il PREFIX   writes PREFIX.aig, PREFIX.aim (input and latch
#                                          names), PREFIX_aiger.log; 0 when every assert
#                                          became a bad-state output and every assume a
#                                          constraint
#   formal_abc_prove ME PREFIX BASE K      base case (bmc3 from reset, BASE cycles) and
#                                          K-step induction (scorr -o) on PREFIX.aig; logs
#                                          PREFIX_base.log, PREFIX_step.log; 0 when proven
#
# The AIGER: every register starts at 0 (setundef -init, as sat -set-init-zero), the
# harness's outputs are dropped, each $assert becomes a bad-state output and each $assume
# an AIGER constraint. ABC's fold turns the constraints into the outputs: an output counts
# only if every constraint has held in its cycle and all earlier ones, so the assumptions
# hold in every cycle, as with sat -set-assumes.

formal_abc_export() {
  local me=$1 il=$2 prefix=$3
  local aig="${prefix}.aig" stat="${prefix}_stat.txt" status=0
  local n_bad n_constr n_assert n_assume
  yosys -q -l "${prefix}_aiger.log" -p "
    read_rtlil $il
    setattr -unset keep
    setundef -zero -init
    delete -output
    opt -full -nosdff -nodffe
    dffunmap
    techmap
    opt -fast -nosdff -nodffe
    dffunmap
    abc -g AND -fast
    opt_clean
    tee -o $stat stat
    write_aiger -I -B -zinit -map ${prefix}.aim $aig
  " > /dev/null 2>&1 || status=1
  # The header (aig M I L O A B C ...) must carry one bad state per $assert cell and one
  # constraint per $assume cell: nothing is lost on the way.
  read -r _ _ _ _ _ _ n_bad n_constr _ < <(head -n 1 "$aig" 2>/dev/null || true)
  n_assert=$(sed -n 's/^ *\$assert *\([0-9]*\)$/\1/p' "$stat" 2>/dev/null | tail -1)
  n_assume=$(sed -n 's/^ *\$assume *\([0-9]*\)$/\1/p' "$stat" 2>/dev/null | tail -1)
  if [ $status -ne 0 ] || [ -z "${n_assert}" ] || [ "${n_bad:-x}" != "$n_assert" ] \
       || [ "${n_constr:-x}" != "${n_assume:-0}" ]; then
    tail -20 "${prefix}_aiger.log" >&2
    echo "$me: FAIL: AIGER conversion (${n_bad:-?} bad states for ${n_assert:-?} asserts," \
         "${n_constr:-?} constraints for ${n_assume:-?} assumes; ${prefix}_aiger.log)" >&2
    return 1
  fi
  echo "$me: model: $(head -n 1 "$aig" | cut -d' ' -f3-4 | awk '{print $1 " inputs, " $2 " registers"}'), ${n_bad} asserts, ${n_constr} assumes"
}

# The unbounded proof, two checks on the same AIGER:
# 1. Base case: bmc3 from reset over BASE cycles (>= K): no property fails in cycles
#    0 .. BASE - 1.
# 2. Induction step: scorr -o (signal correspondence restricted to the outputs) proves every
#    output constant 0 by K-step induction: from any state (not only reachable ones) in
#    which every property and assumption held for K cycles, and the assumptions hold in
#    the next, each property holds in the next. Every property is assumed in the earlier
#    cycles and checked on its own in the last one: sat -tempinduct's induction step split
#    into one SAT call per property (a property that fails or runs out of its conflicts is
#    dropped, never kept). The proven outputs become constant 0; the proof holds only if
#    the reduced model is the constant 0: no register, no gate, its one output (all outputs
#    ORed) literal 0.
formal_abc_prove() {
  local me=$1 prefix=$2 base=$3 kind=$4
  local aig="${prefix}.aig" status=0
  if [ "$base" -lt "$kind" ]; then
    echo "$me: the base case ($base cycles) must be at least the induction depth ($kind)" >&2
    return 2
  fi
  echo "$me: base case: ABC bmc3 from reset, ${base} cycles"
  yosys-abc -c "read_aiger $aig; fold; orpos; strash; dc2; bmc3 -F ${base}" > "${prefix}_base.log" 2>&1 || status=1
  grep -E "asserted|No output" "${prefix}_base.log" || true
  if [ $status -ne 0 ] || ! grep -q "No output asserted in ${base} frames" "${prefix}_base.log"; then
    echo "$me: FAIL: base case (a property fails from reset, or no result; ${prefix}_base.log)" >&2
    return 1
  fi
  echo "$me: induction step: ABC scorr -o, ${kind}-step induction"
  rm -f "${prefix}_step.aig"
  yosys-abc -c "read_aiger $aig; fold; strash; scorr -o -F ${kind} -C 10000000 -v; orpos; strash; print_stats; write_aiger ${prefix}_step.aig" \
    > "${prefix}_step.log" 2>&1 || status=1
  grep -E "SAT calls|NBeg|lat =" "${prefix}_step.log" | sed 's/\x1b\[[0-9;]*m//g' || true
  # A binary AIGER without registers and gates whose one output is literal 0: "aig M I 0 1 0", "0".
  if [ $status -ne 0 ] || [ ! -f "${prefix}_step.aig" ] \
       || ! [[ "$(head -n 2 "${prefix}_step.aig" | tr '\n' ' ')" =~ ^aig\ [0-9]+\ [0-9]+\ 0\ 1\ 0\ 0\ $ ]]; then
    echo "$me: FAIL: induction step (some property is not proven; ${prefix}_step.log)" >&2
    return 1
  fi
  echo "$me: PASS: every property proven (base case ${base} cycles + ${kind}-step induction)"
}

# The unbounded proof by property-directed reachability (ABC pdr) on PREFIX.aig, for a model
# whose induction needs invariants its harness cannot state (specular_delay_fv: the ring's
# words against the line's registers): pdr finds an inductive invariant itself. Logs
# PREFIX_pdr.log; 0 when pdr reports the property proved.
formal_abc_pdr() {
  local me=$1 prefix=$2
  local aig="${prefix}.aig" status=0
  echo "$me: ABC pdr (property-directed reachability)"
  yosys-abc -c "read_aiger $aig; fold; orpos; strash; dc2; pdr" > "${prefix}_pdr.log" 2>&1 || status=1
  grep -E "Property proved|asserted|Undecided|stopped" "${prefix}_pdr.log" | sed 's/\x1b\[[0-9;]*m//g' || true
  if [ $status -ne 0 ] || ! grep -q "Property proved" "${prefix}_pdr.log"; then
    echo "$me: FAIL: pdr (a property fails or no result; ${prefix}_pdr.log)" >&2
    return 1
  fi
  echo "$me: PASS: every property proven (pdr)"
}
