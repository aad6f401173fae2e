#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Draw a timing diagram of specular_unit from a VCD file (written by sim_regression
--vcd-dir DIR --vcd-only), laid out like the timing diagram of patent UA 71489.

    scripts/plot_vcd.py build/vcd/line_l3.vcd build/vcd/line_l3.svg   (or .png)

The VCD is parsed here (header: $scope/$var; body: #time, scalar and b<bits> changes).
Signals are found by the end of their hierarchical name, so the script works whatever
the name of the top scope is. The value of each signal is taken just before every rising
edge of clk_i, i.e. the value "in that clock cycle", which is what the testbench samples.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# (label, hierarchical-name suffix, kind): kind "bit", "lsb" (bit 0 of a bus), "udec"
# (unsigned decimal bus), "pixel" (like udec, one box per valid cycle, labelled with the
# pixel index), "angle" (signed radians with ANGLE_FRAC fraction bits). The names follow
# the RTL hierarchy: specular_unit (host registers, start latch start_q, offer bit offer_q)
# > u_stream (specular_stream) > u_control14, u_counter5, u_accumulator.
ANGLE_FRAC = 28
SIGNALS = [
    ("clk_i", "specular_unit.clk_i", "clock"),
    ("register writes (16..24)", "specular_unit.c_we_i", "bit"),
    ("start_i (26)", "specular_unit.start_i", "bit"),
    ("start latch = busy (28)", "specular_unit.start_q", "bit"),
    ("span offered to the stream", "specular_unit.offer_q", "bit"),
    ("span accepted", "u_stream.u_control14.accept_o", "bit"),
    ("mux select (36)", "u_stream.u_control14.sel_o", "bit"),
    ("reg 8 write (37)", "u_stream.u_control14.strobe_o", "bit"),
    ("run: reg 8 holds a pixel", "u_stream.u_control14.vld_q", "lsb"),
    ("count pulse (34)", "u_stream.u_control14.count_o", "bit"),
    ("counter 5", "u_stream.u_counter5.cnt_q", "udec"),
    ("borrow (35)", "u_stream.u_counter5.borrow_o", "bit"),
    ("reg 8, high-half stage: psi [rad]", "u_stream.u_accumulator.psi_o", "angle"),
    ("last stage valid (29)", "u_stream.u_control14.out_valid_o", "bit"),
    ("busy_o (28)", "specular_unit.busy_o", "bit"),
    ("valid_o (29)", "specular_unit.valid_o", "bit"),
    ("intensity_o (27)", "specular_unit.intensity_o", "pixel"),
]


class VcdError(Exception):
    pass


def parse_vcd(path):
    """Returns ({full_name: (id, width)}, {id: [(time, value_string)]})."""
    variables, changes, scope = {}, {}, []
    with open(path, encoding="ascii", errors="replace") as fh:
        tokens = fh.read().split()
    i, time, in_header = 0, 0, True
    while i < len(tokens):
        tok = tokens[i]
        if in_header:
            if tok == "$scope":
                scope.append(tokens[i + 2])
                i = tokens.index("$end", i) + 1
            elif tok == "$upscope":
                scope.pop()
                i = tokens.index("$end", i) + 1
            elif tok == "$var":
                end = tokens.index("$end", i)
                width, ident, name = int(tokens[i + 2]), tokens[i + 3], tokens[i + 4]
                variables.setdefault(".".join(scope + [name]), (ident, width))
                changes.setdefault(ident, [])
                i = end + 1
            elif tok == "$enddefinitions":
                in_header = False
                i = tokens.index("$end", i) + 1
            elif tok.startswith("$"):
                i = tokens.index("$end", i) + 1
            else:
                raise VcdError(f"{path}: unexpected token {tok!r} in the header")
            continue
        if tok.startswith("#"):
            time = int(tok[1:])
        elif tok in ("$dumpvars", "$dumpall", "$dumpon", "$dumpoff", "$end"):
            pass
        elif tok[0] in "bBrR":
            ident = tokens[i + 1]
            if ident in changes:
                changes[ident].append((time, tok[1:]))
            i += 1
        elif tok[0] in "01xzXZ":
            if tok[1:] in changes:
                changes[tok[1:]].append((time, tok[0]))
        else:
            raise VcdError(f"{path}: cannot parse {tok!r} at time {time}")
        i += 1
    if not variables:
        raise VcdError(f"{path}: no $var definitions")
    return variables, changes


def find(variables, suffix):
    hits = sorted((n for n in variables if n == suffix or n.endswith("." + suffix)), key=len)
    if not hits:
        raise VcdError(f"signal *{suffix} not in the VCD")
    return variables[hits[0]]


def value_at(history, t):
    """Value of a signal just before time t (changes at t itself not yet applied)."""
    v = None
    for when, val in history:
        if when >= t:
            break
        v = val
    return v


def to_int(bits):
    if bits is None or any(c not in "01" for c in bits):
        return None
    return int(bits, 2)


def main(argv):
    if len(argv) != 3 or not argv[2].lower().endswith((".svg", ".png")):
        sys.stderr.write("usage: plot_vcd.py IN.vcd OUT.svg|OUT.png\n")
        return 2
    try:
        variables, changes = parse_vcd(argv[1])
        rows = [(label, find(variables, suffix), kind) for label, suffix, kind in SIGNALS]
    except (OSError, VcdError) as e:
        sys.stderr.write(f"plot_vcd.py: {e}\n")
        return 2

    clk_id = rows[0][1][0]
    rises = [t for (t, v), (_, prev) in zip(changes[clk_id][1:], changes[clk_id]) if v == "1" and prev == "0"]
    if len(rises) < 2:
        sys.stderr.write("plot_vcd.py: fewer than two rising clock edges in the VCD\n")
        return 2
    ncyc = len(rises)
    # Cycle c spans x in [c, c+1); its values are those just before rising edge c.
    fig_h = 0.55 * len(rows) + 1.2
    fig, ax = plt.subplots(figsize=(max(9.0, 0.62 * ncyc + 3.0), fig_h))
    yticks, ylabels = [], []
    start_cycle = None
    valid_id = find(variables, "specular_unit.valid_o")[0]
    valid = [value_at(changes[valid_id], t) for t in rises]
    for r, (label, (ident, width), kind) in enumerate(rows):
        y = len(rows) - 1 - r
        yticks.append(y + 0.35)
        ylabels.append(label)
        hist = changes[ident]
        if kind == "clock":
            xs, ys = [], []
            # Rising edges at integer x: the edge ending cycle c is drawn at x = c + 1.
            for c in range(ncyc):
                xs += [c, c, c + 0.5, c + 0.5, c + 1]
                ys += [y, y + 0.7, y + 0.7, y, y]
            ax.plot(xs, ys, color="black", lw=1)
            continue
        vals = [value_at(hist, t) for t in rises]
        if kind == "lsb":
            vals = [v[-1] if v else v for v in vals]
            kind = "bit"
        if kind == "bit":
            xs, ys = [], []
            for c, v in enumerate(vals):
                level = y + (0.7 if v == "1" else 0.0)
                xs += [c, c + 1]
                ys += [level, level]
                if label.startswith("start_i") and v == "1" and start_cycle is None:
                    start_cycle = c
            ax.plot(xs, ys, color="tab:blue", lw=1.6, drawstyle="steps-post")
            continue
        # Buses: a box per run of equal values, the value written inside.
        c = 0
        while c < ncyc:
            e = c
            while e + 1 < ncyc and vals[e + 1] == vals[c] and not (
                    kind == "pixel" and (valid[e + 1] == "1" or valid[c] == "1")):
                e += 1
            n = to_int(vals[c])
            if n is None:
                text = "x"
            elif kind == "angle":
                if n >> (width - 1):
                    n -= 1 << width
                text = f"{n / 2**ANGLE_FRAC:+.3f}"
            else:
                text = str(n)
            x0, x1 = c + 0.08, e + 1 - 0.08
            ax.plot([c, x0, x1, e + 1, x1, x0, c], [y + 0.35, y + 0.7, y + 0.7, y + 0.35, y, y, y + 0.35],
                    color="tab:green", lw=1.2)
            ax.text((c + e + 1) / 2, y + 0.35, text, ha="center", va="center", fontsize=7.5)
            if kind == "pixel" and valid[c] == "1":
                ax.text((c + e + 1) / 2, y + 0.85, f"pixel {sum(v == '1' for v in valid[:c])}", ha="center",
                        va="center", fontsize=7, color="tab:red")
            c = e + 1
    for c in range(ncyc + 1):
        ax.axvline(c, color="0.85", lw=0.6, zorder=0)
    ax.set_yticks(yticks)
    ax.set_yticklabels(ylabels, fontsize=9)
    ax.set_ylim(-0.4, len(rows) + 0.1)
    ax.set_xlim(0, ncyc)
    if start_cycle is not None:
        ticks = list(range(ncyc))
        ax.set_xticks([t + 0.5 for t in ticks])
        ax.set_xticklabels([f"s{t - start_cycle:+d}" if t != start_cycle else "s" for t in ticks], fontsize=8)
        ax.set_xlabel("clock cycle (s: start_i high, sampled by the rising edge that ends cycle s; every value is "
                      "drawn in the cycle in which it is sampled)", fontsize=9)
    for side in ("top", "right", "left"):
        ax.spines[side].set_visible(False)
    ax.tick_params(axis="y", length=0)
    ax.set_title(f"specular_unit timing diagram: {argv[1].split('/')[-1]} (patent UA 71489 block numbers "
                 "in parentheses)", fontsize=10)
    fig.tight_layout()
    tmp = argv[2] + ".tmp." + argv[2].rsplit(".", 1)[1]
    fig.savefig(tmp, dpi=130)
    import os

    os.replace(tmp, argv[2])
    print(f"wrote {argv[2]} ({ncyc} cycles)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
