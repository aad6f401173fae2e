#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""The measured figures of README.md and rtl/fpga/README.md, checked against the JSON of the runs
that measured them (README.md, section "Where the measured figures live").

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
number in the measured regions of the documents (FIGURE_REGIONS) must belong to a figure or to
a stated non-measured constant (NOT_MEASURED); one that does not ("nobody measured it") fails.

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
    def scene(self, name):
        for x in self.sb["scenes"]:
            if x["scene"] == name:
                return x
        raise KeyError(f"scene {name} not in docs/measured/scene_bench.json")

    def scenes(self, names=None):
        return [x for x in self.sb["scenes"] if names is None or x["scene"] in names]

    def best(self, x, key="speedup"):
        """device x phong_sleef (or a method's ns per pixel) with both at the best instruction set."""
        return x["best_isa"][key]

    def break_even_row(self, key):
        """The longest l of the break-even sweep: the device's or phong_sleef's ns per pixel at the
        best instruction set (the row's names carry it; the baseline ones have none)."""
        isa = self.sb["best_isa"]
        row = self.sb["break_even"][-1]
        if key == "device":
            return row["device" if isa == "baseline" else "device_" + isa]
        return row["phong_sleef_avx512" if isa == "avx512" else "phong_sleef"]

    # place and route
    def pnr(self, core, part):
        for r in self.fpga["runs"]:
            if r["core"] == core and r["part"].startswith(part):
                return r
        raise KeyError(f"{core} {part} not in docs/fpga_figures.json")

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


def span_pixels(x):
    return x["pixels"] / x["spans"]


def lights(x):
    return ", ".join(sorted({"constant" if h.startswith("constant") else "per pixel" for h in x["lights"]}))


# ------------------------------------------------------------------ figures
# A figure: (document, pattern, [(name, value function), ...]) with one group per name. In the
# pattern a space stands for any run of white space (prose is wrapped). Value functions take
# Data; "<" before a name makes the printed number an upper bound of the value instead.
SHORT = ["bunny", "dense_mesh", "spheres"]  # the short-span scenes the prose names
LONG = ["grazing_plane", "wide_glint"]  # 8 or more pixels per span


def rng(fn, names=None):
    return [(lambda d: min(fn(d, x) for x in d.scenes(names))), (lambda d: max(fn(d, x) for x in d.scenes(names)))]


def ranged(doc, pattern, label, fn, names=None):
    lo, hi = rng(fn, names)
    return (doc, pattern, [(label + " (lowest)", lo), (label + " (highest)", hi)])


def stream_scene_total(d, key):
    ss = d.sim["scenes_stream"]
    return sum(s[key] for s in ss.values()) / sum(s["pixels"] for s in ss.values())


