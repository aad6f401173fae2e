#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""The report's reading of evaluator_bench, on a real run (docs/speed_error.md#the-cost-axis).

Runs BUILD/bin/evaluator_bench briefly (a filter that keeps a few per-pixel evaluators and every
scanline-setup benchmark) with the options scripts/make_report.py uses, then hands its JSON to
make_report.parse_bench and checks, for every median in the file, that it was read as the
benchmark's name says: "<evaluator>/<n>" as ns per pixel, a plain name as ns per span, each
equal to 1e9 / items_per_second as the file states it. A benchmark name the parser cannot read
fails here rather than in `make report`. Also checks that a name of neither form is refused.

  check_bench_parse.py --bench BUILD/bin/evaluator_bench [--json FILE]
Exit 0 when all agree, 1 otherwise (one line per disagreement).
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import make_report  # noqa: E402

# Two per-pixel evaluators at the report's first n, and every setup benchmark (plain names).
FILTER = rf"^(pow|device_simd)/{make_report.BENCH_NS[0]}$|^setup_"


def check(data):
    errors = []
    try:
        per_pixel, per_span = make_report.parse_bench(data)
    except ValueError as e:
        return [f"parse_bench refused a real evaluator_bench run: {e}"]
    medians = [b for b in data["benchmarks"] if b.get("aggregate_name") == "median"]
    if not medians:
        errors.append("the evaluator_bench run has no median entries (filter matched nothing?)")
    plain = [b for b in medians if "/" not in b["run_name"]]
    if not any(b["run_name"] == "setup_scalar" for b in plain):
        errors.append("the run has no setup_scalar benchmark: the check would not cover plain names")
    if len(plain) == len(medians):
        errors.append("the run has no '<evaluator>/<n>' benchmark: the check would not cover them")
    for b in medians:
        name = b["run_name"]
        want = 1e9 / b["items_per_second"]
        if "/" in name:
            ev, n = name.split("/")
            got = per_pixel.get(ev, {}).get(int(n))
        else:
            got = per_span.get(name)
        if got is None:
            errors.append(f"{name}: missing from parse_bench's result")
        elif abs(got - want) > 1e-9 * want:
            errors.append(f"{name}: read {got} ns, the file says {want} ns")
    count = sum(len(v) for v in per_pixel.values()) + len(per_span)
    if count != len(medians):
        errors.append(f"parse_bench returned {count} entries for {len(medians)} medians")
    # A name of neither form must be refused, naming it.
    bad = {"benchmarks": [{"run_name": "pow/x/3", "aggregate_name": "median", "items_per_second": 1.0}]}
    try:
        make_report.parse_bench(bad)
        errors.append("parse_bench accepted the malformed name 'pow/x/3'")
    except ValueError as e:
        if "pow/x/3" not in str(e):
            errors.append(f"parse_bench's error does not name the benchmark: {e}")
    return errors


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bench", required=True, help="path of evaluator_bench")
    ap.add_argument("--json", help="keep the run's JSON here (default: a temporary file)")
    args = ap.parse_args()
    if not os.access(args.bench, os.X_OK):
        print(f"check_bench_parse.py: --bench '{args.bench}' is not an executable", file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory() as tmp:
        path = args.json or os.path.join(tmp, "bench.json")
        cmd = [args.bench] + make_report.bench_args(path, min_time=0.002, repetitions=2, filt=FILTER)
        p = subprocess.run(cmd, capture_output=True, text=True)
        if p.returncode != 0:
            print(f"evaluator_bench failed (exit {p.returncode}):\n{p.stderr}", file=sys.stderr)
            return 1
        with open(path) as f:
            data = json.load(f)
    errors = check(data)
    for e in errors:
        print(e)
    n = len([b for b in data["benchmarks"] if b.get("aggregate_name") == "median"])
    print(f"{n} benchmarks checked: " + ("FAIL" if errors else "PASS"))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
