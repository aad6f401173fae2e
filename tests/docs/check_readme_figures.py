#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""The measured figures of README.md, rtl/fpga/README.md and docs/device.md's FPGA cost per error
budget, checked against the JSON of the runs that measured them (docs/usage.md, section "Where the measured figures live").

Sources (all committed; the paths are relative to the repository root):
  docs/measured/sim.json          `sim_regression --json` (deterministic: counts, errors, clocks)
  docs/measured/scene_bench.json  `scene_bench --json` over scenes/*.json (timings: the one run
                                  whose figures README prints)
  docs/fpga_figures.json          `make fpga` (place and route: too slow to re-run in ctest)
  `specular errors ...`           run here when --specular names the binary (deterministic)

Each figure is a regular expression on the document whose groups are the printed numbers, and
a function of the sources giving the value each must print. A printed number must equal its
value to the printed precision (half a unit of its last digit; counts exactly); a figure whose
text is not found, is found more than once, or differs fails with a message naming it. Every
number in the measured regions of the documents (FIGURE_REGIONS: the whole of README.md, code
spans, fenced blocks and link targets aside) must belong to a figure or to a stated
non-measured constant (NOT_MEASURED); one that does not ("nobody measured it") fails.

usage: check_readme_figures.py ROOT [--specular BIN]     check
       check_readme_figures.py ROOT --list [--specular BIN]   print every figure's expected value
       check_readme_figures.py ROOT --self-test [--specular BIN]  tampered copies must fail
       check_readme_figures.py ROOT --update [--specular BIN]  rewrite the figures that differ from
                                                               their sources (same printed precision), then check
"""
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile


# ------------------------------------------------------------------ sources
class Data:
    def __init__(self, root, specular=None):
        self.root = root
        self.specular = specular

        def load(rel):
            with open(os.path.join(root, rel)) as f:
                return json.load(f)

        self.sim = load("docs/measured/sim.json")
        self.sb = load("docs/measured/scene_bench.json")
        self.fpga = load("docs/fpga_figures.json")
        self._cli = {}

    # scene_bench
    def scenes(self):
        return self.sb["scenes"]

    def best(self, x, key="speedup"):
        """device x phong_sleef (or a method's ns per pixel) with both at the best instruction set."""
        return x["best_isa"][key]

    # place and route
    def pnr(self, core, part):
        """The default configuration's run (no "config": a --label or --phong-config run names its
        configuration there, rtl/fpga/README.md#how-to-run)."""
        for r in self.fpga["runs"]:
            if r["core"] == core and r["part"].startswith(part) and not r.get("config"):
                return r
        raise KeyError(f"{core} {part} not in docs/fpga_figures.json")

    def fpga_budget_keys(self):
        """The budget table's keys, or [] when no configuration per budget was run (then the
        table may be absent)."""
        keys = list(budget_entries(self))
        return keys if any(k[1] != "default" for k in keys) else []

    # sim_regression
    def cfg(self, name):
        return self.sim["configs"][name]

    def cli(self, *args):
        """The CSV rows of `specular ARGS` as dicts (run once per argument list)."""
        if args not in self._cli:
            if not self.specular:
                raise KeyError("needs --specular BIN (the `specular` CLI)")
            out = subprocess.run([self.specular, *args], check=True, capture_output=True, text=True).stdout
            lines = [ln for ln in out.splitlines() if ln.strip()]
            head = lines[0].split(",")
            self._cli[args] = [dict(zip(head, ln.split(","))) for ln in lines[1:]]
        return self._cli[args]


# ------------------------------------------------------------------ figures
# A figure: (document, pattern, [(name, value function), ...]) with one group per name. In the
# pattern a space stands for any run of white space (prose is wrapped). Value functions take
# Data; "<" before a name makes the printed number an upper bound of the value instead.
def rng(fn):
    return [(lambda d: min(fn(d, x) for x in d.scenes())), (lambda d: max(fn(d, x) for x in d.scenes()))]


def ranged(doc, pattern, label, fn):
    lo, hi = rng(fn)
    return (doc, pattern, [(label + " (lowest)", lo), (label + " (highest)", hi)])


def stream_scene_total(d, key):
    ss = d.sim["scenes_stream"]
    return sum(s[key] for s in ss.values()) / sum(s["pixels"] for s in ss.values())


def same_in_every_config(d, key):
    """A count every configuration of the run shares (lines, pixels); None where they differ."""
    vals = {c[key] for c in d.sim["configs"].values()}
    return vals.pop() if len(vals) == 1 else None


def sim_total(d, key):
    """A count summed over every stage of make sim that checks the RTL: the line runs of every
    configuration, the scene stage, the scenes through the stream and the stream stage."""
    total = sum(c[key] for c in d.sim["configs"].values())
    total += sum(s[key] for s in d.sim["scenes"].values())
    total += sum(s[key] for s in d.sim["scenes_stream"].values())
    return total + d.sim["stream"][key]


R = "README.md"
F = "rtl/fpga/README.md"
D = "docs/device.md"  # its FPGA cost per error budget (#configurations-per-budget)
P = "docs/phong_hw.md"  # the verdict (#verdict)


def budget_range(label, what):
    """The lowest and the highest over the parts of a configuration per budget's ratio of `what`
    to the default configuration's (budget_ratio); a part where neither has any (the HX8K's
    DSPs) is left out."""
    def vals(d):
        v = [budget_ratio(d, k, what) for k in budget_entries(d) if k[1] == label]
        v = [x for x in v if x != "-"]
        if not v:
            raise KeyError(f"no {label} entries of {BUDGET_CORE} in docs/fpga_figures.json")
        return v
    return [(f"{label}: x {what} (lowest)", lambda d: min(vals(d))),
            (f"{label}: x {what} (highest)", lambda d: max(vals(d)))]


def budget_sentence(label):
    """docs/device.md's sentence of one configuration per budget: its ratios to the default build."""
    return (D, r"\(`" + label + r"`\): LUT4 (\S+) to (\S+) x, flip-flops (\S+) to (\S+) x, DSPs (\S+) to (\S+) x, "
               r"block RAMs (\S+) to (\S+) x, Fmax (\S+) to (\S+) x",
            sum((budget_range(label, w) for w in ("LUT4", "FFs", "DSPs", "BRAMs", "Fmax")), []))

_VERDICT = {}


def verdict_rows(d):
    """scripts/verdict.py on the record (docs/fpga_figures.json): every configuration at the budget it
    was built for (the Phong configurations by their names, roms/phong/phong_configs.cmake; the
    device's by their labels; B1 implies B3), spans of 1, 8, 16 and 64 pixels. Cached per Data."""
    key = id(d)
    if key not in _VERDICT:
        sys.path.insert(0, os.path.join(d.root, "scripts"))
        import verdict  # scripts/verdict.py
        import hw_plane  # scripts/hw_plane.py: the configurations and their budgets
        pts = verdict.record_points(d.fpga, hw_plane.phong_configs(os.path.join(d.root, "roms", "phong",
                                                                                "phong_configs.cmake")))
        _VERDICT[key] = verdict.verdict(pts, [(str(m), m, None) for m in _VERDICT_SPANS])
    return _VERDICT[key]


_VERDICT_SPANS = (1, 8, 16, 64)


def verdict_figure(budget, span, field):
    return lambda d: verdict_rows(d)[budget][_VERDICT_SPANS.index(span)][field]


def _ecp5_entry(d, core, config=None, setup_ii=None):
    """The entry the verdict takes (scripts/verdict.py ecp5_entry: the current ECP5 flow's first)."""
    sys.path.insert(0, os.path.join(d.root, "scripts"))
    import verdict  # scripts/verdict.py
    return verdict.ecp5_entry(d.fpga, core, config, setup_ii)


def phong_entry(d, config):
    return _ecp5_entry(d, "phong_stream", config)


def device_entry(d, config):
    return _ecp5_entry(d, "specular_stream", config)


def hw_long_span_design(d, budget="b1", spans=16):
    """The ECP5 entry of the device system the verdict picks at the budget on spans of `spans` pixels (at each
    core's clock)."""
    name = verdict_rows(d)[budget][_VERDICT_SPANS.index(spans)]["hw_at_clock"]["name"]
    k = int(re.search(r"SetupII=(\d+)", name).group(1))
    return _ecp5_entry(d, "specular_system", None, None if k == 1 else k)


def positions(e):
    return e["lut4"] + 2 * e["ccu2c"]


# README.md's Results table: one figure per row (a table cell is "| ... |": the bars are escaped).
FIGURES = [
    (R, r"every configuration \((\S+) lines, (\S+) M pixels each\) and the scenes \|",
     [("line runs per configuration", lambda d: same_in_every_config(d, "lines")),
      ("pixels per configuration (millions)", lambda d: same_in_every_config(d, "pixels") / 1e6)]),
    (R, r"\| (\S+) mismatches, (\S+) protocol errors \| `make sim` \|",
     [("bit-exact mismatches, every configuration and stage", lambda d: sim_total(d, "mismatches")),
      ("protocol errors, every configuration and stage", lambda d: sim_total(d, "protocol_errors"))]),
    (R, r"default build \| (\S+) % relative in the epicenter, (\S+) C over the lobe \|",
     [("default: relative error in the epicenter (%)", lambda d: 100 * d.cfg("default")["rel_epicenter_with_lsb"]["value"]),
      ("default: absolute error over the lobe (C)", lambda d: d.cfg("default")["abs_lobe_with_lsb"]["value"])]),
    (R, r"the same, patent build \| (\S+) % and (\S+) C \|",
     [("patent: relative error in the epicenter (%)", lambda d: 100 * d.cfg("patent")["rel_epicenter_with_lsb"]["value"]),
      ("patent: absolute error over the lobe (C)", lambda d: d.cfg("patent")["abs_lobe_with_lsb"]["value"])]),
    (R, r"\(the patent claims at most 1 %\) \| (\S+) % \|",
     [("patent float model at n = 3 (%)",
       lambda d: 100 * float(d.cli("errors", "--model", "patent", "--n", "3")[0]["max_rel_epicenter"]))]),
    (R, r"back to back, after the fill \| (\S+) pixels per clock \|",
     [("stream pixels per clock, l = 0..3, without the fill",
       lambda d: d.sim["stream"]["pixels_per_clock_short_spans_steady"])]),
    (R, r"clocks per pixel through `specular_stream` / `specular_unit` \| (\S+) / (\S+) \|",
     [("scenes: stream clocks per pixel", lambda d: stream_scene_total(d, "stream_cycles")),
      ("scenes: register interface clocks per pixel", lambda d: stream_scene_total(d, "register_cycles"))]),
    (R, r"`specular_stream` on the iCE40-HX8K, out of context \| (\S+) SB_LUT4, (\S+) of (\S+) logic cells, (\S+) block "
        r"RAMs, (\S+) MHz \|",
     [("specular_stream HX8K SB_LUT4", lambda d: d.pnr("specular_stream", "HX8K")["sb_lut4"]),
      ("specular_stream HX8K logic cells", lambda d: d.pnr("specular_stream", "HX8K")["lcs"]),
      ("HX8K logic cells available", lambda d: d.pnr("specular_stream", "HX8K")["lcs_available"]),
      ("specular_stream HX8K block RAMs", lambda d: d.pnr("specular_stream", "HX8K")["brams"]),
      ("specular_stream HX8K Fmax", lambda d: d.pnr("specular_stream", "HX8K")["fmax_mhz"])]),
    (R, r"`specular_stream` on the iCE40-UP5K \| (\S+) of (\S+) logic cells, (\S+) MHz \|",
     [("specular_stream UP5K logic cells", lambda d: d.pnr("specular_stream", "UP5K")["lcs"]),
      ("UP5K logic cells available", lambda d: d.pnr("specular_stream", "UP5K")["lcs_available"]),
      ("specular_stream UP5K Fmax", lambda d: d.pnr("specular_stream", "UP5K")["fmax_mhz"])]),
    ranged(R, r"per-pixel Phong \(SLEEF\), per scene \| (\S+) to (\S+) x as fast \|",
           "software: device x phong_sleef, both at the best instruction set", lambda d, x: d.best(x)),
    (R, r"over the cancellation-free per-pixel Phong core \| (\S+) x \((\S+) x at each core's clock\); with the "
        r"setup in hardware (\S+) x on spans of 8 pixels, (\S+) x on spans of 16 \((\S+) x at each core's clock\), "
        r"(\S+) x on spans of 64 or more \((\S+) x\) \|",
     [("B1 verdict: host-setup device / best Phong, px per clock per part", verdict_figure("b1", 1, "host_ratio")),
      ("B1 verdict: the same at each core's clock", verdict_figure("b1", 1, "host_ratio_at_clock")),
      ("B1 verdict: hardware-setup device / best Phong, spans of 8", verdict_figure("b1", 8, "hw_ratio")),
      ("B1 verdict: hardware-setup device / best Phong, spans of 16", verdict_figure("b1", 16, "hw_ratio")),
      ("B1 verdict: hardware-setup device / best Phong at each core's clock, spans of 16",
       verdict_figure("b1", 16, "hw_ratio_at_clock")),
      ("B1 verdict: hardware-setup device / best Phong, spans of 64", verdict_figure("b1", 64, "hw_ratio")),
      ("B1 verdict: hardware-setup device / best Phong at each core's clock, spans of 64",
       verdict_figure("b1", 64, "hw_ratio_at_clock"))]),
    (P, r"at B1 the device's stream gives (\S+) times the pixels per clock per part of the cancellation-free core "
        r"\((\S+) times at each core's clock\), at B3 (\S+) times \((\S+) times\)",
     [("B1 verdict ratio", verdict_figure("b1", 1, "host_ratio")),
      ("B1 verdict ratio at clock", verdict_figure("b1", 1, "host_ratio_at_clock")),
      ("B3 verdict ratio", verdict_figure("b3", 1, "host_ratio")),
      ("B3 verdict ratio at clock", verdict_figure("b3", 1, "host_ratio_at_clock"))]),
    (P, r"at B1 it uses (\S+) times fewer LUT4 positions, (\S+) times fewer flip-flops and (\S+) times fewer "
        r"MULT18X18D",
     [("B1: cross / device LUT4 positions", lambda d: positions(phong_entry(d, "cross_n1000"))
       / positions(device_entry(d, "device_b1_n1000"))),
      ("B1: cross / device flip-flops", lambda d: phong_entry(d, "cross_n1000")["ffs"]
       / device_entry(d, "device_b1_n1000")["ffs"]),
      ("B1: cross / device MULT18X18D", lambda d: phong_entry(d, "cross_n1000")["mult18x18d"]
       / device_entry(d, "device_b1_n1000")["mult18x18d"])]),
    (P, r"from (\S+) times at one pixel per span through (\S+) times on spans of 8 pixels and (\S+) times on\s+"
        r"spans of 16 to (\S+) times on spans of 64 pixels or more",
     [("B1: hardware-setup device / Phong, spans of 1", verdict_figure("b1", 1, "hw_ratio")),
      ("B1: hardware-setup device / Phong, spans of 8", verdict_figure("b1", 8, "hw_ratio")),
      ("B1: hardware-setup device / Phong, spans of 16", verdict_figure("b1", 16, "hw_ratio")),
      ("B1: hardware-setup device / Phong, spans of 64", verdict_figure("b1", 64, "hw_ratio"))]),
    (P, r"At each core's clock \(the folded system\s+at (\S+) MHz, the cancellation-free core at (\S+) MHz\) the "
        r"16-pixel figure is (\S+) times,\s+and at (\S+) MHz the 64-pixel one (\S+) times",
     [("B1: the folded system's Fmax, spans of 16", lambda d: hw_long_span_design(d, spans=16)["fmax_mhz"]),
      ("cross_n1000 Fmax", lambda d: phong_entry(d, "cross_n1000")["fmax_mhz"]),
      ("B1: hardware-setup device / Phong at each core's clock, spans of 16",
       verdict_figure("b1", 16, "hw_ratio_at_clock")),
      ("B1: the folded system's Fmax, spans of 64", lambda d: hw_long_span_design(d, spans=64)["fmax_mhz"]),
      ("B1: hardware-setup device / Phong at each core's clock, spans of 64",
       verdict_figure("b1", 64, "hw_ratio_at_clock"))]),
    (P, r"the cancellation-free core takes (\S+) MULT18X18D where the textbook core takes (\S+), and clocks at (\S+) "
        r"MHz where the textbook core clocks at (\S+) MHz",
     [("cross_n1000 MULT18X18D", lambda d: phong_entry(d, "cross_n1000")["mult18x18d"]),
      ("n1000 MULT18X18D", lambda d: phong_entry(d, "n1000")["mult18x18d"]),
      ("cross_n1000 Fmax", lambda d: phong_entry(d, "cross_n1000")["fmax_mhz"]),
      ("n1000 Fmax", lambda d: phong_entry(d, "n1000")["fmax_mhz"])]),
] + [budget_sentence(label) for label in ("device_b1_n1000", "device_b1_n128", "device_b3_n1000")]

# Markdown tables checked cell by cell: (document, header start, label, keys, {column: value
# function of (Data, key cell)}); the first column is the key; every row must have a source
# entry and every source entry a row. README.md has none since its results are one table of
# sentences (FIGURES above); rtl/fpga/README.md's are FPGA_TABLES and SYNTH_TABLES below.
TABLES = []

def fpga_table():
    """rtl/fpga/README.md's tables: one row per docs/fpga_figures.json run, keyed by core and device."""
    def run(d, k):
        core, part = k
        for r in d.fpga["runs"]:
            if r["core"] == core and r["part"] == part and not r.get("config"):  # the default configuration's
                return r
        raise KeyError(f"{core} {part} not in docs/fpga_figures.json")

    def fmax_text(d, k):
        r = run(d, k)
        return f"{r['fmax_mhz']:.2f}" + ("" if r["fmax_mhz"] >= r["target_mhz"] else " (missed)")

    return {"fit": lambda d, k: "yes",
            "LCs": lambda d, k: f"{run(d, k)['lcs']} / {run(d, k)['lcs_available']}",
            "SB_LUT4": lambda d, k: run(d, k)["sb_lut4"],
            "FFs": lambda d, k: run(d, k)["ffs"],
            "BRAMs": lambda d, k: run(d, k)["brams"],
            "DSPs": lambda d, k: run(d, k)["dsps"],
            "Fmax (MHz)": fmax_text,
            "target": lambda d, k: run(d, k)["target_mhz"],
            "pixels per second": lambda d, k: run(d, k)["fmax_mhz"] * 1e6}  # one pixel per clock


FPGA_TABLES = [
    (F, "| core | device | fit | LCs |", cores)
    for cores in (("specular_unit", "specular_stream"), ("specular_axil",))
]

# rtl/fpga/README.md#the-device-per-error-budget: specular_stream in each configuration of the
# device per error budget (fpga.sh --label device_*, roms/budget/budget_configs.json) beside the
# default configuration's entry (no "config"), on each part in its multiplier style
# (docs/pipeline.md#multiplier-styles), placed and routed (runs and ecp5_runs), and the ratios of
# each count and of Fmax to the default's on the same family of parts. Keyed by core,
# configuration ("default" for the entry without one) and part.
PART_STYLE = (("HX8K", "LUT trees"), ("UP5K", "SB_MAC16 tiles (16-bit)"), ("LFE5U", "MULT18X18D tiles (18-bit)"))
BUDGET_CORE = "specular_stream"


def family(part):
    return next((f for f, _ in PART_STYLE if part.startswith(f)), None)


def budget_entries(d):
    """(core, configuration, part) -> entry, for the budget table."""
    out = {}
    for e in d.fpga["runs"] + d.fpga.get("ecp5_runs", []):
        cfg = e.get("config") or "default"
        if e["core"] != BUDGET_CORE or not (cfg == "default" or cfg.startswith("device_")):
            continue
        if (family(e["part"]), e.get("multipliers", "MULT18X18D tiles (18-bit)")) not in PART_STYLE:
            continue
        out[(e["core"], cfg, e["part"])] = e
    return out


def budget_counts(e):
    """The counts of an entry in one shape for both families: iCE40 (SB_LUT4, SB_CARRY, SB_MAC16,
    SB_RAM40_4K, logic cells) and ECP5 (LUT4, CCU2C, MULT18X18D, DP16KD, TRELLIS_COMB)."""
    if "lcs" in e:
        return {"placed": f"{e['lcs']} / {e['lcs_available']}", "LUT4": e["sb_lut4"], "carry": e["sb_carry"],
                "FFs": e["ffs"], "DSPs": e["dsps"], "BRAMs": e["brams"], "fmax": e["fmax_mhz"]}
    return {"placed": f"{e['trellis_comb']} / {e['trellis_comb_available']}", "LUT4": e["lut4"], "carry": e["ccu2c"],
            "FFs": e["ffs"], "DSPs": e["mult18x18d"], "BRAMs": e["dp16kd"], "fmax": e["fmax_mhz"]}


def budget_default(d, k):
    """The default configuration's entry on the family of parts of key k."""
    fam = family(k[2])
    for (core, cfg, part), e in budget_entries(d).items():
        if core == k[0] and cfg == "default" and family(part) == fam:
            return e
    raise KeyError(f"no default {k[0]} entry on {fam} in docs/fpga_figures.json")


def budget_ratio(d, k, what):
    """count (or Fmax) of k over the default's; '-' when the default's is 0 (no DSP on the HX8K)."""
    a, b = budget_counts(budget_entries(d)[k]), budget_counts(budget_default(d, k))
    what = "fmax" if what == "Fmax" else what
    return "-" if b[what] == 0 and a[what] == 0 else a[what] / b[what]


def budget_fmax_text(d, k):
    e = budget_entries(d)[k]
    return f"{e['fmax_mhz']:.2f}" + ("" if e["fmax_mhz"] >= e["target_mhz"] else " (missed)")


BUDGET_COLUMNS = {
    "placed": lambda d, k: budget_counts(budget_entries(d)[k])["placed"],
    "LUT4": lambda d, k: budget_counts(budget_entries(d)[k])["LUT4"],
    "carry": lambda d, k: budget_counts(budget_entries(d)[k])["carry"],
    "FFs": lambda d, k: budget_counts(budget_entries(d)[k])["FFs"],
    "DSPs": lambda d, k: budget_counts(budget_entries(d)[k])["DSPs"],
    "BRAMs": lambda d, k: budget_counts(budget_entries(d)[k])["BRAMs"],
    "Fmax (MHz)": budget_fmax_text,
    "x LUT4": lambda d, k: budget_ratio(d, k, "LUT4"),
    "x FFs": lambda d, k: budget_ratio(d, k, "FFs"),
    "x DSPs": lambda d, k: budget_ratio(d, k, "DSPs"),
    "x BRAMs": lambda d, k: budget_ratio(d, k, "BRAMs"),
    "x Fmax": lambda d, k: budget_ratio(d, k, "Fmax"),
    "RTL": lambda d, k: f"`{budget_entries(d)[k]['rtl']}`",
}


def synth_key(e):
    """A synthesis-only entry's table key: its core (with the Phong configuration, or the setup's
    SetupII when it is not 1) and part."""
    ii = f" SetupII={e['setup_ii']}" if e.get("setup_ii", 1) != 1 else ""
    return (e["core"] + (f" {e['config']}" if e.get("config") else "") + ii, e["part"])


def synth_entry(d, k):
    for e in d.fpga.get("synthesis_runs", []):
        if synth_key(e) == k:
            return e
    raise KeyError(f"{k[0]} {k[1]} not in docs/fpga_figures.json's synthesis_runs")


# rtl/fpga/README.md's synthesis-only tables (docs/fpga_figures.json "synthesis_runs"): ECP5
# counts (LFE5U-45: 44k LUT4 positions, 72 MULT18X18D; a CCU2C takes two LUT4 positions) and
# the iCE40 runs that Yosys' counts already rule out.
SYNTH_ECP5_COLUMNS = {
    "synthesis": lambda d, k: f"`{synth_entry(d, k)['synthesis']}`",
    "LUT4": lambda d, k: synth_entry(d, k)["lut4"],
    "CCU2C": lambda d, k: synth_entry(d, k)["ccu2c"],
    "TRELLIS_FF": lambda d, k: synth_entry(d, k)["ffs"],
    "MULT18X18D": lambda d, k: synth_entry(d, k)["mult18x18d"],
    "DP16KD": lambda d, k: synth_entry(d, k)["dp16kd"],
    "x LFE5U-45 LUT4": lambda d, k: (synth_entry(d, k)["lut4"] + 2 * synth_entry(d, k)["ccu2c"]) / 44000,
    "x LFE5U-45 MULT18X18D": lambda d, k: synth_entry(d, k)["mult18x18d"] / 72,
    "smallest LFE5U": lambda d, k: synth_entry(d, k)["smallest_lfe5u"] or "none",
    "Yosys (s)": lambda d, k: synth_entry(d, k)["yosys_seconds"],
    "RTL": lambda d, k: f"`{synth_entry(d, k)['rtl']}`",
}
SYNTH_ICE40_COLUMNS = {
    "synthesis": lambda d, k: f"`{synth_entry(d, k)['synthesis']}`",
    "fit": lambda d, k: {False: "no", True: "yes"}[synth_entry(d, k)["fit"]],
    "SB_LUT4": lambda d, k: synth_entry(d, k)["sb_lut4"],
    "FFs": lambda d, k: synth_entry(d, k)["ffs"],
    "BRAMs": lambda d, k: synth_entry(d, k)["brams"],
    "DSPs": lambda d, k: synth_entry(d, k)["dsps"],
    "LCs needed (at least)": lambda d, k: f"{synth_entry(d, k)['lcs_needed_at_least']} / {synth_entry(d, k)['lcs_available']}",
    "x the part": lambda d, k: synth_entry(d, k)["lcs_needed_at_least"] / synth_entry(d, k)["lcs_available"],
    "Yosys (s)": lambda d, k: synth_entry(d, k)["yosys_seconds"],
    "RTL": lambda d, k: f"`{synth_entry(d, k)['rtl']}`",
}
SYNTH_TABLES = [
    (F, "| core | part | synthesis | LUT4 |", SYNTH_ECP5_COLUMNS, lambda e: e["part"] == "ECP5"),
    (F, "| core | part | synthesis | fit |", SYNTH_ICE40_COLUMNS, lambda e: e["part"] != "ECP5"),
]

# Where every number must be a figure above or a constant below: (document, start, end) regular
# expressions; the region runs from the start match to the end match.
FIGURE_REGIONS = [
    (R, r"\A", r"\Z"),  # the whole README: every number it prints is a figure or a constant below
    (F, r"## Measured", r"What the tables say:"),
    (F, r"<!-- synthesis-only figures -->", r"<!-- end of the synthesis-only figures -->"),
    (F, r"<!-- budget figures -->", r"<!-- end of the budget figures -->"),
    (D, r"<!-- FPGA cost per budget -->", r"<!-- end of the FPGA cost per budget -->"),
]
# Numbers in those regions that are not measurements: names, definitions, settings.
NOT_MEASURED = [
    r"UA 71489",                                 # the patent's number
    r"C\+\+20",                                  # the language standard
    r"the patent claims at most 1 %",            # the patent's claim, not a measurement
    r"1-LSB allowance",                          # the check's definition (sim/README.md#what-is-checked-per-pixel)
    r"seed 1\b",                                 # the place-and-route seed
    r"\(256 Kbit, 64 block RAMs\)",              # the patent ROM's size, from its format
    r"4 banks x 4096 x 16 bits = 256 Kbit, 64 block RAMs",
    r"8 banks x\s+256 x 31 bits",                # the configuration
    r"Yosys 0\.23, nextpnr-ice40 0\.4",          # tool versions
    r"commit `[0-9a-f]+`",
    r"4-entry span FIFO",                        # the configuration
    r"(?:ROM|register|multiplier|counter|decoder|control unit) \d+",  # the patent's block numbers
    r"SetupII=\d+",                              # a configuration of the hardware setup
    r"\d+-bit SB_MAC16 tiles",                    # the UP5K's multiplier style (docs/pipeline.md)
    r"\d+ x \d+ tile products",                   # the tile size of that style
    r"CABGA381 -6",                              # an ECP5 part's package and speed grade
    r"spans of (8|16|64)( pixels)?( or more)?",    # a span length of the verdict (scripts/verdict.py)
]


# ------------------------------------------------------------------ checking
def printed(text):
    """The printed number: its value and half a unit of its last digit."""
    t = text.replace(",", "").strip("*")
    m = re.fullmatch(r"-?\d+(?:\.(\d+))?(?:e([+-]?\d+))?", t)
    if not m:
        return None, None
    dec = len(m.group(1) or "")
    exp = int(m.group(2) or 0)
    return float(t), 0.5 * 10.0 ** (exp - dec)


def agrees(text, want):
    if isinstance(want, str):
        return text.strip("*") == want
    got, tol = printed(text)
    if got is None or want is None or (isinstance(want, float) and math.isnan(want)):
        return False
    return abs(got - want) <= tol * (1 + 1e-9) + 1e-12


def fmt_want(want):
    if want is None:
        return "none (no such scene, or the text's claim does not hold)"
    if isinstance(want, str):
        return repr(want)
    return f"{want:.6g}"


def expand(pattern):
    return pattern.replace(" ", r"\s+")


def reprint(text, want):
    """`want` printed the way `text` prints its figure: the same decimals (or significant digits
    of an exponent form), thousands separators and bold markers; None where it cannot be."""
    if isinstance(want, str):
        return want
    if want is None or (isinstance(want, float) and math.isnan(want)):
        return None
    bold = "**" if text.startswith("**") and text.endswith("**") else ""
    t = text.strip("*")
    m = re.fullmatch(r"(-?)([\d,]+)(?:\.(\d+))?(?:e([+-]?\d+))?", t)
    if not m:
        return None
    dec = len(m.group(3) or "")
    if m.group(4) is not None:
        out = f"{want:.{dec}e}"
        mant, exp = out.split("e")
        out = f"{mant}e{'-' if int(exp) < 0 else ('+' if m.group(4).startswith('+') else '')}{abs(int(exp)):0{len(m.group(4).lstrip('+-'))}d}"
    elif "," in m.group(2) or (abs(want) >= 1000 and dec == 0 and len(m.group(2)) > 3):
        out = f"{want:,.{dec}f}"
    else:
        out = f"{want:.{dec}f}"
    return bold + out + bold


def rewritten(text, edits):
    """`text` with the (start, end, new text) edits of check(updates=...) applied."""
    for a, b, new in sorted(edits, reverse=True):
        text = text[:a] + new + text[b:]
    return text


def check(root, specular=None, listing=False, updates=None):
    """Messages, one per failure (empty: every figure agrees). With `updates` (a dict), each
    failing figure adds {document: [(start, end, new text)]} instead of a message where its
    source gives a value to print."""
    errors = []
    texts = {}
    for doc in {R, F, D, P}:
        with open(os.path.join(root, doc)) as f:
            texts[doc] = f.read()
    try:
        d = Data(root, specular)
    except (OSError, ValueError) as e:
        return [f"cannot read the figures' sources: {e}"]
    covered = {doc: [] for doc in texts}  # spans of numbers that are figures or constants

    def compare(doc, name, text, fn, span):
        bound = name.startswith("<")
        label = name.lstrip("<")
        try:
            want = fn(d)
        except (KeyError, IndexError, TypeError, ValueError, subprocess.CalledProcessError, OSError) as e:
            errors.append(f"{doc}: figure '{label}' ({text}): its source has no value: {e}")
            return
        if listing:
            print(f"{doc}: {label}: printed {text}, source {fmt_want(want)}")
        if bound:
            got, _ = printed(text)
            ok = got is not None and want < got
        else:
            ok = agrees(text, want)
        if not ok and updates is not None and not bound and span[1] > span[0]:
            new_text = reprint(text, want)
            if new_text is not None:
                updates.setdefault(doc, []).append((span[0], span[1], new_text))
                return
        if not ok:
            line = texts[doc].count("\n", 0, span[0]) + 1
            rel = "an upper bound of" if bound else "equal to"
            errors.append(f"{doc}:{line}: figure '{label}' prints {text}, not {rel} its source's {fmt_want(want)}")

    for entry in FIGURES:
        doc, pattern, names = entry
        ms = list(re.finditer(expand(pattern), texts[doc]))
        if len(ms) != 1:
            what = names[0][0] if isinstance(names, list) and names else pattern
            errors.append(f"{doc}: figure '{what}': its text /{pattern}/ is found {len(ms)} times, not once")
            continue
        m = ms[0]
        if len(names) != len(m.groups()):
            errors.append(f"{doc}: /{pattern}/ has {len(m.groups())} groups for {len(names)} figures")
            continue
        for i, (name, fn) in enumerate(names, start=1):
            covered[doc].append(m.span(i))
            compare(doc, name, m.group(i), fn, m.span(i))

    for doc, header, label, keys_of, columns in TABLES:
        check_table(doc, texts[doc], header, label, keys_of(d), columns, 1, compare, covered, errors)
    for doc, header, cores in FPGA_TABLES:
        keys = [(r["core"], r["part"]) for r in d.fpga["runs"] if r["core"] in cores and not r.get("config")]
        check_table(doc, texts[doc], header, "docs/fpga_figures.json runs of " + "/".join(cores), keys,
                    fpga_table(), 2, compare, covered, errors, row_filter=lambda cells: cells[0] in cores)

    if d.fpga_budget_keys():
        check_table(F, texts[F], "| core | configuration | part | placed |", "docs/fpga_figures.json runs of the "
                    "device per error budget", d.fpga_budget_keys(), BUDGET_COLUMNS, 3, compare, covered, errors)

    for doc, header, columns, which in SYNTH_TABLES:
        keys = [synth_key(e) for e in d.fpga.get("synthesis_runs", []) if which(e)]
        if not keys and header not in texts[doc]:
            continue  # no such runs yet, and no table
        check_table(doc, texts[doc], header, "docs/fpga_figures.json synthesis_runs", keys, columns, 2,
                    compare, covered, errors)

    # Coverage: every number in a measured region is a figure or a stated constant.
    for doc, start, end in FIGURE_REGIONS:
        text = texts[doc]
        s = re.search(start, text)
        e = re.compile(end).search(text, s.end()) if s else None
        if not s or not e:
            errors.append(f"{doc}: the measured region /{start}/ .. /{end}/ is not found")
            continue
        skip = list(covered[doc])
        skip += [m.span() for m in re.finditer(r"^```.*?^```", text, re.M | re.S)]  # fenced blocks
        skip += [m.span() for m in re.finditer(r"`[^`\n]*`", text)]
        skip += [m.span() for m in re.finditer(r"\]\([^)]*\)", text)]
        for pat in NOT_MEASURED:
            skip += [m.span() for m in re.finditer(expand(pat), text)]
        for m in re.finditer(r"(?<![\w.^])(?<![A-Za-z]-)\d(?:[\d,]*\d)?(?:\.\d+)?(?:e[+-]?\d+)?(?![\w])",
                             text[s.start():e.end()]):
            a, b = m.start() + s.start(), m.end() + s.start()
            if any(x <= a and b <= y for x, y in skip):
                continue
            line = text.count("\n", 0, a) + 1
            ctx = text[max(0, a - 30):b + 10].replace("\n", " ")
            errors.append(f"{doc}:{line}: '{m.group(0)}' is in a measured section but is no figure of "
                          f"tests/docs/check_readme_figures.py (nobody measured it?): ...{ctx}...")
    return errors


def check_table(doc, text, header, label, keys, columns, key_cols, compare, covered, errors, row_filter=None):
    """Every row of the Markdown tables whose header starts with `header` (and whose cells pass
    row_filter) against the source entry of its key (the first key_cols cells)."""
    lines = text.split("\n")
    offsets = [0]
    for ln in lines:
        offsets.append(offsets[-1] + len(ln) + 1)
    seen = []
    found = False
    i = 0
    while i < len(lines):
        if not lines[i].startswith(header):
            i += 1
            continue
        head = [c.strip() for c in lines[i].strip().strip("|").split("|")]
        i += 2  # the |---| line
        while i < len(lines) and lines[i].startswith("|"):
            cells = [c.strip() for c in lines[i].strip().strip("|").split("|")]
            if row_filter and not row_filter(cells):
                i += 1
                continue
            found = True
            key = cells[0] if key_cols == 1 else tuple(cells[:key_cols])
            seen.append(key)
            if key not in keys:
                errors.append(f"{doc}:{i + 1}: table row {key} has no entry in the {label}")
                i += 1
                continue
            # cell spans, for the coverage check
            pos = offsets[i] + 1
            for col, cell_raw in zip(head, lines[i].strip().strip("|").split("|")):
                a = offsets[i] + lines[i].index(cell_raw, pos - offsets[i])
                pos = a + len(cell_raw)
                cell = cell_raw.strip()
                if col in columns:
                    covered[doc].append((a, a + len(cell_raw)))
                    want_fn = columns[col]
                    c0 = a + len(cell_raw) - len(cell_raw.lstrip())
                    compare(doc, f"{col} of {key}", cell, lambda dd, f=want_fn, k=key: f(dd, k), (c0, c0 + len(cell)))
            i += 1
    if not found:
        errors.append(f"{doc}: no table with the header '{header}...'")
    for k in keys:
        if k not in seen:
            errors.append(f"{doc}: the {label} has {k}, which no table row shows")


# ------------------------------------------------------------------ self-test
def self_test(root, specular):
    """A tampered figure, a tampered source, an unmeasured number and a missing figure must each fail,
    with the figure named; the untouched copy must pass."""
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        def fresh():
            dst = os.path.join(tmp, "repo")
            shutil.rmtree(dst, ignore_errors=True)
            for rel in (R, F, D, P, "docs/fpga_figures.json", "docs/measured/sim.json", "docs/measured/scene_bench.json",
                        "scripts/verdict.py", "scripts/fpga_parts.py", "scripts/hw_plane.py",
                        "roms/phong/phong_configs.cmake"):
                os.makedirs(os.path.dirname(os.path.join(dst, rel)), exist_ok=True)
                shutil.copy(os.path.join(root, rel), os.path.join(dst, rel))
            return dst

        def edit(dst, rel, old, new):
            p = os.path.join(dst, rel)
            with open(p) as f:
                t = f.read()
            if old not in t:
                failures.append(f"self-test: '{old}' is not in {rel}")
            with open(p, "w") as f:
                f.write(t.replace(old, new, 1))

        base = check(fresh(), specular)
        if base:
            failures.append("self-test: the untouched copy fails: " + "; ".join(base[:3]))
        d = Data(root, specular)
        fmax = f"{d.pnr('specular_stream', 'HX8K')['fmax_mhz']:.2f}"
        lo = min(d.best(x) for x in d.scenes())
        cases = [
            # (what, file, old, new, text the failure must contain)
            ("README stream HX8K Fmax tampered", R, f"block RAMs, {fmax} MHz",
             "block RAMs, 134.14 MHz", "specular_stream HX8K Fmax"),
            ("rtl/fpga/README.md stream row tampered", F, f"| {fmax} | 100 |", "| 134.14 | 100 |",
             "Fmax (MHz) of ('specular_stream', 'HX8K ct256')"),
            ("docs/fpga_figures.json tampered", "docs/fpga_figures.json", f"\"fmax_mhz\": {fmax}",
             "\"fmax_mhz\": 130.00", "specular_stream HX8K Fmax"),
            ("the speed ratio tampered", R, f"| {lo:.2f} to", f"| {lo + 1:.2f} to",
             "software: device x phong_sleef, both at the best instruction set (lowest)"),
            ("docs/measured/sim.json tampered", "docs/measured/sim.json", '"mismatches": 0', '"mismatches": 1',
             "bit-exact mismatches, every configuration"),
            ("an unmeasured number added", R, "is a valid/ready handshake with AXI4-Stream rules.",
             "is a valid/ready handshake with AXI4-Stream rules, 42 % of them registered.",
             "'42' is in a measured section"),
            ("a figure's text removed", R, "| 0 mismatches, 0 protocol errors |",
             "| 0 protocol errors |", "bit-exact mismatches, every configuration"),
        ]
        # A synthesis-only count tampered in the JSON: the table's cell no longer agrees.
        ecp5 = [e for e in d.fpga.get("synthesis_runs", []) if e["part"] == "ECP5"]
        if ecp5:
            e = ecp5[0]
            cases.append(("a synthesis-only count tampered", "docs/fpga_figures.json",
                          f'"mult18x18d": {e["mult18x18d"]}', f'"mult18x18d": {e["mult18x18d"] + 1}',
                          f"MULT18X18D of {synth_key(e)}"))
        if specular:
            cases.append(("the float-model figure tampered", R, "| 1.09 % |", "| 1.01 % |",
                          "patent float model at n = 3"))
        # The device per error budget: a count of a labelled entry tampered in the JSON, and a
        # ratio of docs/device.md tampered.
        budget = {k: e for k, e in budget_entries(d).items() if k[1] != "default"}
        if budget:
            k, e = next(iter(budget.items()))
            lut = "sb_lut4" if "sb_lut4" in e else "lut4"
            cases.append(("a budget configuration's count tampered", "docs/fpga_figures.json",
                          json.dumps(e), json.dumps(dict(e, **{lut: e[lut] + 1})), f"LUT4 of {k}"))
            b_lo = budget_range(k[1], "LUT4")[0][1](d)
            cases.append(("a budget ratio tampered in docs/device.md", D, f"(`{k[1]}`): LUT4 {b_lo:.2f} to",
                          f"(`{k[1]}`): LUT4 {b_lo + 0.2:.2f} to", f"{k[1]}: x LUT4 (lowest)"))
        for what, rel, old, new, must in cases:
            dst = fresh()
            edit(dst, rel, old, new)
            errs = check(dst, specular)
            if not errs:
                failures.append(f"self-test: {what}: the check passed")
            elif must and not any(must in e for e in errs):
                failures.append(f"self-test: {what}: no message names '{must}': " + "; ".join(errs[:3]))
            else:
                print(f"self-test: {what}: fails as it must: {errs[0]}")
        # A labelled run's entry (fpga.sh --label) ahead of the default configuration's, with other
        # figures: every default figure still reads the default's entry, so the copy passes.
        dst = fresh()
        p = os.path.join(dst, "docs/fpga_figures.json")
        with open(p) as f:
            fig = json.load(f)
        default_hx8k = d.pnr("specular_stream", "HX8K")
        fig["runs"].insert(0, dict(default_hx8k, config="other_label", fmax_mhz=default_hx8k["fmax_mhz"] + 7,
                                   sb_lut4=default_hx8k["sb_lut4"] + 7))
        with open(p, "w") as f:
            json.dump(fig, f)
        errs = check(dst, specular)
        if errs:
            failures.append("self-test: a labelled entry ahead of the default's changes what the check reads: "
                            + "; ".join(errs[:3]))
        else:
            print("self-test: a labelled entry ahead of the default's: the default's figures still agree")
        # --update puts back what a tampered copy changed, each at its printed precision: a count,
        # a percentage and the lowest of a range.
        dst = fresh()
        with open(os.path.join(root, R)) as f:
            original = f.read()
        edit(dst, R, f"block RAMs, {fmax} MHz", "block RAMs, 99.99 MHz")
        rel = 100 * d.cfg("default")["rel_epicenter_with_lsb"]["value"]
        edit(dst, R, f"| {rel:.4f} % relative", "| 0.5000 % relative")
        edit(dst, R, f"| {lo:.2f} to", "| 9.99 to")
        updates = {}
        check(dst, specular, updates=updates)
        p = os.path.join(dst, R)
        with open(p) as f:
            text = f.read()
        text = rewritten(text, updates.get(R, []))
        if text != original or len(updates.get(R, [])) != 3:
            failures.append(f"self-test: --update did not restore the 3 tampered figures ({len(updates.get(R, []))} edits)")
        else:
            print("self-test: --update restores 3 tampered figures")
    return failures


def main(argv):
    args = [a for a in argv if not a.startswith("--")]
    specular = None
    if "--specular" in argv:
        specular = argv[argv.index("--specular") + 1]
        args.remove(specular)
    if len(args) != 1:
        print(__doc__, file=sys.stderr)
        return 2
    root = args[0]
    if "--self-test" in argv:
        failures = self_test(root, specular)
        for f in failures:
            print(f, file=sys.stderr)
        print("check_readme_figures self-test: " + ("FAIL" if failures else "PASS"))
        return 1 if failures else 0
    if "--update" in argv:
        # Rewrites every figure whose source now gives another value, then checks again.
        updates = {}
        check(root, specular, updates=updates)
        for doc, edits in updates.items():
            path = os.path.join(root, doc)
            with open(path) as f:
                text = rewritten(f.read(), edits)
            with open(path, "w") as f:
                f.write(text)
            print(f"{doc}: {len(edits)} figures rewritten")
    errors = check(root, specular, listing="--list" in argv)
    if not specular:
        print("note: without --specular the float-model figure cannot be checked", file=sys.stderr)
    for e in errors:
        print(e, file=sys.stderr)
    print(f"check_readme_figures: {'FAIL' if errors else 'PASS'} ({len(errors)} problems)")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