R = "README.md"
F = "rtl/fpga/README.md"
FIGURES = [
    # Headline
    ranged(R, r"device method with its scanline setup is (\S+)-(\S+) x as fast", "headline: device x phong_sleef",
           lambda d, x: d.best(x)),
    # The device
    (R, r"\((\S+) cycles per pixel at `l = 2047`, measured by `make sim`\)",
     [("register interface cycles per pixel at l = 2047", lambda d: d.cfg("default")["cycles_per_pixel_long_lines"])]),
    # The streaming core
    (R, r"Measured by `make sim` \(stream stage, (\S+) random spans with gaps, stalls and resets\): (\S+) mismatches, "
        r"(\S+) protocol errors, (\S+) pixels per clock after the fill on `l = 0..3` spans \((\S+) with it\)",
     [("stream stage spans", lambda d: d.sim["stream"]["spans"]),
      ("stream stage mismatches", lambda d: d.sim["stream"]["mismatches"]),
      ("stream stage protocol errors", lambda d: d.sim["stream"]["protocol_errors"]),
      ("stream pixels per clock, l = 0..3, without the fill",
       lambda d: d.sim["stream"]["pixels_per_clock_short_spans_steady"]),
      ("stream pixels per clock, l = 0..3, with the fill", lambda d: d.sim["stream"]["pixels_per_clock_short_spans"])]),
    (R, r"on the scenes \(streamed in the scene stage\), (\S+) clocks per pixel through the stream against (\S+) "
        r"through the register interface's\s+`l \+ L \+ 1` per line \((\S+) on `dense_mesh`\)",
     [("scenes: stream clocks per pixel", lambda d: stream_scene_total(d, "stream_cycles")),
      ("scenes: register interface clocks per pixel", lambda d: stream_scene_total(d, "register_cycles")),
      ("dense_mesh: register interface clocks per pixel",
       lambda d: d.sim["scenes_stream"]["dense_mesh"]["register_clocks_per_pixel"])]),
    # Measured figures and known limits: make sim
    (R, r"`make sim`, every configuration \((\S+) line runs, (\S+) million pixels each",
     [("line runs per configuration", lambda d: d.cfg("default")["lines"]),
      ("pixels per configuration (millions)", lambda d: d.cfg("default")["pixels"] / 1e6)]),
    (R, r"(\S+) bit-exact mismatches, (\S+) protocol errors, every latency as specified\.",
     [("bit-exact mismatches, every configuration", lambda d: sum(c["mismatches"] for c in d.sim["configs"].values())),
      ("protocol errors, every configuration", lambda d: sum(c["protocol_errors"] for c in d.sim["configs"].values()))]),
    (R, r"default build (\S+) % relative in the epicenter",
     [("default: relative error in the epicenter (%)", lambda d: 100 * d.cfg("default")["rel_epicenter_with_lsb"]["value"])]),
    (R, r"and (\S+) C absolute over the lobe; patent build (\S+) % and (\S+) C",
     [("default: absolute error over the lobe (C)", lambda d: d.cfg("default")["abs_lobe_with_lsb"]["value"]),
      ("patent: relative error in the epicenter (%)", lambda d: 100 * d.cfg("patent")["rel_epicenter_with_lsb"]["value"]),
      ("patent: absolute error over the lobe (C)", lambda d: d.cfg("patent")["abs_lobe_with_lsb"]["value"])]),
    (R, r"measured (\S+)% in float, `specular errors --model patent --n 3`",
     [("patent float model at n = 3 (%)",
       lambda d: 100 * float(d.cli("errors", "--model", "patent", "--n", "3")[0]["max_rel_epicenter"]))]),
    (R, r"the patent build's budget is (\S+) %",
     [("patent relative budget (%)", lambda d: 100 * d.cfg("patent")["budget"]["rel_epicenter"])]),
    # Measured figures and known limits: place and route
    (R, r"iCE40-HX8K (\S+) / (\S+) MHz \(target (\S+)\), (\S+) / (\S+) of (\S+) logic cells; iCE40-UP5K (\S+) / (\S+) MHz "
        r"\(target (\S+)\), (\S+) / (\S+) of (\S+) logic cells; (\S+) block RAMs, no DSP",
     [("specular_unit HX8K Fmax", lambda d: d.pnr("specular_unit", "HX8K")["fmax_mhz"]),
      ("specular_stream HX8K Fmax", lambda d: d.pnr("specular_stream", "HX8K")["fmax_mhz"]),
      ("HX8K target", lambda d: d.pnr("specular_stream", "HX8K")["target_mhz"]),
      ("specular_unit HX8K logic cells", lambda d: d.pnr("specular_unit", "HX8K")["lcs"]),
      ("specular_stream HX8K logic cells", lambda d: d.pnr("specular_stream", "HX8K")["lcs"]),
      ("HX8K logic cells available", lambda d: d.pnr("specular_stream", "HX8K")["lcs_available"]),
      ("specular_unit UP5K Fmax", lambda d: d.pnr("specular_unit", "UP5K")["fmax_mhz"]),
      ("specular_stream UP5K Fmax", lambda d: d.pnr("specular_stream", "UP5K")["fmax_mhz"]),
      ("UP5K target", lambda d: d.pnr("specular_stream", "UP5K")["target_mhz"]),
      ("specular_unit UP5K logic cells", lambda d: d.pnr("specular_unit", "UP5K")["lcs"]),
      ("specular_stream UP5K logic cells", lambda d: d.pnr("specular_stream", "UP5K")["lcs"]),
      ("UP5K logic cells available", lambda d: d.pnr("specular_stream", "UP5K")["lcs_available"]),
      ("block RAMs", lambda d: max(r["brams"] for r in d.fpga["runs"] if r["core"] in ("specular_unit", "specular_stream")))]),
    # System speed
    (R, r"2-vCPU AMD EPYC without AVX-512 with nothing else running, `--reps (\d+) --min-time (\S+)`\)",
     [("scene_bench rounds", lambda d: int(re.search(r"median of (\d+) ", d.sb["timer"]).group(1))),
      ("scene_bench min time (s)", lambda d: float(re.search(r">= (\S+) s", d.sb["timer"]).group(1)))]),
]


