#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# RTL coverage (sim/README.md): builds sim_regression with every model verilated with
# --coverage (line/branch, toggle, user) in its own build directory, runs a reduced but
# complete regression (every configuration: the deterministic sweep, random lines, the
# scenes; the stream: random spans and the scenes), merges the per-model .dat files and writes
#   OUT/merged.dat      verilator_coverage merge of every model and configuration
#   OUT/summary.md      per rtl/ file line / branch / toggle coverage, waivers applied (printed too);
#                       files of rtl/specular.f that no model elaborates are named on the console
#   OUT/annotated/      verilator_coverage --annotate (sources with counts, %000000 = not hit)
#   OUT/coverage.info   verilator_coverage --write-info (lcov tracefile)
#   OUT/html/index.html genhtml of it
# Fails when a line or branch point of rtl/ is neither covered nor waived in
# sim/coverage_waivers.txt. Usage: scripts/coverage.sh [BUILD_DIR [OUT_DIR]] (run from the root).
set -euo pipefail
BUILD=${1:-build/coverage}
OUT=${2:-$BUILD/report}
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}
COVERAGE_ARGS=${COVERAGE_ARGS:---random 20000 --stream-spans 200000}

cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DSPECULAR_COVERAGE=ON > /dev/null
cmake --build "$BUILD" -j "$JOBS" --target sim_regression
rm -rf "$OUT"
mkdir -p "$OUT/dat"
# shellcheck disable=SC2086
"$BUILD/bin/sim_regression" $COVERAGE_ARGS --images-dir "$OUT/scenes" --coverage-dir "$OUT/dat" > "$OUT/regression.log"
tail -n 2 "$OUT/regression.log"
verilator_coverage --write "$OUT/merged.dat" "$OUT"/dat/*.dat
verilator_coverage --annotate "$OUT/annotated" --annotate-all --annotate-min 1 "$OUT/merged.dat" | sed -n 1p
verilator_coverage --write-info "$OUT/coverage.info" "$OUT/merged.dat"
genhtml --quiet --output-directory "$OUT/html" --title "specular-device RTL coverage" "$OUT/coverage.info" \
  > "$OUT/genhtml.log" 2>&1 || { cat "$OUT/genhtml.log"; exit 1; }
echo "coverage: HTML report $OUT/html/index.html, annotated sources $OUT/annotated/"
# Every source of rtl/specular.f (compile order, paths relative to the root; rtl/README.md)
# either has coverage points or is named here: the AXI wrappers are not in sim_regression's
# models (their tests are the rtl_axi ctests, tests/rtl/).
# shellcheck source=scripts/rtl_filelist.sh
source scripts/rtl_filelist.sh
rtl_filelist rtl/specular.f rtl/competitors/phong/phong.f
for f in "${RTL_SOURCES[@]}"; do
  grep -qF "$f" "$OUT/merged.dat" || echo "coverage: $f (rtl/specular.f) is in none of the regression's models"
done
python3 scripts/coverage_summary.py "$OUT/merged.dat" --waivers sim/coverage_waivers.txt --out "$OUT/summary.md" --check
