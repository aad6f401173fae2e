#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Per-file summary of Verilator coverage (make coverage, rtl/README.md).

Reads a Verilator coverage file (SystemC::Coverage-3, e.g. the merge of every model's .dat
that `verilator_coverage --write` produces) and prints, per rtl/ file, line, branch and
toggle coverage:

  line    Verilator `v_line` points: every statement block (`block`), `elsif` and `case` arm;
  branch  `v_branch` points: the `if` and the `else` arm of every if statement (Verilator
          5.006 has no expression coverage);
  toggle  `v_toggle` points: each bit of each signal (counted when it toggled at least once).

A point is a source location (file, line, column, kind, comment): the instances of a module
and the hardware configurations (default, patent, banks4-interp, interp128, the stream) are
merged, so a point is covered when any instance of any configuration reached it.

Waivers (sim/coverage_waivers.txt): uncovered line and branch points that cannot be reached,
one per line, `FILE:LINE KIND[:COMMENT] reason`, KIND `line` or `branch`, COMMENT optional
(`if`, `else`, `block`, `elsif`, `case`, ...). With --check the script fails when a line or
branch point is neither covered nor waived, or when a waiver matches no uncovered point (it
is stale). Toggle coverage is reported, not checked.

  coverage_summary.py MERGED.dat --waivers sim/coverage_waivers.txt --out summary.md [--check]
