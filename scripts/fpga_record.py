#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Record the runs of scripts/fpga.py in docs/fpga_figures.json (rtl/fpga/README.md#records).

    scripts/fpga_record.py OUT_DIR/figures_entries.json [...] [--figures docs/fpga_figures.json]

entry() shapes a run of scripts/fpga.py (its result.json) into an entry, with the date of the
run, its tools (the Yosys and nextpnr versions) and the commit of the RTL; fpga.py writes them
to OUT_DIR/figures_entries.json and, with --record, calls main() on it. Each entry goes into
the section of its shape: a placed iCE40 run into "runs", a placed ECP5 run into "ecp5_runs", a
run whose counts exceed the part into "synthesis_runs". It replaces the entry of the same core,
configuration, SetupII, part and multiplier style there, or is appended. An entry whose RTL
commit ends in "-modified" (rtl/ or roms/ differed from the commit when the run started), or
whose tools do not name its Yosys version, is refused: commit the RTL, re-run, then record.
Exit 0 when recorded, 1 when an entry is refused or malformed (the figures file is then left
as it was), 2 on bad arguments.
"""
import argparse
import json
import os
import re
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
        if not re.match(r"Yosys \d", e["tools"]):
            raise ValueError(f"entry {e['core']} {e['part']}: its tools do not name the Yosys version ({e['tools']!r})")
        if e["rtl"].endswith("-modified"):
            raise ValueError(f"entry {e['core']} {e['part']}: run on modified RTL ({e['rtl']}); commit, re-run, record")
        runs = out.setdefault(section(e), [])
        at = next((i for i, x in enumerate(runs) if key(x) == key(e)), None)
        if at is None:
            runs.append(e)
        else:
            runs[at] = e
    return out


def multipliers(r):
    """The multiplier style of a run (docs/pipeline.md#multiplier-styles), from its parameters."""
    tile = next((p.split("=", 1)[1] for p in r["params"] if p.split("=", 1)[0] in ("MulTileBits", "TileBits")), None)
    if tile is None:
        return "the core's own"
    if tile == "0":
        return "LUT trees"
    return ("SB_MAC16" if r["device"] == "up5k" else "MULT18X18D") + f" tiles ({tile}-bit)"


ICE40_PARTS = {"hx8k": "HX8K ct256", "up5k": "UP5K sg48"}


def entry(r, rtl, date):
    """The docs/fpga_figures.json entry of a run of scripts/fpga.py (its result.json), or None for
    a run that is not a figure (a tool failed): placed on an iCE40 ("runs"), placed on an ECP5
    ("ecp5_runs"), or counts beyond the part with nextpnr not run ("synthesis_runs")."""
    import fpga_parts  # scripts/fpga_parts.py, beside this file
    e = {"core": r["core"]}
    cfg = r.get("phong_config") or r.get("label")
    if cfg:
        e["config"] = cfg  # the default configuration's entries have none
    ii = next((p.split("=", 1)[1] for p in r["params"] if p.startswith("SetupII=")), None)
    if ii is not None:
        e["setup_ii"] = int(ii)
    ecp5 = r["device"].startswith("ecp5")
    y, npr = r["yosys"], r.get("nextpnr", {})
    synthesis = r["synthesis"]
    if r["status"] == "placed and routed" and not ecp5:
        lcs = npr["ICESTORM_LC"]["used"]
        bram = npr.get("ICESTORM_RAM", {}).get("used", y["bram"])
        dsp = npr.get("ICESTORM_DSP", {}).get("used", y["dsp"])
        e.update({"part": ICE40_PARTS[r["device"]], "rtl": rtl, "date": date,
                  "tools": f"{r['yosys_version']}, {r['nextpnr_version']}", "synthesis": synthesis,
                  "multipliers": multipliers(r), "fmax_mhz": r.get("fmax_mhz"), "target_mhz": r["target_mhz"],
                  "lcs": lcs, "lcs_available": npr["ICESTORM_LC"]["available"], "sb_lut4": y["lut4"],
                  "sb_carry": y["carry"], "ffs": y["ff"], "brams": bram, "dsps": dsp,
                  "smallest_ice40": fpga_parts.smallest_ice40(lcs, bram, dsp)})
    elif r["status"] == "placed and routed":
        e.update({"part": r["part"], "rtl": rtl, "date": date, "multipliers": multipliers(r),
                  "tools": f"{r['yosys_version']}, {r['nextpnr_version']}", "synthesis": synthesis,
                  "fmax_mhz": r.get("fmax_mhz"), "target_mhz": r["target_mhz"],
                  "trellis_comb": npr.get("TRELLIS_COMB", {}).get("used"),
                  "trellis_comb_available": npr.get("TRELLIS_COMB", {}).get("available"),
                  "lut4": y["lut4"], "ccu2c": y["ccu2c"], "ffs": y["ff"],
                  "mult18x18d": npr.get("MULT18X18D", {}).get("used", y["mult18x18d"]),
                  "dp16kd": npr.get("DP16KD", {}).get("used", y["dp16kd"]), "smallest_lfe5u": r.get("smallest_lfe5u")})
    elif r["status"] == "does not fit" and r.get("nextpnr_run") is False:
        e.update({"part": "ECP5" if ecp5 else ICE40_PARTS[r["device"]], "rtl": rtl, "date": date,
                  "tools": r["yosys_version"], "synthesis": synthesis, "synthesis_only": True, "fit": False})
        if ecp5:
            e.update({"lut4": y["lut4"], "ccu2c": y["ccu2c"], "ffs": y["ff"], "mult18x18d": y["mult18x18d"],
                      "dp16kd": y["dp16kd"], "smallest_lfe5u": r.get("smallest_lfe5u")})
        else:
            e.update({"sb_lut4": y["lut4"], "ffs": y["ff"], "brams": y["bram"], "dsps": y["dsp"],
                      "lcs_needed_at_least": r["lcs_needed_at_least"], "lcs_available": r["lcs_available"]})
        e["yosys_seconds"] = r["synthesis_seconds"]
    else:
        return None
    return e


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
    ap.add_argument("entries", nargs="+", help="figures_entries.json files of scripts/fpga.py runs")
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
