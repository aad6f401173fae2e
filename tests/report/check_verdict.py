#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""scripts/verdict.py (make report's section 4c, docs/phong_hw.md#verdict) on synthetic points whose
figures are worked out by hand below, then on the committed docs/fpga_figures.json (every row it
writes has a figure or says why not). Exit 0 when every check holds."""
import json
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import verdict  # noqa: E402

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)


def close(a, b, what):
    check(a is not None and abs(a - b) <= 1e-9 * max(1.0, abs(b)), f"{what}: {a} != {b}")


def entry(lut4, ccu2c, ffs, mult, ebr, fmax):
    return {"lut4": lut4, "ccu2c": ccu2c, "ffs": ffs, "mult18x18d": mult, "dp16kd": ebr, "fmax_mhz": fmax}


# LFE5U-85F: 83,640 LUT4 positions and flip-flops, 156 MULT18X18D, 208 DP16KD.
# stream: LUT4 positions 1,000 + 2 * 100 = 1,200 (0.014347), FF 2,091 (0.025), MULT 3.9 -> 6 (0.0385),
# DP16KD 6 (0.0288): binding MULT18X18D, share 6 / 156, 26 px/clock per part.
stream = entry(1000, 100, 2091, 6, 6, 120.0)
# system at SetupII 4: FF 41,820 (0.5) binds; share 0.5, 2 px/clock per part at one pixel per clock.
system4 = entry(20000, 1000, 41820, 39, 10, None)
# Phong: MULT 78 (0.5) and FF 20,910 (0.25): share 0.5; 2 px/clock per part; at 100 MHz 200 Mpx/s.
phong = entry(5000, 1000, 20910, 78, 1, 100.0)
pts = [
    {"name": "stream", "kind": "device", "ecp5": stream, "meets": ["b1", "b3"], "setup_ii": None},
    {"name": "system4", "kind": "device", "ecp5": system4, "meets": ["b1", "b3"], "setup_ii": 4},
    {"name": "phong", "kind": "phong", "ecp5": phong, "err": {"rel_lsb": 5e-4, "abs_lsb": 1e-3, "abs_raw": 3e-3},
     "setup_ii": None},
]
sh, res = verdict.share(stream)
close(sh, 6 / 156, "stream share")
check(res == "MULT18X18D", f"stream binding resource {res}")
close(verdict.share(system4)[0], 0.5, "system share")
close(verdict.share(phong)[0], 0.5, "phong share")
# Phong's errors: B1 rel 0.5, abs 0.1 -> 0.5 meets; B2 raw 3e-3 * 512 = 1.536 misses; B3 0.1.
close(verdict.budget_error(pts[2]["err"], "b1"), 0.5, "b1 error fraction")
close(verdict.budget_error(pts[2]["err"], "b2"), 3e-3 * 512, "b2 error fraction")
close(verdict.budget_error(pts[2]["err"], "b3"), 0.1, "b3 error fraction")
check(verdict.budget_error({"rel_lsb": 1e-4}, "b1") is None, "a missing figure gives no verdict")
# Pixels per clock of the system at SetupII 4: spans of 2 pixels -> 0.5; of 8 -> 1.
close(verdict.pixels_per_clock(4, 2), 0.5, "ppc m=2 k=4")
close(verdict.pixels_per_clock(4, 8), 1.0, "ppc m=8 k=4")
close(verdict.pixels_per_clock(None, 1), 1.0, "ppc host setup")

# Break-even: system4 (share 0.5, SetupII 4) against phong (0.5): m = 4 * 0.5 / 0.5 = 4 at B1; a
# system twice Phong's share never ties (ratio 0.5 on long spans).
be = verdict.break_even(pts, "b1")
close(be["span"], 4.0, "break-even span, equal shares")
check(be["design"] == "system4" and be["phong"] == "phong", f"break-even designs {be}")
close(be["ratio_at_long_spans"], 1.0, "long-span ratio, equal shares")
big = dict(pts[1], name="system4 big", ecp5=entry(20000, 1000, 83640, 39, 10, None))  # FF 83,640: share 1
be = verdict.break_even([big, pts[2]], "b1")
check(be["span"] is None, f"a system of twice Phong's share has no break-even: {be}")
close(be["ratio_at_long_spans"], 0.5, "long-span ratio, twice the share")
small = dict(pts[1], name="system8 small", setup_ii=8, ecp5=entry(20000, 1000, 10455, 39, 10, None))  # share 0.25
be = verdict.break_even([pts[1], small, pts[2]], "b1")
close(be["span"], 4.0, "the smaller of 4 * 0.5 / 0.5 and 8 * 0.25 / 0.5")
check(verdict.break_even([pts[2]], "b1") is None, "no hardware-setup design: no break-even")
# Against each Phong core: a second core of share 1 (FF 83,640) ties with system4 at
# m = 4 * 0.5 / 1 = 2, the best core (share 0.5) at 4; the best-core figure stays 4.
phong_big = dict(pts[2], name="phong big", ecp5=entry(100, 10, 83640, 10, 1, 100.0))
each = verdict.break_even_each(pts + [phong_big], "b1")
check([e["phong"] for e in each] == ["phong", "phong big"], f"each Phong core, smallest first: {each}")
close(each[0]["span"], 4.0, "break-even against the smaller core")
close(each[1]["span"], 2.0, "break-even against the larger core")
close(verdict.break_even(pts + [phong_big], "b1")["span"], 4.0, "the best core's break-even unchanged")
check(verdict.break_even_each([pts[2]], "b1") == [], "no hardware-setup design: no break-even against any core")

# Only the system and the Phong core: at m = 2 the system gives 0.5 / 0.5 = 1 px/clock per part
# against Phong's 2 (ratio 0.5); at m = 8, 2 against 2 (ratio 1). A measured 0.25 at m = 2 gives 0.25.
res = verdict.verdict(pts[1:], [("2", 2, None), ("8", 8, None), ("scene", 2, {4: 0.25})])
b1 = res["b1"]
close(b1[0]["hw_ratio"], 0.5, "system/phong at m = 2")
close(b1[1]["hw_ratio"], 1.0, "system/phong at m = 8")
close(b1[2]["hw_ratio"], 0.25, "measured pixels per clock replace the formula")
check(b1[0]["hw_ratio_at_clock"] is None, "no clock for a synthesis-only design")
check(b1[0]["host"] is None and b1[0]["host_ratio"] is None, "no host-setup design among the points")
check(res["b2"][0]["phong"] is None and res["b2"][0]["hw_ratio"] is None, "B2: the Phong core misses it")
# With the stream: 26 / 2 = 13 per clock; at each clock 26 * 120 / (2 * 100) = 15.6.
res = verdict.verdict(pts, [("1", 1, None)])
check(res["b1"][0]["host"]["name"] == "stream", "the stream is the host-setup device design")
close(res["b1"][0]["host_ratio"], 13.0, "stream/phong")
close(res["b1"][0]["host_ratio_at_clock"], 15.6, "stream/phong at each clock")
close(res["b1"][0]["hw_ratio"], (0.25 / 0.5) / 2, "system at m = 1: 1/4 px/clock, share 0.5, over Phong's 2")

# An entry of the current ECP5 flow is taken over an older one of the same core, whatever their
# order; a placed entry over synthesis counts of the same flow; synthesis counts of the current
# flow over an older placed run.
old_run = {"core": "phong_stream", "config": "c", "setup_ii": None, "multipliers": "MULT18X18D tiles",
           "synthesis": "synth_ecp5", "date": "2026-12-07", "lut4": 1}
new_run = dict(old_run, synthesis="read_verilog -DSPECULAR_ECP5_MULT18X18D; synth_ecp5 -nowidelut; opt_merge",
               date="2026-12-06", lut4=2)
check(verdict.ecp5_entry({"ecp5_runs": [old_run, new_run]}, "phong_stream", "c")["lut4"] == 2,
      "the current flow's entry first")
check(verdict.ecp5_entry({"ecp5_runs": [new_run, old_run]}, "phong_stream", "c")["lut4"] == 2,
      "the current flow's entry first, either order")
syn_new = {"core": "specular_system", "part": "ECP5", "config": None, "setup_ii": 1,
           "synthesis": "read_verilog -DSPECULAR_ECP5_MULT18X18D; synth_ecp5 -nowidelut -noflatten", "lut4": 3}
placed_old = {"core": "specular_system", "config": None, "setup_ii": None, "multipliers": "MULT18X18D tiles",
              "synthesis": "synth_ecp5 -nowidelut -noflatten", "lut4": 4}
e = verdict.ecp5_entry({"ecp5_runs": [placed_old], "synthesis_runs": [syn_new]}, "specular_system")
check(e["lut4"] == 3 and not e["placed"], "current synthesis counts over an older placed run")
e = verdict.ecp5_entry({"ecp5_runs": [dict(placed_old, synthesis=syn_new["synthesis"])],
                        "synthesis_runs": [syn_new]}, "specular_system")
check(e["lut4"] == 4 and e["placed"], "a placed run over synthesis counts of the same flow")

# The current flow is the one scripts/fpga.py runs on the ECP5: its synthesis command there
# (ECP5_SYNTH) and the define of its DSP tiles (ECP5_TILE_DEFINE).
import re  # noqa: E402
with open(os.path.join(ROOT, "scripts", "fpga.py")) as f:
    fpga_py = f.read()
ecp5_synth = re.findall(r'^ECP5_SYNTH = "([^"]*)"', fpga_py, re.M)
tile_define = re.findall(r'^ECP5_TILE_DEFINE = "([^"]*)"', fpga_py, re.M)
flow_synth, flow_define = [m for m in verdict.CURRENT_FLOW if m.startswith("synth_")], \
                          [m for m in verdict.CURRENT_FLOW if m.startswith("-D")]
check(len(ecp5_synth) == 1 and flow_synth == ecp5_synth,
      f"verdict.CURRENT_FLOW {verdict.CURRENT_FLOW!r} is not scripts/fpga.py's ECP5_SYNTH: {ecp5_synth}")
check(len(tile_define) == 1 and flow_define == ["-D" + tile_define[0]],
      f"verdict.CURRENT_FLOW {verdict.CURRENT_FLOW!r} does not name scripts/fpga.py's ECP5_TILE_DEFINE: {tile_define}")

# The plots' number labels: points at one place (the systems per SetupII share an error) get labels
# whose boxes do not overlap, and a lone point the first offset.
offs = verdict.label_offsets([(100.0, 100.0)] * 5 + [(400.0, 50.0)])
boxes = [(100 + dx, 100 + dy) for dx, dy in offs[:5]]
check(all(abs(a[0] - b[0]) >= 16 or abs(a[1] - b[1]) >= 11 for i, a in enumerate(boxes) for b in boxes[i + 1:]),
      f"the labels of five points at one place overlap: {offs[:5]}")
check(offs[5] == offs[0], f"a lone point takes the first offset: {offs}")
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        written = verdict.plot(pts, tmp, plt)
        check([os.path.basename(w) for w in written] == ["verdict_b1.png", "verdict_b2.png", "verdict_b3.png", "verdict_b4.png"]
              and all(os.path.getsize(w) > 0 for w in written), f"verdict.plot wrote {written}")
except ImportError:
    failures.append("matplotlib is missing for /usr/bin/python3 (python3-matplotlib): the plots are not checked")

# The committed record: the section is written for every budget and span length.
with open(os.path.join(ROOT, "docs", "fpga_figures.json")) as f:
    figs = json.load(f)
lines = []
import hw_plane  # noqa: E402  (scripts/hw_plane.py: the configurations and their budgets)
pts = verdict.record_points(figs, hw_plane.phong_configs())
verdict.write(lines.append, verdict.verdict(pts, [(str(m), m, None) for m in verdict.SPAN_LENGTHS]), pts)
text = "\n".join(lines)
for b in verdict.BUDGETS:
    check(f"**{b.upper()}**" in text, f"no table for {b}")
check(text.count("\n| 64 |") == len(verdict.BUDGETS), "one row per budget for span length 64")

for msg in failures:
    print("FAIL", msg)
print("check_verdict:", "FAIL" if failures else "PASS")
sys.exit(1 if failures else 0)