def names_text(names):
    """Scene names as the prose lists them: "a", "a and b", "a, b and c"; "none" for none."""
    if not names:
        return "none"
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


def goals_figures():
    """The goals and causes bullets under the System speed table (both methods at the best
    instruction set): for each goal the scenes that miss it, computed here, and the figures the
    prose quotes."""
    out = []
    mid = lambda d: [x for x in d.sb["scenes"] if span_pixels(x) >= 2.5]  # noqa: E731
    missed = lambda xs, cond: names_text([x["scene"] for x in xs if cond(x)])  # noqa: E731
    lowest = lambda xs, key: min(xs, key=key)  # noqa: E731
    out.append((R, r"device >= 1\.0 x phong_sleef on every scene: missed on ([\w, ]+?) \(the lowest: (\w+) at (\S+) x;"
                   r" bunny (\S+) x, dense_mesh (\S+) x, spheres (\S+) x\)",
                [("scenes where device < 1.0 x phong_sleef", lambda d: missed(d.sb["scenes"], lambda x: d.best(x) < 1.0)),
                 ("the scene of the lowest device x phong_sleef", lambda d: lowest(d.sb["scenes"], d.best)["scene"]),
                 ("lowest device x phong_sleef", lambda d: min(d.best(x) for x in d.sb["scenes"])),
                 ("bunny: device x phong_sleef", lambda d: d.best(d.scene("bunny"))),
                 ("dense_mesh: device x phong_sleef", lambda d: d.best(d.scene("dense_mesh"))),
                 ("spheres: device x phong_sleef", lambda d: d.best(d.scene("spheres")))]))
    out.append((R, r"2\.5 or more pixels per span: missed on ([\w, ]+?) \(the lowest: (\w+) at (\S+) x, the highest"
                   r" (\S+) x\);",
                [("2.5 or more pixels per span: scenes where device < 1.5 x",
                  lambda d: missed(mid(d), lambda x: d.best(x) < 1.5)),
                 ("2.5 or more pixels per span: the scene of the lowest", lambda d: lowest(mid(d), d.best)["scene"]),
                 ("2.5 or more pixels per span: lowest device x", lambda d: min(d.best(x) for x in mid(d))),
                 ("2.5 or more pixels per span: highest device x", lambda d: max(d.best(x) for x in mid(d)))]))
    out.append((R, r"\(grazing_plane, wide_glint\):\s+(met|missed) \((\S+)-(\S+) x\)",
                [("8 or more pixels per span: met or missed",
                  lambda d: "met" if all(d.best(x) >= 5.0 for x in d.scenes(LONG)) else "missed"),
                 ("8 or more pixels per span: device x (lowest)", lambda d: min(d.best(x) for x in d.scenes(LONG))),
                 ("8 or more pixels per span: device x (highest)", lambda d: max(d.best(x) for x in d.scenes(LONG)))]))
    out.append((R, r"the span rate of the core at (\S+) MHz: missed on\s+([\w, ]+?) \(bunny (\S+) x, dense_mesh (\S+) x,"
                   r" spheres (\S+) x\); met on the other scenes",
                [("scene_bench Fmax (docs/fpga_figures.json at the run)", lambda d: d.sb["fmax_mhz"]),
                 ("scenes where one host core gives < 1.5 x the core's span rate",
                  lambda d: missed(d.sb["scenes"], lambda x: x["setup_over_core_rate"] < 1.5)),
                 ("bunny: setup rate / core rate", lambda d: d.scene("bunny")["setup_over_core_rate"]),
                 ("dense_mesh: setup rate / core rate", lambda d: d.scene("dense_mesh")["setup_over_core_rate"]),
                 ("spheres: setup rate / core rate", lambda d: d.scene("spheres")["setup_over_core_rate"])]))
    out.append(ranged(R, r"on bunny, dense_mesh and spheres the setup costs (\S+)-(\S+) ns per span",
                      "short-span scenes: setup ns per span", lambda d, x: x["device_setup_ns_per_span"], SHORT))
    least = lambda d: min(d.scenes(SHORT), key=lambda x: x["device_setup_ns_per_span"])  # noqa: E731
    out.append((R, r"the least on\s+(\w+), (\S+) % of its spans one pixel long",
                [("short-span scenes: the scene of the least setup ns per span", lambda d: least(d)["scene"]),
                 ("that scene's one-pixel spans (%)", lambda d: 100 * least(d)["spans_l0"] / least(d)["spans"])]))
    out.append(ranged(R, r"per-pixel SLEEF Phong (\S+)-(\S+) ns per pixel\.", "short-span scenes: phong_sleef ns per pixel",
                      lambda d, x: d.best(x, "phong_sleef"), SHORT))
    out.append(ranged(R, r"With (\S+)-(\S+) pixels per span the setup is paid", "short-span scenes: pixels per span",
                      lambda d, x: span_pixels(x), SHORT))
    out.append((R, r"device is at or below phong_sleef from l = (\d+) \((\d+) pixels per span\)\. At l = (\d+): (\S+) "
                   r"against\s+(\S+) ns per pixel",
                [("break-even l at the best instruction set", lambda d: d.sb["break_even_l_isa"][d.sb["best_isa"]]),
                 ("break-even pixels per span", lambda d: d.sb["break_even_l_isa"][d.sb["best_isa"]] + 1),
                 ("break-even sweep: longest l", lambda d: d.sb["break_even"][-1]["l"]),
                 ("break-even sweep: device ns per pixel at the longest l", lambda d: d.break_even_row("device")),
                 ("break-even sweep: phong_sleef ns per pixel at the longest l",
                  lambda d: d.break_even_row("phong_sleef"))]))
    return out


