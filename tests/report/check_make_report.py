#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Smoke test of scripts/make_report.py: run it in --smoke mode (report_data only, a coarse
n grid) and cross-check the tables of report.md against the report_data.json it read.
Every expected cell is recomputed here from the JSON, not taken from make_report.py.

  check_make_report.py --build BUILD [--out DIR]   run make_report.py, then check
  check_make_report.py --check-only DIR            check an existing DIR/report.md
Exit 0 when every table agrees with the JSON, 1 otherwise (one line per mismatch).
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def val(v):
    return float(v)  # report_data writes non-finite numbers as "inf" / "nan" strings


def pct(v):
    if math.isinf(v):
        return "unbounded"
    return f"{100 * v:.3g} %"


def table_rows(md):
    """Markdown table rows as lists of stripped cells."""
    rows = []
    for line in md.splitlines():
        if line.startswith("|") and not line.startswith("|---"):
            rows.append([c.strip() for c in line.strip().strip("|").split("|")])
    return rows


def check(out):
    errors = []
    with open(os.path.join(out, "report_data.json")) as f:
        data = json.load(f)
    with open(os.path.join(out, "report.md")) as f:
        md = f.read()
    rows = table_rows(md)

    # Hardware configurations: one row per JSON config, every model-side cell recomputed.
    hw = data["hardware"]
    if not hw:
        errors.append("report_data.json has no hardware configurations")
    for h in hw:
        mine = [r for r in rows if r and r[0] == h["name"]]
        if len(mine) != 1:
            errors.append(f"hardware {h['name']}: {len(mine)} table rows, expected 1")
            continue
        r = mine[0]
        rel = [val(v) for v in h["max_rel_epicenter"]]
        ab = [val(v) for v in h["max_abs_lobe"]]
        want = {
            1: f"{'interp' if h['cos_interp'] else 'direct'} {h['cos_addr_bits']}/{h['cos_data_bits']}",
            2: h["policy"],
            3: "{" + ",".join(map(str, h["banks"])) + "} (" + ",".join(map(str, h["bank_max_n"])) + ")",
            4: f"{h['coef_rom_bits'] + h['cos_rom_bits']} ({h['coef_rom_bits']} + {h['cos_rom_bits']})",
            5: pct(max(rel)),
            6: pct(max(val(v) for v in h["max_rel_epicenter_lsb"])),
        }
        for col, w in want.items():
            if r[col] != w:
                errors.append(f"hardware {h['name']} column {col}: report '{r[col]}', JSON gives '{w}'")
        if f"{max(ab):.3g}" not in r:
            errors.append(f"hardware {h['name']}: worst abs. lobe {max(ab):.3g} (JSON) not in the row {r}")
        # ROM 12 bits from the configuration itself (banks x 2^addr x word: the value with its
        # integer bit and the step when interpolated, the saturating value when direct), not
        # from the JSON's own sums; ROM 9 has 2^10 words (n up to 1000) of a whole number of bits.
        word = h["cos_data_bits"] + 1 + h["cos_delta_bits"] if h["cos_interp"] else h["cos_data_bits"]
        cos_bits = len(h["banks"]) * (1 << h["cos_addr_bits"]) * word
        if h["cos_rom_bits"] != cos_bits or h["coef_rom_bits"] % 1024 != 0:
            errors.append(f"hardware {h['name']}: ROM bits {h['coef_rom_bits']} + {h['cos_rom_bits']}, "
                          f"formats give 1024 x w + {cos_bits}")

    # The published-claims line of the patent: the worst of the JSON's patent evaluator.
    ev = {e["name"]: e for e in data["evaluators"]}
    for name, label in (("patent", "Patent (k in {1,2,4,16}, maclaurin a"),):
        worst = max(val(v) for v in ev[name]["max_rel_epicenter"])
        line = next((l for l in md.splitlines() if label in l), None)
        if line is None:
            errors.append(f"claims: no line for {name}")
        elif f"measured worst {pct(worst)}" not in line:
            errors.append(f"claims: {name} worst {pct(worst)} (JSON) not in '{line}'")
        elif ("holds" if worst <= 0.01 else "does NOT hold") not in line:
            errors.append(f"claims: {name} verdict does not follow from {worst}")

    # Albedo table: every printed value equals the JSON value at that n (3 decimals).
    header = next((r for r in rows if r[:2] == ["series", "convention"]), None)
    if header is None:
        errors.append("albedo table missing")
    else:
        ns = [int(c.split("=")[1]) for c in header[2:]]
        checked = 0
        for s in data["albedo"]:
            for conv in ("phong", "blinn"):
                r = next((r for r in rows if r[:2] == [s["name"], conv]), None)
                if r is None:
                    errors.append(f"albedo row {s['name']} / {conv} missing")
                    continue
                m = dict(zip(s["n"], s[conv]))
                for n, cell in zip(ns, r[2:]):
                    want = f"{val(m[n]):.3f}" if n in m else ""
                    checked += 1
                    if cell != want:
                        errors.append(f"albedo {s['name']} {conv} n={n}: report '{cell}', JSON '{want}'")
        if checked == 0:
            errors.append("albedo table: nothing compared")
    return errors


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build")
    ap.add_argument("--out")
    ap.add_argument("--check-only")
    a = ap.parse_args()
    if a.check_only:
        out = a.check_only
    else:
        out = a.out or tempfile.mkdtemp(prefix="make_report_smoke_")
        p = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "make_report.py"), "--build", a.build,
                            "--out", out, "--smoke", "--n-step", "111"], cwd=ROOT)
        if p.returncode != 0:
            print(f"make_report.py --smoke failed with exit code {p.returncode}")
            return 1
    errors = check(out)
    for e in errors:
        print(e)
    print(f"{len(errors)} mismatches between {out}/report.md and report_data.json")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
