#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""scripts/fpga_parts.py: which LFE5U fpga.py records (smallest_lfe5u, Yosys' counts as they are)
and which it places on (place_lfe5u, PLACE_MARGIN on LUT4 positions and flip-flops), on counts
placed by hand against the data-sheet capacities (LFE5U-45F: 43,848 LUT4 positions, 72
MULT18X18D, 108 DP16KD; LFE5U-85F: 83,640, 156, 208). Exit 0 when all agree, 1 otherwise."""
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import fpga_parts  # noqa: E402

PARTS = list(fpga_parts.ECP5_DEVICES.values())  # fpga.py's candidates: 25F, 45F, 85F
CASES = [
    # (LUT4 positions, FF, MULT18X18D, DP16KD), smallest holding, placed on
    ((42939, 33999, 17, 29), "LFE5U-45F", "LFE5U-85F"),  # 98 % of the 45F: no room to pack
    ((36331, 37223, 45, 29), "LFE5U-45F", "LFE5U-85F"),  # 83 % of the 45F: failed to place
    ((32652, 29842, 17, 29), "LFE5U-45F", "LFE5U-85F"),  # 74 % of the 45F: failed to place
    ((31320, 30000, 17, 29), "LFE5U-45F", "LFE5U-45F"),  # 31,320 x 1.4 = 43,848 <= 43,848
    ((31321, 30000, 17, 29), "LFE5U-45F", "LFE5U-85F"),  # 31,321 x 1.4 = 43,849.4 > 43,848
    ((10000, 32000, 17, 29), "LFE5U-45F", "LFE5U-85F"),  # the flip-flops bind: 44,800
    ((10000, 10000, 72, 29), "LFE5U-45F", "LFE5U-45F"),  # 72 tiles: exactly, no margin
    ((10000, 10000, 73, 29), "LFE5U-85F", "LFE5U-85F"),
    ((80000, 20000, 17, 29), "LFE5U-85F", "LFE5U-85F"),  # no part with margin: the exact fit
    ((83641, 20000, 17, 29), None, None),                # over the largest part
    ((10000, 10000, 157, 0), None, None),
]


def name(p):
    return p[0] if p else None


def main():
    bad = 0
    for need, smallest, placed in CASES:
        got = (name(fpga_parts.smallest_lfe5u(*need, parts=PARTS)), name(fpga_parts.place_lfe5u(*need, parts=PARTS)))
        if got != (smallest, placed):
            print(f"FAIL {need}: smallest, placed {got}, expected {(smallest, placed)}")
            bad += 1
    print(f"{len(CASES) - bad} of {len(CASES)} cases agree")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
