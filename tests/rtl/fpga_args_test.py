#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""ctest fpga_args: scripts/fpga.py rejects bad arguments with exit 2 and a message naming the
argument and its allowed values, before running any tool and without writing anything (its
--out folder is not created). No tool runs here.

usage: fpga_args_test.py SCRATCH_DIR"""
import os
import re
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FPGA = os.path.join(ROOT, "scripts", "fpga.py")

CASES = [
    (r"--device must be one of hx8k, up5k, ecp5, ecp5-25, ecp5-45, ecp5-85, all, or a comma-separated list of "
     r"them \(got 'virtex7'\)", ["--device", "virtex7"]),
    (r"--top must be one of unit, stream, axil, phong, setup, system, mul, all \(got 'core'\)", ["--top", "core"]),
    (r"--device must be one of .* \(got 'hx8k,ecp6'\)", ["--top", "setup", "--device", "hx8k,ecp6"]),
    (r"--device must be one of .* \(got 'ecp5-12'\)", ["--device", "ecp5-12"]),
    (r"--seed must be a non-negative integer \(got 'abc'\)", ["--top", "phong", "--phong-config", "all", "--seed", "abc"]),
    (r"--phong-config must be all or one of n1000,n128,.* \(got 'n7'\)", ["--top", "phong", "--phong-config", "n7"]),
    (r"--phong-config needs --top phong \(got --top setup\)", ["--top", "setup", "--phong-config", "n64"]),
    (r"--param must be NAME=VALUE", ["--param", "CosAddrBits"]),
    (r"--param name must be a Verilog identifier", ["--param", "9x=1"]),
    (r"--param CosAddrBits has an empty value", ["--param", "CosAddrBits="]),
    (r"string value must not contain quotes", ["--param", 'CosRomFile=a"b']),
    (r"--seed must be a non-negative integer", ["--seed", "abc"]),
    (r"--yosys-timeout must be a whole number of seconds, 0 for no limit \(got '1h'\)",
     ["--top", "setup", "--yosys-timeout", "1h"]),
    (r"must be a positive number of MHz", ["--freq-hx8k", "0"]),
    (r"must be a positive number of MHz \(got 'fast'\)", ["--freq-ecp5", "fast"]),
    (r"--out needs a value", ["--out"]),
    (r"--setup-ii must be a positive whole number \(got 'x'", ["--top", "setup", "--setup-ii", "x"]),
    (r"--setup-ii needs --top setup or system \(got --top stream\)", ["--top", "stream", "--setup-ii", "2"]),
    (r"--label must be letters, digits and _ \(got 'b1 n64'\)", ["--top", "stream", "--label", "b1 n64"]),
    (r"--label must not be 'default'", ["--top", "stream", "--label", "default"]),
    (r"--label and --phong-config both name the configuration: give one \(got --label x --phong-config n64\)",
     ["--top", "phong", "--phong-config", "n64", "--label", "x"]),
    (r"--label needs a value", ["--top", "stream", "--label"]),
    (r"--record with --param CosAddrBits needs --label NAME", ["--top", "stream", "--param", "CosAddrBits=7", "--record"]),
    (r"--record with --param CoefBits needs --label NAME",
     ["--top", "stream", "--record", "--param", "MulTileBits=0", "--param", "CoefBits=20"]),
    (r"unknown argument '--bogus' \(allowed: .*--flatten, --no-flatten", ["--bogus"]),
    (r"unknown argument .*--setup-ii, --label, --record\)", ["--bogus"]),
    (r"unknown argument '--fla'", ["--fla"]),  # no abbreviations
]


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    scratch = sys.argv[1]
    shutil.rmtree(scratch, ignore_errors=True)
    fail = 0
    env = dict(os.environ)
    env.pop("FPGA_PARAMS", None)
    for want, args in CASES:
        out = os.path.join(scratch, "out")
        p = subprocess.run([sys.executable, FPGA] + args + ["--out", out] * ("--out" not in args),
                           capture_output=True, text=True, env=env, cwd=ROOT)
        shown = " ".join(args)
        if p.returncode != 2 or not re.search(want, p.stderr):
            print(f"FAIL: fpga.py {shown} -> exit {p.returncode} (want 2), stderr: {p.stderr.strip()}")
            fail += 1
        elif os.path.exists(out):
            print(f"FAIL: fpga.py {shown} -> exit 2 but it created {out}")
            fail += 1
        else:
            print(f"ok: fpga.py {shown} -> exit 2: {p.stderr.splitlines()[0]}")
    # FPGA_PARAMS is checked as --param is.
    p = subprocess.run([sys.executable, FPGA, "--out", os.path.join(scratch, "out")], capture_output=True, text=True,
                       env=dict(env, FPGA_PARAMS="CosAddrBits=7 bad"), cwd=ROOT)
    if p.returncode != 2 or "--param must be NAME=VALUE (got 'bad')" not in p.stderr:
        print(f"FAIL: FPGA_PARAMS='CosAddrBits=7 bad' -> exit {p.returncode}, stderr: {p.stderr.strip()}")
        fail += 1
    else:
        print("ok: FPGA_PARAMS='CosAddrBits=7 bad' -> exit 2")
    print(f"fpga_args: {len(CASES) + 1 - fail} of {len(CASES) + 1} checks hold: " + ("FAIL" if fail else "PASS"))
    return 1 if fail else 0


if __name__ == "__main__":
    sys.exit(main())