SCENE_STAGE_GOAL = 3.0  # M checked pixels per second, every scene (the goal the README states)


def scene_stage(d, k):
    return d.sim["scenes"][k]


def scene_stage_rtl_rate(d, k):
    """M pixels per second of the Verilator run alone: one clock per pixel, its wall time."""
    x = scene_stage(d, k)
    return x["pixels"] / x["rtl_seconds"] / 1e6


def scene_stage_figures():
    """The bullets under the scene-stage table (make sim's default run, docs/measured/sim.json)."""
    names = lambda d: list(d.sim["scenes"])  # noqa: E731
    met = lambda d: [k for k in names(d) if scene_stage(d, k)["checked_mpix_per_s"] >= SCENE_STAGE_GOAL]  # noqa: E731
    capped = lambda d: [k for k in names(d) if scene_stage_rtl_rate(d, k) < SCENE_STAGE_GOAL]  # noqa: E731
    return [
        (R, r"checked pixels per second on every scene: met on ([\w, ]+?), missed on ([\w, ]+?) \(",
         [("scene stage: scenes at or above the goal", lambda d: names_text(met(d))),
          ("scene stage: scenes below the goal",
           lambda d: names_text([k for k in names(d) if k not in met(d)]))]),
        (R, r"The Verilator model of `specular_stream` alone runs (\S+)-(\S+) M clocks per second on the scenes, below 3 M on ([\w, ]+?)\.",
         [("scene stage: RTL alone, M pixels per second (lowest)", lambda d: min(scene_stage_rtl_rate(d, k) for k in names(d))),
          ("scene stage: RTL alone, M pixels per second (highest)", lambda d: max(scene_stage_rtl_rate(d, k) for k in names(d))),
          ("scene stage: scenes whose RTL alone is below the goal", lambda d: names_text(capped(d)))]),
    ]


