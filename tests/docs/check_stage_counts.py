#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""ctest docs_stage_counts (docs/pipeline.md#stage-counts).

  check_stage_counts.py --sim SIM_REGRESSION --root ROOT [--update | --self-test]

1. The table between the stage-table markers of docs/pipeline.md must equal what
   `sim_regression --stage-table` prints (the stage counts of rtl/prim/specular_pkg.sv at every
   configuration's widths). --update rewrites the table instead (make stage-table).
2. No document, RTL source, testbench or script may write a latency, a pipeline depth or a
   stage range as a number: they cite docs/pipeline.md#stage-counts or read the package.
   Each hit is reported as FILE:LINE: text.

--self-test copies docs/pipeline.md into a temporary tree with one figure of the table
changed and a document that writes a latency as a number, and passes only if the check
reports both.
Exit 0 when both hold, 1 otherwise, 2 on bad arguments.
"""
import argparse
import re
import subprocess
import sys
from pathlib import Path

BEGIN = "<!-- stage-table:"
END = "<!-- end stage-table -->"

# Hand-written copies of a stage count. Each pattern is a way the documents used to write
# one; the numbers below 10 in `l + N` are pixel counts (l + 1 pixels), not latencies, and
# s+1 is the cycle after a start. Parameter declarations are skipped: a block's default (the
# control unit's PipeDepth for its block test, the formal harness's Latency, which the
# script sets from the netlist) is not a figure of the pipeline.
COPIES = [
    (re.compile(r"\bL\s*=\s*\d+"), "a latency L written as a number"),
    (re.compile(r"\b[Ll]atency\b\s*(?:=|:|of|is)?\s*\(?\d+"), "a latency written as a number"),
    (re.compile(r"\b\d+[- ]clock (?:fill|latency)"), "a latency written as a number"),
    (re.compile(r"\b\d+ clocks? (?:after the start|from (?:the )?start)"), "a latency written as a number"),
    (re.compile(r"\bPipeDepth\s*=\s*\d+"), "a pipeline depth written as a number"),
    (re.compile(r"\b\d+ pipeline stages"), "a pipeline depth written as a number"),
    (re.compile(r"\(\d+ stages?\)"), "a block's stage count written as a number"),
    (re.compile(r"\b[ts]\s*\+\s*\d+\s*\+\s*[il]\b"), "a cycle offset written as a number"),
    (re.compile(r"\bs\+(?:[2-9]|\d\d+)"), "a cycle offset written as a number"),
    (re.compile(r"\bl\s*\+\s*[1-9]\d+\b"), "a line's clocks written as a number"),
    (re.compile(r"\bstages? \d+ *\.\. *\d+"), "a stage range written as numbers"),
]

# Every text a reader sees, the harnesses under rtl/ included (so not the filelists alone).
SCAN = ["*.md", "docs/*.md", "rtl/**/*.md", "sim/*.md", "roms/*.md", "scenes/*.md",
        "tests/*/*.md", "rtl/**/*.sv", "rtl/**/*.svh", "sim/*.sv", "sim/*.cpp",
        "sim/*.hpp", "tests/*/*.cpp", "tests/*/*.hpp", "scripts/*.sh", "scripts/*.py"]


def table_block(text, path):
    lines = text.split("\n")
    try:
        b = next(i for i, l in enumerate(lines) if l.startswith(BEGIN))
        e = next(i for i, l in enumerate(lines) if l.strip() == END and i > b)
    except StopIteration:
        sys.exit(f"{path}: no stage table between '{BEGIN} ...' and '{END}'")
    return lines, b, e


def check(sim, root, update=False):
    """Both checks on the tree at root; returns (table ok, number of copies)."""
    doc = root / "docs" / "pipeline.md"
    table_ok = True
    got = subprocess.run([sim, "--stage-table"], check=True, capture_output=True, text=True).stdout
    lines, b, e = table_block(doc.read_text(), doc)
    want = got.rstrip("\n").split("\n")
    if update:
        doc.write_text("\n".join(lines[: b + 1] + want + lines[e:]))
        print(f"rewrote the stage table of {doc}")
    elif lines[b + 1 : e] != want:
        print(f"{doc}: the stage table differs from `sim_regression --stage-table` (run `make stage-table`):")
        print("  in the document:\n    " + "\n    ".join(lines[b + 1 : e]))
        print("  from rtl/prim/specular_pkg.sv:\n    " + "\n    ".join(want))
        table_ok = False
    return table_ok, copies(root)


def copies(root):
    hits = 0
    for pattern in SCAN:
        for f in sorted(root.glob(pattern)):
            if "build" in f.relative_to(root).parts[0]:
                continue
            inside = False
            for n, line in enumerate(f.read_text(errors="replace").split("\n"), 1):
                if line.startswith(BEGIN):
                    inside = True
                if inside:
                    inside = line.strip() != END
                    continue
                if re.match(r"\s*parameter\b", line):
                    continue
                for rx, what in COPIES:
                    m = rx.search(line)
                    if m:
                        print(f"{f.relative_to(root)}:{n}: '{m.group(0)}': {what}; cite "
                              "docs/pipeline.md#stage-counts or take it from rtl/prim/specular_pkg.sv")
                        hits += 1
                        break
    return hits


def self_test(sim, root):
    import tempfile
    with tempfile.TemporaryDirectory() as t:
        t = Path(t)
        (t / "docs").mkdir()
        text = (root / "docs" / "pipeline.md").read_text()
        lines, b, e = table_block(text, "docs/pipeline.md")
        if e <= b + 3:
            print("self-test: the table has no rows")
            return 1
        row = lines[b + 3].split("|")
        row[-3] = " " + str(int(row[-3]) + 1) + " "  # L one clock more
        lines[b + 3] = "|".join(row)
        (t / "docs" / "pipeline.md").write_text("\n".join(lines))
        (t / "docs" / "copy.md").write_text("Pixel 0 appears 23 clocks after the start.\n")
        table_ok, hits = check(sim, t)
        if table_ok or hits != 1:
            print(f"self-test FAILED: table mismatch found: {not table_ok}, copies found: {hits} (want 1)")
            return 1
    print("self-test: the changed figure and the copy were both reported")
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("--sim", required=True, help="the sim_regression executable")
    ap.add_argument("--root", required=True, help="the repository root")
    ap.add_argument("--update", action="store_true", help="rewrite docs/pipeline.md's table")
    ap.add_argument("--only-copies", action="store_true", help="only look for hand-written copies (no sim_regression needed)")
    ap.add_argument("--self-test", action="store_true", help="check that the checker finds what it should")
    a = ap.parse_args()
    root = Path(a.root)
    if a.self_test:
        return self_test(a.sim, root)
    if a.only_copies:
        table_ok, hits = True, copies(root)
    else:
        table_ok, hits = check(a.sim, root, a.update)
    ok = table_ok and hits == 0
    print("stage counts: " + ("ok" if ok else f"FAILED ({hits} hand-written copies)"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
