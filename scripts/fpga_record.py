#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Record the runs of scripts/fpga.sh in docs/fpga_figures.json (rtl/fpga/README.md#measured).

    scripts/fpga_record.py OUT_DIR/figures_entries.json [...] [--figures docs/fpga_figures.json]

Each entry of a figures_entries.json (written by every fpga.sh run, with its date, tools and
the commit of the RTL) goes into the section of its shape: a placed iCE40 run into "runs", a
placed ECP5 run into "ecp5_runs", a run whose counts exceed the part into "synthesis_runs". It
replaces the entry of the same core, configuration, SetupII, part and multiplier style there,
or is appended. An entry whose RTL commit ends in "-modified" (rtl/ differed from the commit
when the run started) is refused: commit the RTL, re-run, then record. Exit 0 when recorded,
1 when an entry is refused or malformed (the figures file is then left as it was), 2 on bad
arguments.
"""
import argparse
import json
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NEEDED = ("core", "part", "rtl", "date", "tools", "synthesis")


def section(e):
    if e.get("synthesis_only"):
        return "synthesis_runs"
    return "ecp5_runs" if e["part"].startswith("LFE5U") else "runs"


def key(e):
    # An ECP5 entry without "multipliers" predates the field: its runs used MULT18X18D tiles.
    default = "MULT18X18D tiles (18-bit)" if section(e) == "ecp5_runs" else None
    return (e["core"], e.get("config"), e.get("setup_ii", 1), e["part"], e.get("multipliers", default))


def merge(figures, entries):
    """figures with entries merged in (a new dict); raises ValueError on a refused entry."""
    out = json.loads(json.dumps(figures))
    for e in entries:
        missing = [k for k in NEEDED if not e.get(k)]
        if missing:
            raise ValueError(f"entry {e.get('core')} {e.get('part')}: no {', '.join(missing)}")
        if e["rtl"].endswith("-modified"):
            raise ValueError(f"entry {e['core']} {e['part']}: run on modified RTL ({e['rtl']}); commit, re-run, record")
        runs = out.setdefault(section(e), [])
        at = next((i for i, x in enumerate(runs) if key(x) == key(e)), None)
        if at is None:
            runs.append(e)
        else:
            runs[at] = e
    return out


def dump(figures):
    """One entry a line, as the file is kept (diffs show one run per changed line)."""
    lines = ["{"]
    keys = list(figures)
    for i, k in enumerate(keys):
        v = figures[k]
        comma = "," if i + 1 < len(keys) else ""
        if isinstance(v, list):
            lines.append(f"  {json.dumps(k)}: [")
            lines += [f"    {json.dumps(e)}" + ("," if j + 1 < len(v) else "") for j, e in enumerate(v)]
            lines.append(f"  ]{comma}")
        else:
            lines.append(f"  {json.dumps(k)}: {json.dumps(v)}{comma}")
    return "\n".join(lines + ["}"]) + "\n"


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("entries", nargs="+", help="figures_entries.json files of scripts/fpga.sh runs")
    ap.add_argument("--figures", default=os.path.join(ROOT, "docs", "fpga_figures.json"))
    args = ap.parse_args(argv)
    try:
        with open(args.figures) as f:
            figures = json.load(f)
        entries = []
        for path in args.entries:
            with open(path) as f:
                entries += json.load(f)
        merged = merge(figures, entries)
    except (OSError, ValueError) as err:
        print(f"fpga_record: {err}", file=sys.stderr)
        return 1
    tmp = args.figures + ".tmp"
    with open(tmp, "w") as f:
        f.write(dump(merged))
    os.replace(tmp, args.figures)
    print(f"fpga_record: {len(entries)} entries recorded in {os.path.relpath(args.figures)}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
