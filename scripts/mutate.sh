#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# Mutation campaign of the RTL against `make sim` (sim/README.md#mutation-campaign).
#
#   scripts/mutate.sh [--list] [--check] [--only NAME[,NAME...]] [--jobs N] [OUT_DIR]
#
# --check builds and runs nothing: it applies every mutant's sed expression to a temporary
# copy of its file and exits 1 unless each changes exactly one line (the ctest
# mutate_patterns, so that an RTL edit cannot silently retire a mutant).
# Copies the repository's files (tracked and untracked, not ignored) into OUT_DIR/src,
# builds sim_regression there once with only the default configuration
# (-DSPECULAR_SIM_CONFIGS=default), then for every mutant below: applies its one-line sed
# edit to the copy's RTL (never to rtl/), rebuilds, runs the regression of the default
# configuration as `make sim` runs it (lines, scenes, stream stage), and restores the file.
# A mutant is killed when the build fails (an elaboration check), an assertion stops the
# simulation or the regression exits non-zero; the first failing checks are recorded.
# Writes OUT_DIR/results.md (one row per mutant) and exits 1 if a mutant not listed as
# equivalent below survives, 2 on bad arguments or a mutation that no longer applies.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

# name # file under rtl/ # sed expression (one line changes) # what it breaks
# Equivalent mutants (the behaviour cannot change on any input) are marked EQUIVALENT: in
# the last field, with the reason; the campaign reports them but does not require a kill.
mutants=(
  "carry_drop_neg_dpsi#core/specular_accumulator.sv#s/hi_q + dhi_q + HiBits'(carry_q)/hi_q + dhi_q + HiBits'(carry_q \\& ~dhi_q[HiBits-1])/#register 8 loses the low half's carry whenever dpsi < 0"
  "psi0_high_never_loaded#core/specular_accumulator.sv#s/load_q <= ~sel_i;/load_q <= 1'b0;/#register 8's high half adds dpsi on a span's first pixel instead of loading psi0"
  "abs_no_complement#core/specular_angle_mul.sv#s/assign ones_d = psi_i ^ {AccBits{psi_i\\[AccBits-1\\]}};/assign ones_d = psi_i;/#multiplier 11 takes psi instead of |psi| for negative angles"
  "far_test_ge_high#core/specular_angle_mul.sv#s/gt_hi_q <= ones_q\\[AccBits-1:LoBits\\] > HalfPiCode/gt_hi_q <= ones_q[AccBits-1:LoBits] >= HalfPiCode/#angles in the last 2^-6 rad below pi/2 count as past pi/2"
  "coef3_is_2coef#core/specular_angle_mul.sv#s/coef3_q <= (CoefBits + 2)'(coef_i) + ((CoefBits + 2)'(coef_i) << 1);/coef3_q <= (CoefBits + 2)'(coef_i) << 1;/#the radix-4 digit 3 of multiplier 11 selects 2a"
  "past_quarter_ignored#core/specular_angle_mul.sv#s/assign past_quarter = |zeta\\[ZetaBits-1:ZetaFrac\\];/assign past_quarter = 1'b0;/#a(n)|psi| >= pi/2 is not forced to 0 (interpolated ROM 12)"
  "interp_adds_step#core/specular_cos_k_rom.sv#s/cosk_q <= v_m - (CosDataBits + 1)'(/cosk_q <= v_m + (CosDataBits + 1)'(/#ROM 12 interpolates v + d t instead of v - d t"
  "interp_truncates#core/specular_cos_k_rom.sv#s/(1 << (CosFracBits - 1))/(0)/#ROM 12's d t is truncated instead of rounded"
  "mul13_truncates#core/specular_intensity_mul.sv#s/assign prod_rnd = prod + (ProdBits'(1) << (CosDataBits - 1));/assign prod_rnd = prod;/#multiplier 13 truncates instead of rounding half up"
  "zero_flag_ignored#core/specular_intensity_mul.sv#s/assign intensity_d = keep_m ? prod_rnd\\[CosDataBits +: CBits\\] : '0;/assign intensity_d = prod_rnd[CosDataBits +: CBits];/#pixels flagged zero (far, invalid n, bubbles) show the product"
  "bank_edge_lt#core/specular_decoder.sv#s/assign le_d\\[j\\] = (n_i <= BankMaxN/assign le_d[j] = (n_i < BankMaxN/#decoder 10 puts n = BankMaxN[j] into bank j + 1"
  "n0_valid#core/specular_decoder.sv#s/assign nz_d = (n_i != '0);/assign nz_d = 1'b1;/#n = 0 is decoded as bank 0 instead of invalid"
  "c_line_short#core/specular_stream.sv#s/.Depth (AccStages - 1 + Mul11Stages + Rom12Stages + BlendStages)) u_c_line/.Depth (AccStages - 2 + Mul11Stages + Rom12Stages + BlendStages)) u_c_line/#C reaches multiplier 13 one pixel early (the previous span's C at a span boundary)"
  "tag_line_short#core/specular_stream.sv#s/.Depth (PipeDepth - 1)) u_tag_line/.Depth (PipeDepth - 2)) u_tag_line/#a pixel's tag is the next pixel's (wrong at span boundaries)"
)

list=0
check=0
only=""
jobs=$(nproc 2>/dev/null || echo 2)
while [ $# -gt 0 ]; do
  case "$1" in
    --list) list=1; shift ;;
    --check) check=1; shift ;;
    --only) only=${2:?"--only needs mutant names"}; shift 2 ;;
    --jobs) jobs=${2:?"--jobs needs a number"}; shift 2 ;;
    -h|--help) sed -n '4,21p' "${BASH_SOURCE[0]}"; exit 0 ;;
    -*) echo "mutate.sh: unknown option '$1' (--list, --check, --only NAMES, --jobs N)" >&2; exit 2 ;;
    *) break ;;
  esac
