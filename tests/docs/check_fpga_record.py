#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""scripts/fpga_record.py (fpga.py --record) and the committed docs/fpga_figures.json.

1. The committed file: every entry names its core, part, RTL commit, date, tools and
   synthesis command (the FPGA-flow contract of rtl/fpga/README.md#measured), no entry was
   run on modified RTL, no two entries of a section share a key (core, configuration,
   SetupII, part, multiplier style), and the file is in the one-entry-a-line form that
   fpga_record.py writes (so a record changes only the lines of the runs it records).
2. On a copy: an entry with an existing key replaces it, a new key is appended to the
   section of its shape (iCE40 placed, ECP5 placed, synthesis only); an entry on modified
   RTL or without its tools is refused with exit 1, naming it, and the file is unchanged.
Exit 0 when all hold, 1 otherwise.
"""
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import fpga_record  # noqa: E402

FIGURES = os.path.join(ROOT, "docs", "fpga_figures.json")
SECTIONS = ("runs", "ecp5_runs", "synthesis_runs")


def committed(fail):
    with open(FIGURES) as f:
        text = f.read()
    d = json.loads(text)
    for sec in SECTIONS:
        seen = set()
        for e in d.get(sec, []):
            name = f"{sec}: {e.get('core')} {e.get('config', '')} {e.get('part')}"
            for k in fpga_record.NEEDED:
                if not e.get(k):
                    fail(f"{name} has no {k}")
            if str(e.get("rtl", "")).endswith("-modified"):
                fail(f"{name} was run on modified RTL")
            if fpga_record.section(e) != sec:
                fail(f"{name} is in {sec}, its shape belongs in {fpga_record.section(e)}")
            k = fpga_record.key(e)
            if k in seen:
                fail(f"{name}: two entries with the key {k}")
            seen.add(k)
    if fpga_record.dump(d) != text:
        fail("docs/fpga_figures.json is not in the form scripts/fpga_record.py writes")


def run_record(figures, entries):
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(entries, f)
    try:
        p = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "fpga_record.py"), f.name,
                            "--figures", figures], capture_output=True, text=True)
    finally:
        os.remove(f.name)
    return p.returncode, p.stdout + p.stderr


def copy_cases(fail):
    base = {"provenance": {"machine": "m"}, "about": "a",
            "runs": [{"core": "specular_stream", "part": "UP5K sg48", "rtl": "aaaaaaa", "date": "2026-01-01",
                      "tools": "Yosys 0.23, nextpnr-ice40 0.4", "synthesis": "synth_ice40 -dsp",
                      "multipliers": "SB_MAC16 tiles (16-bit)", "lcs": 1}],
            "ecp5_runs": [], "synthesis_runs": []}
    same = dict(base["runs"][0], rtl="bbbbbbb", lcs=2)
    other_style = dict(base["runs"][0], multipliers="LUT trees", lcs=3)
    ecp5 = {"core": "phong_stream", "config": "n64", "part": "LFE5U-45F CABGA381 -6", "rtl": "bbbbbbb",
            "date": "2026-01-02", "tools": "Yosys 0.23, nextpnr-ecp5 0.11", "synthesis": "synth_ecp5",
            "multipliers": "MULT18X18D tiles (18-bit)"}
    syn = {"core": "specular_setup", "setup_ii": 8, "part": "ECP5", "rtl": "bbbbbbb", "date": "2026-01-03",
           "tools": "Yosys 0.23", "synthesis": "synth_ecp5 -noflatten", "synthesis_only": True}
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "fig.json")
        with open(path, "w") as f:
            f.write(fpga_record.dump(base))
        rc, out = run_record(path, [same, other_style, ecp5, syn])
        d = json.load(open(path))
        if rc != 0:
            fail(f"record of four good entries: exit {rc}: {out}")
        if [e["lcs"] for e in d["runs"]] != [2, 3]:
            fail(f"runs after the record: {d['runs']} (the same key replaced, the other style appended)")
        if d["ecp5_runs"] != [ecp5] or d["synthesis_runs"] != [syn]:
            fail(f"ecp5_runs / synthesis_runs after the record: {d['ecp5_runs']} / {d['synthesis_runs']}")
        before = open(path).read()
        for bad, word in ((dict(ecp5, rtl="ccccccc-modified"), "modified"),
                          ({k: v for k, v in ecp5.items() if k != "tools"}, "tools")):
            rc, out = run_record(path, [dict(same, lcs=9), bad])
            if rc != 1 or word not in out:
                fail(f"an entry with {word!r} wrong: exit {rc}, message {out!r}")
            if open(path).read() != before:
                fail(f"a refused record ({word}) changed the file")


def main():
    errors = []
    committed(errors.append)
    copy_cases(errors.append)
    for e in errors:
        print("FAIL " + e)
    print("check_fpga_record: " + ("FAIL" if errors else "OK"))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