TABLES = [
    # make sim's scene stage (docs/measured/sim.json, the first configuration's run of each scene).
    (R, "| scene | pixels | checked M pixels/s |", "docs/measured/sim.json scenes",
     lambda d: list(d.sim["scenes"]),
     {"pixels": lambda d, k: scene_stage(d, k)["pixels"],
      "checked M pixels/s": lambda d, k: scene_stage(d, k)["checked_mpix_per_s"],
      "RTL alone, M pixels/s": scene_stage_rtl_rate,
      "RTL's thread, CPU ms": lambda d, k: 1e3 * scene_stage(d, k)["rtl_thread_cpu_seconds"],
      "other thread, CPU ms": lambda d, k: 1e3 * scene_stage(d, k)["side_thread_cpu_seconds"]}),
    # (document, header start, {column: (name, value function of (Data, key cell))}); the first column
    # is the key; every row must have a source entry and every source entry a row.
    (R, "| scene | spans | pixels per span | H | device |", "scene_bench scenes",
     lambda d: [x["scene"] for x in d.sb["scenes"]],
     {"spans": lambda d, k: d.scene(k)["spans"],
      "pixels per span": lambda d, k: span_pixels(d.scene(k)),
      "H": lambda d, k: lights(d.scene(k)),
      "device": lambda d, k: d.best(d.scene(k), "device"),
      "phong_sleef": lambda d, k: d.best(d.scene(k), "phong_sleef"),
      "phong_scalar": lambda d, k: d.scene(k)["ns_per_pixel"]["phong_scalar"],
      "pow_cos": lambda d, k: d.scene(k)["ns_per_pixel"]["pow_cos"],
      "x": lambda d, k: d.best(d.scene(k)),
      "as defined x": lambda d, k: d.scene(k)["speedup_vs_phong_sleef"]["device"],
      "setup ns/span": lambda d, k: d.scene(k)["device_setup_ns_per_span"],
      "host cores": lambda d, k: d.scene(k)["host_cores_to_feed"],
      "feed": lambda d, k: d.scene(k)["setup_over_core_rate"]}),
]