done
if [ "$list" = 1 ]; then
  for m in "${mutants[@]}"; do IFS='#' read -r name file _ what <<< "$m"; printf '%-24s %-28s %s\n' "$name" "$file" "$what"; done
  exit 0
fi
if [ "$check" = 1 ]; then
  tmp=$(mktemp)
  trap 'rm -f "$tmp"' EXIT
  bad=0
  for m in "${mutants[@]}"; do
    IFS='#' read -r name file expr _ <<< "$m"
    cp "$root/rtl/$file" "$tmp"
    sed -i "$expr" "$tmp"
    changed=$(diff "$root/rtl/$file" "$tmp" | grep -c '^>' || true)
    if [ "$changed" != 1 ]; then
      echo "mutate.sh: mutant '$name' changes $changed lines of rtl/$file (want 1): update its sed expression" >&2
      bad=1
    else
      echo "ok: $name ($file)"
    fi
  done
  exit $bad
fi
out=${1:-$root/build/mutate}
mkdir -p "$out"
out=$(cd "$out" && pwd)
if [ -n "$only" ]; then
  for n in ${only//,/ }; do
    found=0
    for m in "${mutants[@]}"; do [ "${m%%#*}" = "$n" ] && found=1; done
    [ "$found" = 1 ] || { echo "mutate.sh: --only: no mutant '$n' (see --list)" >&2; exit 2; }
  done
fi

# A fresh copy of the working tree (uncommitted edits included), so rtl/ is never touched.
src="$out/src"
rm -rf "$src"
mkdir -p "$src"
# Timestamps kept, so that a second run reuses the C++ of the first; the RTL is touched, so
# that no model of an earlier run's mutant survives into this one.
(cd "$root" && git ls-files -z --cached --others --exclude-standard | xargs -0 cp -p --parents -t "$src")
(cd "$src" && python3 scripts/rtl_filelist.py rtl/specular.f rtl/competitors/phong/phong.f | xargs touch)
build="$out/build"
echo "mutate.sh: configuring $build (default configuration only)"
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSPECULAR_SIM_CONFIGS=default > "$out/configure.log" 2>&1 ||
  { echo "mutate.sh: configure failed, see $out/configure.log" >&2; exit 1; }
echo "mutate.sh: building sim_regression on the unmutated RTL"
cmake --build "$build" --target sim_regression -j "$jobs" > "$out/build_pristine.log" 2>&1 ||
  { echo "mutate.sh: the unmutated build failed, see $out/build_pristine.log" >&2; exit 1; }
(cd "$src" && "$build/bin/sim_regression" --config default --images-dir "$out/images" > "$out/run_pristine.log" 2>&1) ||
  { echo "mutate.sh: the unmutated regression fails, see $out/run_pristine.log" >&2; exit 1; }

results="$out/results.md"
{
  echo "| mutant | file | what it breaks | result | killed by |"
  echo "|---|---|---|---|---|"
} > "$results"
survivors=0
for m in "${mutants[@]}"; do
  IFS='#' read -r name file expr what <<< "$m"
  if [ -n "$only" ] && [[ ",$only," != *",$name,"* ]]; then continue; fi
  f="$src/rtl/$file"
  mkdir -p "$out/$(dirname "$file")"
  cp -p "$f" "$out/$file.orig"
  sed -i "$expr" "$f"
  if cmp -s "$f" "$out/$file.orig"; then
    echo "mutate.sh: mutant '$name' no longer applies to rtl/$file (the RTL changed): update its sed expression" >&2
    exit 2
  fi
  echo "mutate.sh: $name: $(diff "$out/$file.orig" "$f" | grep '^>' | sed 's/^> *//')"
  log="$out/$name.log"
  result=""
  killer=""
  if ! cmake --build "$build" --target sim_regression -j "$jobs" > "$log" 2>&1; then
    result="killed"
    killer="build: $(grep -m1 -E '%Error|error:' "$log" | sed 's/|/\\|/g' | cut -c1-160)"
  else
    set +e
    (cd "$src" && timeout 1200 "$build/bin/sim_regression" --config default --images-dir "$out/images" >> "$log" 2>&1)
    rc=$?
    set -e
    if [ "$rc" = 0 ]; then
      result="survived"
    else
      result="killed"
      killer=$(grep -m3 -E '^FAIL|SPEC_ASSERT|%Error' "$log" | cut -c1-140 | sed 's/|/\\|/g' | paste -sd ';' |
                 sed 's/;/; /g' || true)
      [ -n "$killer" ] || killer="exit code $rc"
    fi
  fi
  if [ "$result" = survived ]; then
    if [[ "$what" == EQUIVALENT:* ]]; then
      result="survived (equivalent)"
    else
      survivors=$((survivors + 1))
    fi
  fi
  echo "mutate.sh: $name: $result ${killer:+($killer)}"
  echo "| \`$name\` | \`rtl/$file\` | ${what//|/\\|} | $result | $killer |" >> "$results"
  cp "$out/$file.orig" "$f"
done
# Leave the build on the unmutated RTL.
cmake --build "$build" --target sim_regression -j "$jobs" > "$out/build_restore.log" 2>&1 || true
echo "mutate.sh: results in $results"
cat "$results"
if [ "$survivors" -gt 0 ]; then
  echo "mutate.sh: $survivors mutant(s) not equivalent survived make sim" >&2
  exit 1
fi
