# SPDX-License-Identifier: Apache-2.0
"""The FPGA parts of the flow and their resources (data sheets), one definition for
scripts/fpga.py's checks and summaries and for make report's hardware plane."""

# iCE40, by fpga.py's --device name: (part, logic cells, SB_RAM40_4K, SB_MAC16).
ICE40 = {"up5k": ("UP5K", 5280, 30, 8), "hx8k": ("HX8K", 7680, 32, 0)}
# The largest iCE40's logic cells (HX8K / LP8K).
ICE40_MAX_LC = max(p[1] for p in ICE40.values())

# LFE5U, smallest first: (part, nextpnr size flag, LUT4 positions (= flip-flops), MULT18X18D, DP16KD).
LFE5U = [("LFE5U-12F", "12k", 12288, 28, 32), ("LFE5U-25F", "25k", 24288, 28, 56),
         ("LFE5U-45F", "45k", 43848, 72, 108), ("LFE5U-85F", "85k", 83640, 156, 208)]
# fpga.py's ECP5 devices (the parts it places on).
ECP5_DEVICES = {"ecp5-25": LFE5U[1], "ecp5-45": LFE5U[2], "ecp5-85": LFE5U[3]}


def smallest_ice40(lcs, brams, dsps):
    """The smallest iCE40 whose logic cells, block RAMs and SB_MAC16 hold the counts, or None."""
    return next((p[0] for p in sorted(ICE40.values(), key=lambda p: p[1])
                 if lcs <= p[1] and brams <= p[2] and dsps <= p[3]), None)


def lfe5u_holds(p, lut4_positions, ffs, mults, ebrs):
    return lut4_positions <= p[2] and ffs <= p[2] and mults <= p[3] and ebrs <= p[4]


def smallest_lfe5u(lut4_positions, ffs, mults, ebrs, parts=LFE5U):
    """The smallest of `parts` that holds the counts, or None."""
    return next((p for p in parts if lfe5u_holds(p, lut4_positions, ffs, mults, ebrs)), None)


# The packing margin of the part fpga.py places on: nextpnr packs LUT4 and flip-flops into
# slices sharing clock, enable and reset, so Yosys' counts at the part's capacity do not
# place. Three specular_system runs failed on the LFE5U-45F with "Unable to find legal
# placement": folded at SetupII 64 at 98 % of its LUT4 positions by Yosys' counts, at
# SetupII 16 at 83 % (36,331 positions; 90 % of them after packing, 84 % of the flip-flops),
# and at SetupII 64 on the pruned netlist at 74 % (32,652; 81 % after packing, 68 % of the
# flip-flops). The 40 % below keeps every recorded ECP5 run on the part it placed on. The hard
# blocks (MULT18X18D, DP16KD) are placed one for one and need no margin (phong n1000 placed
# with 71 of the 45F's 72 MULT18X18D). Not explained by it: the system at SetupII 8 failed on
# the LFE5U-85F at 58 % of its LUT4 positions (62 % after packing) and 72 % of its MULT18X18D.
PLACE_MARGIN = 1.4


def place_lfe5u(lut4_positions, ffs, mults, ebrs, parts=LFE5U):
    """The part to place on: the smallest of `parts` that holds the counts with PLACE_MARGIN
    on LUT4 positions and flip-flops, else the smallest that holds them at all, or None."""
    roomy = smallest_lfe5u(lut4_positions * PLACE_MARGIN, ffs * PLACE_MARGIN, mults, ebrs, parts)
    return roomy or smallest_lfe5u(lut4_positions, ffs, mults, ebrs, parts)


def ice40_nofit(dev, lut4, ffs, brams, dsps):
    """Why Yosys' counts cannot fit the iCE40 part of fpga.py's --device dev, or None. A logic
    cell holds one LUT4 and one flip-flop, so the larger of the two is a lower bound of the
    logic cells needed."""
    _, lc_avail, ram_avail, dsp_avail = ICE40[dev]
    lc = max(lut4, ffs)
    why = []
    if lc > lc_avail:
        why.append(f"{lc} LC needed ({'flip-flops' if ffs >= lut4 else 'SB_LUT4'}; at least), {lc_avail} available")
    if brams > ram_avail:
        why.append(f"{brams} SB_RAM40_4K needed, {ram_avail} available")
    if dsps > dsp_avail:
        why.append(f"{dsps} SB_MAC16 needed, {dsp_avail} available")
    return "; ".join(why) + " (Yosys counts; nextpnr not run)" if why else None


def ecp5_place(lut4_positions, ffs, mults, ebrs, parts):
    """(the part of `parts` to place on, None) or (None, why none of them can hold the counts)."""
    part = place_lfe5u(lut4_positions, ffs, mults, ebrs, parts)
    if part:
        return part, None
    p = parts[-1]
    why = [f"{n} {what} needed, {avail} in the {p[0]}"
           for what, n, avail in (("LUT4 positions (LUT4 + 2 CCU2C)", lut4_positions, p[2]), ("flip-flops", ffs, p[2]),
                                  ("MULT18X18D", mults, p[3]), ("DP16KD", ebrs, p[4])) if n > avail]
    return None, "; ".join(why) + " (Yosys counts; nextpnr not run)"
