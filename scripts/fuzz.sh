#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `make fuzz`: builds the libFuzzer targets of tests/fuzz with clang++-14
# (-fsanitize=fuzzer,address,undefined) in BUILD/fuzz and runs each for a bounded time.
#   scripts/fuzz.sh [BUILD] [FUZZ_SECONDS]     defaults: build, 60 (shared by all targets)
# Seeds: tests/fuzz/corpus/<target>/ (committed, read only). New inputs go to
# BUILD/fuzz/corpus/<target>/, crashes to BUILD/fuzz/artifacts/<target>/. A crash ends the
# run with exit 1; copy the input into tests/fuzz/corpus/<target>/ once it is fixed, so
# that `make test` (fuzz_replay_<target>) keeps it fixed.
set -euo pipefail
BUILD=${1:-build}
SECONDS_TOTAL=${2:-60}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
OUT="$BUILD/fuzz"
TARGETS=(scene rom_hex cli_parse span_csv)

cmake -S "$ROOT/tests/fuzz" -B "$OUT" -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=RelWithDebInfo > /dev/null
cmake --build "$OUT" -j "${JOBS:-2}" > "$OUT/build.log" 2>&1 || { cat "$OUT/build.log"; exit 1; }

per=$(( SECONDS_TOTAL / ${#TARGETS[@]} ))
[ "$per" -ge 1 ] || per=1
status=0
printf '%-10s %10s %8s %8s %8s %s\n' target execs exec/s cov ft result > "$OUT/summary.txt"
for t in "${TARGETS[@]}"; do
  mkdir -p "$OUT/corpus/$t" "$OUT/artifacts/$t"
  log="$OUT/$t.log"
  echo "fuzz: $t for ${per}s"
  set +e
  "$OUT/bin/fuzz_$t" -max_total_time="$per" -print_final_stats=1 -rss_limit_mb=2048 -timeout=10 \
    -artifact_prefix="$OUT/artifacts/$t/" "$OUT/corpus/$t" "$ROOT/tests/fuzz/corpus/$t" > "$log" 2>&1
  rc=$?
  set -e
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || true)
  rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$log" | grep -o '[0-9]*$' || true)
  last=$(grep -E '^#[0-9]+' "$log" | grep -E 'cov: ' | tail -1 || true)
  cov=$(echo "$last" | grep -o 'cov: [0-9]*' | grep -o '[0-9]*' || true)
  ft=$(echo "$last" | grep -o 'ft: [0-9]*' | grep -o '[0-9]*' || true)
  result=ok
  if [ $rc -ne 0 ]; then result="CRASH (see $log, $OUT/artifacts/$t/)"; status=1; fi
  printf '%-10s %10s %8s %8s %8s %s\n' "$t" "${execs:-?}" "${rate:-?}" "${cov:-?}" "${ft:-?}" "$result" >> "$OUT/summary.txt"
done
cat "$OUT/summary.txt"
exit $status
