#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""ctest fpga_ecp5_tiles: the netlist of an ECP5 run of scripts/fpga.py (its Yosys JSON) has its
DSP tiles as rtl/prim/specular_mul_tile.sv makes them under SPECULAR_ECP5_MULT18X18D: at least
one MULT18X18D, and every one with its input A, input B and output registers on CLK0 (clock
enable CE0) and no pipeline register. Exit 1 naming the first cell that is not.

usage: check_ecp5_tiles.py NETLIST.json"""
import json
import sys

if len(sys.argv) != 2:
    sys.exit(__doc__)
try:
    with open(sys.argv[1]) as f:
        netlist = json.load(f)
except (OSError, ValueError) as err:
    sys.exit(f"check_ecp5_tiles: cannot read the netlist {sys.argv[1]}: {err}")


def text(v):
    """A Yosys JSON string parameter (as written, or as the bits of its characters)."""
    if isinstance(v, str) and v and set(v) <= {"0", "1"} and len(v) % 8 == 0:
        return bytes(int(v[i:i + 8], 2) for i in range(0, len(v), 8)).decode(errors="replace").strip()
    return str(v).strip()


WANT = {"REG_INPUTA_CLK": "CLK0", "REG_INPUTB_CLK": "CLK0", "REG_OUTPUT_CLK": "CLK0",
        "REG_INPUTA_CE": "CE0", "REG_INPUTB_CE": "CE0", "REG_OUTPUT_CE": "CE0"}
tiles = 0
for mod in netlist.get("modules", {}).values():
    for name, cell in mod.get("cells", {}).items():
        if cell.get("type") != "MULT18X18D":
            continue
        tiles += 1
        params = cell.get("parameters", {})
        for p, v in WANT.items():
            if text(params.get(p, "")) != v:
                sys.exit(f"check_ecp5_tiles: FAIL {name}: {p} = {text(params.get(p, ''))!r}, expected {v!r}")
        if text(params.get("REG_PIPELINE_CLK", "NONE")) != "NONE":
            sys.exit(f"check_ecp5_tiles: FAIL {name}: a pipeline register")
if tiles == 0:
    sys.exit("check_ecp5_tiles: FAIL no MULT18X18D in the netlist")
print(f"check_ecp5_tiles: PASS ({tiles} MULT18X18D, each with registered inputs and output)")
