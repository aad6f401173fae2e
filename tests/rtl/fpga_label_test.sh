#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# ctest fpga_label: a run of scripts/fpga.sh with --param and --label is an entry of its own in
# docs/fpga_figures.json, beside the default configuration's, never in its place
# (rtl/fpga/README.md#how-to-run). The lone 16 x 16 multiplier (--top mul) is placed and
# routed on the HX8K twice, with its defaults and with --param MulBits=12 --label narrow, and
# each run's figures_entries.json is recorded by scripts/fpga_record.py into a copy of
# docs/fpga_figures.json. Fails when the labelled run's entry has no "config", when it
# replaced or changed the default configuration's entry, or when the two do not differ.
# (A run on modified RTL is refused by fpga_record.py, tested by docs_fpga_record; here its
# "-modified" commit suffix is dropped so that the test also runs in a working tree.)
set -u
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
out=${1:?usage: fpga_label_test.sh OUT_DIR}
rm -rf "$out"
mkdir -p "$out"
cp "$root/docs/fpga_figures.json" "$out/figures.json"

record() {  # record OUT_SUBDIR: its figures_entries.json into the copy
  sed 's/-modified"/"/g' "$out/$1/figures_entries.json" > "$out/$1/entries.json"
  /usr/bin/python3 "$root/scripts/fpga_record.py" "$out/$1/entries.json" --figures "$out/figures.json" ||
    { echo "FAIL: fpga_record.py on the $1 run"; exit 1; }
}

bash "$root/scripts/fpga.sh" --top mul --device hx8k --fresh --out "$out/default" ||
  { echo "FAIL: fpga.sh --top mul --device hx8k"; exit 1; }
record default
cp "$out/figures.json" "$out/after_default.json"
bash "$root/scripts/fpga.sh" --top mul --device hx8k --fresh --param MulBits=12 --label narrow --out "$out/narrow" ||
  { echo "FAIL: fpga.sh --top mul --device hx8k --param MulBits=12 --label narrow"; exit 1; }
[ -f "$out/narrow/mul_narrow_hx8k/result.json" ] ||
  { echo "FAIL: the labelled run's folder is not mul_narrow_hx8k/"; exit 1; }
record narrow

/usr/bin/python3 - "$out" <<'PY'
import json, os, sys
out = sys.argv[1]
before = json.load(open(os.path.join(out, "after_default.json")))
after = json.load(open(os.path.join(out, "figures.json")))
entries = json.load(open(os.path.join(out, "narrow", "figures_entries.json")))
fail = []
if [e.get("config") for e in entries] != ["narrow"]:
    fail.append(f"the labelled run's figures_entries.json: config {[e.get('config') for e in entries]}, want ['narrow']")

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
others = [e for e in after["runs"] if e["core"] != "specular_pipe_mul"]
if others != [e for e in before["runs"] if e["core"] != "specular_pipe_mul"]:
    fail.append("the record changed entries of other cores")
for f in fail:
    print("FAIL: " + f)
if not fail:
    print(f"ok: default entry kept ({d1[0]['sb_lut4']} SB_LUT4), labelled entry 'narrow' beside it "
          f"({l1[0]['sb_lut4']} SB_LUT4)")
sys.exit(1 if fail else 0)
PY