def fpga_table():
    """rtl/fpga/README.md's tables: one row per docs/fpga_figures.json run, keyed by core and device."""
    def run(d, k):
        core, part = k
        for r in d.fpga["runs"]:
            if r["core"] == core and r["part"] == part:
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
    (R, r"\*\*Headline", r"Figures, goals"),
    (R, r"A line occupies", r"measured by\s+`make sim`\)"),
    (R, r"- Measured by `make sim` \(stream stage", r"\(23\.11 on `dense_mesh`\)|on `dense_mesh`\)\."),
    (R, r"Measured figures and known limits:", r"## Timing diagrams"),
    (R, r"## System speed", r"## Where the measured figures live"),
    (F, r"## Measured", r"On the HX8K the AXI4-Lite core meets"),
    (F, r"<!-- synthesis-only figures -->", r"<!-- end of the synthesis-only figures -->"),
]
# Numbers in those regions that are not measurements: definitions, goals, budgets, settings.
NOT_MEASURED = [
    r"one 2048-pixel line",                      # the benchmark's definition (section 1 of the report)
    r"at least 4 (?:output )?LSB",               # the n = 1 budget rule (sim/README.md)
    r"seed 1\b",                                 # the place-and-route seed
    r"\(256 Kbit, 64 block RAMs\)",              # the patent ROM's size, from its format
    r"2-vCPU",                                   # the machine
    r">= 1\.0 x",                                # goal
    r">= 1\.5 x",                                # goal
    r">= 3 M checked pixels per second",         # goal (scene stage)
    r"below 3 M on",                             # the same goal
    r"2\.5 or more pixels per span",             # goal
    r">= 5 x on every\s+scene with 8 or more pixels per span",  # goal
    r"4 banks x 4096 x 16 bits = 256 Kbit, 64 block RAMs",
    r"8 banks x\s+256 x 31 bits",                # the configuration
    r"Yosys 0\.23, nextpnr-ice40 0\.4",          # tool versions
    r"commit `[0-9a-f]+`",
    r"4-entry span FIFO",                        # the configuration
    r"(?:ROM|register|multiplier|counter|decoder|control unit) \d+",  # the patent's block numbers
    r"\(?(?:its )?section \d+\)?",                 # sections of the report
    r"`l \+ L \+ 1`|`L \+ 1`",                   # the protocol (docs/interfaces.md)
    r"1-LSB allowance",                          # the check's definition (sim/README.md)
    r"`cos` is 0",                               # mathematics
    r"SetupII=\d+",                              # a configuration of the hardware setup
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
    for doc in {R, F}:
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

    for entry in FIGURES + goals_figures() + scene_stage_figures():
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
        keys = [(r["core"], r["part"]) for r in d.fpga["runs"] if r["core"] in cores]
        check_table(doc, texts[doc], header, "docs/fpga_figures.json runs of " + "/".join(cores), keys,
                    fpga_table(), 2, compare, covered, errors, row_filter=lambda cells: cells[0] in cores)

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
            for rel in (R, F, "docs/fpga_figures.json", "docs/measured/sim.json", "docs/measured/scene_bench.json"):
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
        cases = [
            # (what, file, old, new, text the failure must contain)
            ("README stream HX8K Fmax tampered", R, f"/ {fmax} MHz (target",
             "/ 134.14 MHz (target", "specular_stream HX8K Fmax"),
            ("rtl/fpga/README.md stream row tampered", F, f"| {fmax} | 100 |", "| 134.14 | 100 |",
             "Fmax (MHz) of ('specular_stream', 'HX8K ct256')"),
            ("docs/fpga_figures.json tampered", "docs/fpga_figures.json", f"\"fmax_mhz\": {fmax}",
             "\"fmax_mhz\": 130.00", "specular_stream HX8K Fmax"),
            ("a scene timing tampered", R, "| bunny |", "| bunny |", None),
            ("docs/measured/sim.json tampered", "docs/measured/sim.json", '"mismatches": 0', '"mismatches": 1',
             "bit-exact mismatches, every configuration"),
            ("an unmeasured number added", R, "the setup is paid at about that rate per pixel.",
             "the setup is paid at about that rate per pixel, 42 % of it in one loop.",
             "'42' is in a measured section"),
            ("a figure's text removed", R, "0 bit-exact mismatches, 0 protocol errors, every latency",
             "0 protocol errors, every latency", "bit-exact mismatches, every configuration"),
        ]
        # The scene timing case: replace bunny's device ns/px with a different value.
        bunny = d.best(d.scene("bunny"), "device")
        cases[3] = ("a scene timing tampered", R, f"| {bunny:.2f} |", f"| {bunny + 1:.2f} |", "device of bunny")
        # A synthesis-only count tampered in the JSON: the table's cell no longer agrees.
        ecp5 = [e for e in d.fpga.get("synthesis_runs", []) if e["part"] == "ECP5"]
        if ecp5:
            e = ecp5[0]
            cases.append(("a synthesis-only count tampered", "docs/fpga_figures.json",
                          f'"mult18x18d": {e["mult18x18d"]}', f'"mult18x18d": {e["mult18x18d"] + 1}',
                          f"MULT18X18D of {synth_key(e)}"))
        if specular:
            cases.append(("the float-model figure tampered", R, "measured 1.09%", "measured 1.01%",
                          "patent float model at n = 3"))
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
        # --update puts back what a tampered copy changed: a table cell, a number in the prose
        # and a list of scenes that miss a goal, each at its printed precision.
        dst = fresh()
        with open(os.path.join(root, R)) as f:
            original = f.read()
        edit(dst, R, f"| {bunny:.2f} |", f"| {bunny + 1:.2f} |")
        edit(dst, R, "the core at " + f"{d.sb['fmax_mhz']:.2f} MHz", "the core at 99.99 MHz")
        missing = re.search(r"device >= 1\.0 x phong_sleef on every scene:\s+missed on ([\w, ]+?) \(", original)
        if missing:
            edit(dst, R, missing.group(0), missing.group(0).replace(missing.group(1), "grazing_plane"))
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