"""
import argparse
import os
import re
import sys
from collections import defaultdict

KINDS = ("line", "branch", "toggle")


def parse_dat(path, root):
    """{(file, line, col, kind, comment): count}, counts summed over instances."""
    points = defaultdict(int)
    with open(path, encoding="utf-8", errors="replace") as f:
        for raw in f:
            if not raw.startswith("C '"):
                continue
            body, _, count = raw.rstrip("\n").rpartition("' ")
            fields = {}
            for item in body[3:].split("\x01"):
                if "\x02" in item:
                    k, v = item.split("\x02", 1)
                    fields[k] = v
            page = fields.get("page", "")
            kind = {"v_line": "line", "v_branch": "branch", "v_toggle": "toggle"}.get(page.split("/")[0])
            if kind is None:
                continue
            fname = fields.get("f", "")
            if os.path.isabs(fname):
                fname = os.path.relpath(fname, root)
            key = (fname, int(fields.get("l", 0)), int(fields.get("n", 0)), kind, fields.get("o", ""))
            points[key] += int(count)
    return points


def parse_waivers(path):
    waivers = []
    if not path or not os.path.exists(path):
        return waivers
    with open(path, encoding="utf-8") as f:
        for no, raw in enumerate(f, 1):
            s = raw.strip()
            if not s or s.startswith("#"):
                continue
            m = re.match(r"^(\S+):(\d+)\s+(line|branch)(?::(\S+))?\s+(.+)$", s)
            if not m:
                sys.exit(f"{path}:{no}: expected 'FILE:LINE line|branch[:COMMENT] reason', got: {s}")
            waivers.append({"file": m.group(1), "line": int(m.group(2)), "kind": m.group(3),
                            "comment": m.group(4), "reason": m.group(5), "where": f"{path}:{no}", "used": 0})
    return waivers


def waiver_for(key, waivers):
    fname, line, _, kind, comment = key
    for w in waivers:
        if w["file"] == fname and w["line"] == line and w["kind"] == kind and w["comment"] in (None, comment):
            return w
    return None


def pct(a, b):
    return f"{100.0 * a / b:.1f} %" if b else "-"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dat", help="merged coverage .dat")
    ap.add_argument("--waivers", default="sim/coverage_waivers.txt")
    ap.add_argument("--root", default=".", help="repository root (file names are printed relative to it)")
    ap.add_argument("--out", help="also write the summary as markdown to this file")
    ap.add_argument("--check", action="store_true", help="fail on uncovered unwaived line/branch points or stale waivers")
    args = ap.parse_args()

    points = parse_dat(args.dat, os.path.abspath(args.root))
    waivers = parse_waivers(args.waivers)
    files = sorted({k[0] for k in points})
    total = {f: {k: 0 for k in KINDS} for f in files}
    hit = {f: {k: 0 for k in KINDS} for f in files}
    waived = {f: {k: 0 for k in KINDS} for f in files}
    open_points, waived_points, cold_toggles = [], [], []
    for key, count in sorted(points.items()):
        fname, _, _, kind, _ = key
        total[fname][kind] += 1
        if count > 0:
            hit[fname][kind] += 1
            continue
        if kind == "toggle":
            cold_toggles.append(key)
            continue
        w = waiver_for(key, waivers)
        if w:
            w["used"] += 1
            waived[fname][kind] += 1
            waived_points.append((key, w))
        else:
            open_points.append(key)

    lines = ["# RTL coverage (Verilator 5.006, every configuration merged)", ""]
    lines.append(f"Source: `{args.dat}`; waivers: `{args.waivers}` ({len(waivers)}).")
    lines.append("Line = statement blocks and `elsif`/`case` arms, branch = `if`/`else` arms, toggle = bits that "
                 "toggled; \"after waivers\" counts waived unreachable points as covered.")
    lines.append("")
    lines.append("| file | line | branch | toggle | line after waivers | branch after waivers |")
    lines.append("|---|---|---|---|---|---|")
    sums = {k: [0, 0, 0] for k in KINDS}
    for f in files:
        cells = []
        for k in KINDS:
            cells.append(f"{hit[f][k]}/{total[f][k]} ({pct(hit[f][k], total[f][k])})")
            sums[k][0] += hit[f][k]
            sums[k][1] += total[f][k]
            sums[k][2] += waived[f][k]
        for k in ("line", "branch"):
            cells.append(pct(hit[f][k] + waived[f][k], total[f][k]))
        lines.append(f"| `{f}` | " + " | ".join(cells) + " |")
    cells = [f"{sums[k][0]}/{sums[k][1]} ({pct(sums[k][0], sums[k][1])})" for k in KINDS]
    cells += [pct(sums[k][0] + sums[k][2], sums[k][1]) for k in ("line", "branch")]
    lines.append("| **all** | " + " | ".join(cells) + " |")
    lines.append("")
    if waived_points:
        lines.append(f"Waived (unreachable) line/branch points: {len(waived_points)}")
        lines.append("")
        for (fname, line, col, kind, comment), w in waived_points:
            lines.append(f"- `{fname}:{line}:{col}` {kind} `{comment}`: {w['reason']}")
        lines.append("")
    stale = [w for w in waivers if not w["used"]]
    if open_points:
        lines.append(f"**Uncovered line/branch points without a waiver: {len(open_points)}**")
        lines.append("")
        for fname, line, col, kind, comment in open_points:
            lines.append(f"- `{fname}:{line}:{col}` {kind} `{comment}`")
        lines.append("")
    if stale:
        lines.append(f"**Stale waivers (no uncovered point matches): {len(stale)}**")
        lines.append("")
        for w in stale:
            lines.append(f"- {w['where']}: `{w['file']}:{w['line']}` {w['kind']}")
        lines.append("")
    if cold_toggles:
        lines.append(f"Bits that never toggled (reported, not checked; reasons in sim/README.md): {len(cold_toggles)}")
        lines.append("")
        for fname, line, col, kind, comment in cold_toggles:
            lines.append(f"- `{fname}:{line}` `{comment}`")
        lines.append("")
    text = "\n".join(lines)
    print(text)
    if args.out:
        with open(args.out + ".tmp", "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(args.out + ".tmp", args.out)
    if args.check and (open_points or stale):
        print(f"coverage: FAIL ({len(open_points)} uncovered unwaived points, {len(stale)} stale waivers)")
        return 1
    if args.check:
        print("coverage: PASS (100 % line and branch coverage of rtl/ after waivers)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
