#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Write docs/results.md and the generated regions of the Markdown pages from the committed JSON of the runs.

    scripts/results_page.py --write   rewrite docs/results.md and every generated region
    scripts/results_page.py --check   exit 1 when docs/results.md or a generated region differs from
                                      what --write writes (the ctest docs_results_page)
    --specular BIN                    also run the `specular` CLI and compare its figures with
                                      docs/measured/specular_cli.json (--check), or record them
                                      there when they differ (--write)

Sources (each carries its run's commit, date and machine in "provenance"; docs/fpga_figures.json
a date per entry and the commit of the RTL in "rtl"):

    docs/measured/sim.json          sim_regression --json (make sim's defaults)
    docs/measured/sim_setup_ii.json make sim-setup-ii
    docs/measured/scene_bench.json  scene_bench --json over scenes/*.json
    docs/fpga_figures.json          make fpga (place and route) and its synthesis-only runs
    docs/measured/build_time.json   the build's compiler time per rule, make test on a fresh clone
    docs/measured/phong_search.json   phong_search per form and budget: the competitor's narrowest widths
    docs/measured/device_search.json  device_search per budget and n range: the device's narrowest widths
    docs/measured/setup_sweep.json    setup_sweep: the hardware setup's unit width against its contract
    docs/measured/specular_cli.json   the `specular` CLI's float-model figures (--specular BIN checks them)

A generated region is the text between the lines

    <!-- BEGIN generated: NAME (scripts/results_page.py) -->
    <!-- END generated: NAME -->

in any Markdown file of the repository; NAME is one of REGIONS, whose function writes the region
from the same JSON. Each region of REGIONS must be in the file it names, once; an unknown name, a
region without its END line or one in another file fails the check with the file and line.
The design documents (docs/*.md) state what is built and why; the figures a run measured are on
docs/results.md and in these regions only.
"""
import argparse
import datetime
import importlib
import json
import math
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PAGE = "docs/results.md"
SOURCES = {
    "sim": "docs/measured/sim.json",
    "setup_ii": "docs/measured/sim_setup_ii.json",
    "bench": "docs/measured/scene_bench.json",
    "fpga": "docs/fpga_figures.json",
    "build": "docs/measured/build_time.json",
    "phong_search": "docs/measured/phong_search.json",
    "device_search": "docs/measured/device_search.json",
    "setup_sweep": "docs/measured/setup_sweep.json",
    "cli": "docs/measured/specular_cli.json",
    "flip": "docs/measured/colour_flip.json",
    "sweep_b2": "docs/measured/blend_sweep_b2.json",
    "sweep_b4": "docs/measured/blend_sweep_b4.json",
}


class SourceError(Exception):
    pass


def load(root, rel):
    try:
        with open(os.path.join(root, rel)) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        raise SourceError(f"{rel}: {e}")


def provenance(data, rel, need=("commit", "date", "machine", "command")):
    p = data.get("provenance")
    if not isinstance(p, dict) or any(not p.get(k) for k in need):
        raise SourceError(f"{rel} has no \"provenance\" with {', '.join(need)}: a re-run replaces "
                          f"the whole file, so add them again (docs/measured/README.md)")
    return p


def num(x, digits=2):
    """Thousands separators for integers, `digits` decimals for floats."""
    if isinstance(x, bool) or x is None:
        return {True: "yes", False: "no", None: "-"}[x]
    if isinstance(x, int):
        return f"{x:,}"
    return f"{x:,.{digits}f}"


def sci(x):
    return "0" if x == 0 else f"{x:.2e}"


def table(head, rows):
    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return out


def run_line(p, rel):
    return (f"Run: commit `{p['commit']}`, {p['date']}, {p['machine']}; "
            f"`{p['command']}`; [`{os.path.basename(rel)}`]({os.path.relpath(rel, 'docs')}).\n")


def section_sim(sim, rel):
    p = provenance(sim, rel)
    out = ["## Regression: every build configuration", "", run_line(p, rel),
           "Deterministic: any run of the same code and options gives the same counts and errors. "
           f"Seed {sim['seed']}, {num(sim['random_lines_per_config'])} random lines per configuration.", ""]
    rows = []
    for name, c in sim["configs"].items():
        lat = ", ".join(f"{k}" for k in c["latency"])
        rows.append([f"`{name}`", num(c["lines"]), num(c["pixels"]), num(c["mismatches"]),
                     num(c["protocol_errors"]), lat, num(c["cycles_per_pixel_long_lines"], 5),
                     f"{c['budget']['rel_epicenter']} / {c['budget']['abs_lobe']}",
                     sci(c["rel_epicenter_with_lsb"]["value"]), sci(c["abs_lobe_with_lsb"]["value"]),
                     num(c["rel_violations"] + c["abs_violations"] + c["quant_violations"]),
                     num(c["n1_pixels_over_rel_budget"])])
    out += table(["configuration", "lines", "pixels", "mismatches", "protocol errors", "latency (clocks)",
                  "cycles per pixel at `l = 2047`", "budget (rel. epicenter / abs. lobe)",
                  "max rel. epicenter (+1 LSB)", "max abs. lobe (+1 LSB)", "budget violations",
                  "`n = 1` pixels over the rel. budget"], rows)
    s = sim["stream"]
    out += ["", "### The stream stage", "",
            "`specular_stream` under random backpressure, resets and span mixes (same run).", ""]
    out += table(["spans", "pixels", "mismatches", "protocol errors", "resets",
                  "pixels per clock, short spans (steady)", "pixels per clock, mixed spans (steady)"],
                 [[num(s["spans"]), num(s["pixels"]), num(s["mismatches"]), num(s["protocol_errors"]),
                   num(s["resets"]), f"{s['pixels_per_clock_short_spans']:.4f} ({s['pixels_per_clock_short_spans_steady']:.4f})",
                   f"{s['pixels_per_clock_mixed_spans']:.4f} ({s['pixels_per_clock_mixed_spans_steady']:.4f})"]])
    out += ["", "### Scenes", "",
            "Every scene of `scenes/` through the register interface and the stream (same run; "
            "the checked-pixel rate is this run's, two threads).", ""]
    rows = []
    for name, sc in sim["scenes"].items():
        st = sim["scenes_stream"][name]
        rows.append([f"`{name}`", num(sc["spans"]), num(sc["pixels"]), num(sc["mismatches"] + st["mismatches"]),
                     num(sc["protocol_errors"] + st["protocol_errors"]), f"{st['register_clocks_per_pixel']:.2f}",
                     f"{st['stream_clocks_per_pixel']:.4f}", sci(sc["max_device_rel_epicenter"]),
                     f"{sc['max_device_error_abs']:.5f}", f"{sc['checked_mpix_per_s']:.2f}"])
    out += table(["scene", "spans", "pixels", "mismatches", "protocol errors", "register interface clocks per pixel",
                  "stream clocks per pixel", "max device rel. epicenter", "max device abs. error",
                  "checked M pixels/s"], rows)
    out += ["", "### The Phong competitor (`phong_stream`)", "",
            "Every scene through the verilated `phong_stream` in both forms, the textbook `n1000` and the "
            "cancellation-free `cross_n1000`, against its golden model and double per-pixel "
            "Phong (same run; [phong_hw.md](phong_hw.md)), summed over the scenes; spans back to back, so the clocks "
            "beyond one a pixel are the empty pipeline's fill.", ""]
    rows = []
    for cfg, key in (("n1000", "phong"), ("cross_n1000", "phong_cross")):
        vs = list(sim.get(key, {}).values())
        if vs:
            rows.append([f"`{cfg}`", num(len(vs)), num(sum(v["spans"] for v in vs)), num(sum(v["pixels"] for v in vs)),
                         num(sum(v["mismatches"] for v in vs)),
                         num(sum(v["rel_violations"] + v["abs_violations"] for v in vs)),
                         sci(max(v["abs_lsb"] for v in vs)), sci(max(v["rel_lsb"] for v in vs)),
                         ", ".join(sorted({num(v["cycles"] - v["pixels"]) for v in vs}))])
    out += table(["configuration", "scenes", "spans", "pixels", "mismatches", "budget violations", "max abs. error",
                  "max rel. epicenter error", "clocks - pixels per scene"], rows)
    streams = sim.get("stream_by_config", {})
    if streams:
        out += ["", "The stream stage on the blend builds (a tenth of the spans, same run):", ""]
        out += table(["configuration", "spans", "pixels", "mismatches", "protocol errors", "resets",
                      "pixels per clock, short spans (steady)"],
                     [[f"`{k}`", num(v["spans"]), num(v["pixels"]), num(v["mismatches"]), num(v["protocol_errors"]),
                       num(v["resets"]), f"{v['pixels_per_clock_short_spans']:.4f} "
                                         f"({v['pixels_per_clock_short_spans_steady']:.4f})"]
                      for k, v in streams.items()])
    out += ["", "### The system (`specular_system`)", "",
            "Geometry spans through the system, the setup and the stream in hardware (same run; "
            "[setup_hw.md](setup_hw.md#the-system)): bit-exact against `setup_fixed` and the device model; the setup "
            "error is against the reference of the setup's contract "
            "([setup_hw.md](setup_hw.md#the-contract)), the end-to-end error against `C cos^n(psi_i)` of that reference.", ""]
    out += system_rows(sim["system"])
    return out


def section_colour(sim, flip, rel_sim, rel_flip):
    """Per scene: the colour stage of the run (sim/colour_stage.hpp) and the mean FLIP of its images."""
    p = provenance(flip, rel_flip)
    out = ["### Colour", "",
           "Every scene through the RGB core (`Channels = 3`, the default build) with each span's specular "
           "colour, composed on the host, against the composition around the material's BRDF in double "
           "([colour.md](colour.md)); 8-bit sRGB codes over the covered pixels; last column: against "
           "`C cos^n(psi)` of its registers, linear "
           f"([`{os.path.basename(rel_sim)}`]({os.path.relpath(rel_sim, 'docs')}), the run above); mean FLIP over "
           "the whole image at 67 pixels per degree, black background included: " + run_line(p, rel_flip)]
    rows = []
    for name, c in sim["colour"].items():
        f = flip["scenes"].get(name)
        if f is None:
            raise SourceError(f"{rel_flip} has no FLIP of scene {name}: run scripts/colour_flip.py on {rel_sim}")
        rows.append([f"`{name}`", num(c["spans"]), num(c["pixels"]), num(c["mismatches"] + c["protocol_errors"]),
                     num(c["saturated_spans"]),
                     "/".join(str(x) for x in c["srgb8_max"]), "/".join(f"{x:.3f}" for x in c["srgb8_mean"]),
                     f"{f['mean_flip']:.5f}", f"{max(c['device_linear_max']):.2e}"])
    out += table(["scene", "spans", "pixels", "mismatches", "spans with C clamped", "worst R/G/B (codes)",
                  "mean R/G/B (codes)",
                  "mean FLIP", "device alone"], rows)
    return out


def system_rows(sys_):
    rows = [[f"`{k}`", num(v["spans"]), num(v["pixels"]), num(v["mismatches"]), f"{v['setup_lsb']:.2f}",
             sci(v["setup_rel_epicenter"]), f"{v['e2e_lsb']:.1f}", sci(v["e2e_rel_epicenter"]),
             f"{v['px_per_clock_steady']:.4f}"] for k, v in sys_.items()]
    return table(["scene", "spans", "pixels", "mismatches", "setup error (LSB)", "setup rel. epicenter",
                  "end-to-end error (LSB)", "end-to-end rel. epicenter", "pixels per clock (steady)"], rows)


def section_setup_ii(d, rel):
    p = provenance(d, rel)
    out = ["## The system per `SetupII`", "", run_line(p, rel),
           "Deterministic like the regression. Pixels per clock (steady state) of `specular_system` per scene "
           "and initiation interval of its setup ([setup_hw.md](setup_hw.md#the-folded-setup)); "
           "mismatches summed over the scenes.", ""]
    iis = sorted(d["system_setup_ii"], key=int)
    scenes = list(d["system_setup_ii"][iis[0]])
    rows = [[f"`{s}`", num(d["system_setup_ii"][iis[0]][s]["spans"])] +
            [f"{d['system_setup_ii'][ii][s]['px_per_clock_steady']:.4f}" for ii in iis] for s in scenes]
    rows.append(["mismatches", ""] + [num(sum(v["mismatches"] for v in d["system_setup_ii"][ii].values()))
                                      for ii in iis])
    out += table(["scene", "spans"] + [f"`SetupII = {ii}`" for ii in iis], rows)
    return out


def section_bench(b, rel):
    p = provenance(b, rel)
    out = ["## System speed: per scene, setup included", "", run_line(p, rel),
           f"Timer: {b['timer']}. Instruction set: {b['best_isa']} ({b['simd']}). A re-run gives other "
           f"timings; compare methods within one run ([system.md](system.md#what-is-timed)). The core's span "
           f"rate uses Fmax {b['fmax_mhz']} MHz (`specular_stream` on the HX8K, [below](#place-and-route)).", ""]
    rows = []
    for s in b["scenes"]:
        ns = s["ns_per_pixel"]
        rows.append([f"`{s['scene']}`", num(s["spans"]), num(s["pixels"]), f"{s['mean_span']:.2f}",
                     f"{s['best_isa']['device']:.2f}", f"{s['best_isa']['phong_sleef']:.2f}",
                     f"{s['best_isa']['speedup']:.2f}", f"{ns['phong_scalar']:.2f}", f"{ns['pow_cos']:.2f}",
                     f"{s['device_setup_ns_per_span']:.2f}", f"{s['setup_over_core_rate']:.2f}",
                     f"{s['host_cores_to_feed']:.2f}"])
    out += table(["scene", "spans", "pixels", "pixels per span", "device ns/pixel", "phong_sleef ns/pixel",
                  "device x phong_sleef", "phong_scalar ns/pixel", "pow_cos ns/pixel", "setup ns/span",
                  "setup / core span rate", "host cores to feed the core"], rows)
    out += ["", "### Break-even span length", "",
            f"The first `l` at which the device method (setup included) is at or below `phong_sleef` on "
            f"synthetic spans ([system.md](system.md#break-even-span-length)): {b['break_even_l']} "
            f"(per instruction set: " + ", ".join(f"{k} {v}" for k, v in b["break_even_l_isa"].items()) + ").", ""]
    rows = [[str(e["l"]), f"{e['device']:.2f}", f"{e['phong_sleef']:.2f}"]
            for e in b["break_even"] if e["l"] in (0, 1, 2, 3, 4, 7, 15, 31, 63)]
    out += table(["`l`", "device ns/pixel", "phong_sleef ns/pixel"], rows)
    return out


def section_fpga(f, rel):
    prov = f.get("provenance") or {}
    if not prov.get("machine"):
        raise SourceError(f"{rel} has no \"provenance\" with machine (docs/measured/README.md)")
    for e in f["runs"] + f.get("ecp5_runs", []) + f.get("synthesis_runs", []):
        if not e.get("date") or not e.get("rtl"):
            raise SourceError(f"{rel}: the entry {e['core']} {e['part']} has no \"date\" or \"rtl\" "
                              f"(docs/measured/README.md)")
    link = os.path.relpath(rel, "docs")

    def name(e):
        return (f"`{e['core']}`" + (f" {e['config']}" if e.get("config") else "")
                + (f" `SetupII = {e['setup_ii']}`" if e.get("setup_ii", 1) != 1 else ""))

    def part(e):
        return e["part"].split()[0]

    def style(e):
        return e["multipliers"].split(" tiles")[0]

    def tools(entries):
        return "; ".join(sorted({e["tools"] for e in entries}))

    def fmax(e):
        return (f"{e['fmax_mhz']:.2f} / {e['target_mhz']:g}"
                + ("" if e["fmax_mhz"] >= e["target_mhz"] else " (missed)"),)

    out = ["## Place and route", "",
           f"`make fpga` (`scripts/fpga.py`: out of context with registered IO, seed 1; {tools(f['runs'])}), "
           f"one run per core, part and multiplier style on the RTL of the commit in the column \"RTL\" (each run's date is "
           f"in the JSON); machine: "
           f"{prov['machine']}; source [`{rel}`]({link}). LCs: logic cells used; SB_LUT4, SB_CARRY and FFs: Yosys' "
           f"counts, harness included ([rtl/fpga/README.md](../rtl/fpga/README.md)); smallest iCE40: the smaller of "
           f"UP5K and HX8K whose logic cells, block RAMs and SB_MAC16 hold the placed counts. Packages: "
           f"{', '.join(sorted({' '.join(e['part'].split()[1:]) + ' (' + e['part'].split()[0] + ')' for e in f['runs']}))}; "
           f"multipliers: the style of [pipeline.md](pipeline.md#multiplier-styles) (LUT trees, SB_MAC16 or "
           f"MULT18X18D tiles).", ""]
    rows = [[name(e), part(e), style(e), f"`{e['rtl']}`", f"{e['lcs']} / {e['lcs_available']}",
             num(e["sb_lut4"]), num(e["sb_carry"]), num(e["ffs"]), num(e["brams"]), num(e["dsps"]),
             e["smallest_ice40"] or "none", *fmax(e)]
            for e in f["runs"]]
    out += table(["core", "device", "multipliers", "RTL", "LCs", "SB_LUT4", "SB_CARRY", "FFs", "BRAMs",
                  "DSPs", "smallest iCE40", "Fmax / target (MHz)"], rows)
    ecp5 = f.get("ecp5_runs", [])
    if ecp5:
        flows = {syn: chr(ord("A") + i) for i, syn in
                 enumerate(dict.fromkeys(e.get("synthesis", "synth_ecp5") for e in ecp5))}
        out += ["", "### ECP5", "",
                f"Yosys `synth_ecp5`, nextpnr-ecp5 (package CABGA381, speed grade 6, seed 1; {tools(ecp5)}), the "
                "multipliers in the style of the column ([pipeline.md](pipeline.md#multiplier-styles)). TRELLIS_COMB: "
                "LUT4 positions used after packing (LUT4s and carry halves); LUT4, CCU2C and TRELLIS_FF: Yosys' "
                "counts, harness included; smallest LFE5U: the smallest part whose LUT4 positions (LUT4 + 2 CCU2C), "
                "flip-flops, MULT18X18D and DP16KD hold those counts. The column \"syn.\" names the synthesis: "
                + "; ".join(f"{k} `{syn}`" + (" ([hierarchical](../rtl/fpga/README.md#hierarchical-synthesis))"
                                              if "-noflatten" in syn else " ([merged cells](../rtl/fpga/README.md#merged-cells))"
                                              if "opt_merge" in syn else "")
                            for syn, k in flows.items()) + ".", ""]
        rows = [[name(e), part(e), style(e), flows[e.get("synthesis", "synth_ecp5")], f"`{e['rtl']}`",
                 f"{e['trellis_comb']} / {e['trellis_comb_available']}", num(e["lut4"]), num(e["ccu2c"]),
                 num(e["ffs"]), num(e["mult18x18d"]), num(e["dp16kd"]), e["smallest_lfe5u"], *fmax(e)]
                for e in ecp5]
        out += table(["core", "part", "multipliers", "syn.", "RTL", "TRELLIS_COMB", "LUT4", "CCU2C", "TRELLIS_FF",
                      "MULT18X18D", "DP16KD", "smallest LFE5U", "Fmax / target (MHz)"], rows)
    syn = f.get("synthesis_runs", [])

    out += ["", "### Synthesis only: ECP5", "",
            "Yosys `synth_ecp5` counts of runs that were not placed: LUT4 positions are LUT4 + 2 CCU2C; "
            "the LFE5U-45 has 44k LUT4 positions and 72 MULT18X18D. \"Yosys (s)\": the wall time of the run, "
            "on the machine above.", ""]
    rows = [[name(e), f"`{e['rtl']}`", num(e["lut4"]), num(e["ccu2c"]), num(e["ffs"]),
             num(e["mult18x18d"]), num(e["dp16kd"]), f"{(e['lut4'] + 2 * e['ccu2c']) / 44000:.1f}",
             f"{e['mult18x18d'] / 72:.1f}", e["smallest_lfe5u"] or "none", num(e["yosys_seconds"])]
            for e in syn if e["part"] == "ECP5"]
    out += table(["core", "RTL", "LUT4", "CCU2C", "TRELLIS_FF", "MULT18X18D", "DP16KD",
                  "x LFE5U-45 LUT4", "x LFE5U-45 MULT18X18D", "smallest LFE5U", "Yosys (s)"], rows)
    out += ["", "### Synthesis only: iCE40", "",
            "Yosys' counts exceed the part, so nextpnr was not run; a logic cell holds one LUT4 and one "
            "flip-flop, so the larger count is a lower bound of the logic cells.", ""]
    rows = [[name(e), part(e), f"`{e['rtl']}`", f"`{e['synthesis']}`", num(e["fit"]),
             num(e["sb_lut4"]), num(e["ffs"]), num(e["brams"]), num(e["dsps"]),
             f"{e['lcs_needed_at_least']} / {e['lcs_available']}",
             f"{e['lcs_needed_at_least'] / e['lcs_available']:.1f}", num(e["yosys_seconds"])]
            for e in syn if e["part"] != "ECP5"]
    out += table(["core", "part", "RTL", "synthesis", "fit", "SB_LUT4", "FFs", "BRAMs", "DSPs",
                  "LCs needed (at least)", "x the part", "Yosys (s)"], rows)
    return out


def section_phong_search(d, rel):
    p = provenance(d, rel)
    out = ["## The Phong competitor's widths per form and budget", "", run_line(p, rel),
           "`build/bin/phong_search --form F --budget B --n-max N` on the golden model "
           "([phong_hw.md](phong_hw.md#configuration-search)): the narrowest configuration of each form for every "
           "`n` in 1..N, confirmed on the sweeps of two other seeds. Worst over those `n`: relative = "
           "`(|err| - 1 LSB)^+ / ref` in the epicenter, absolute = `(|err| - 1 LSB)^+ / C`, raw = `|err| / C` "
           "(budgets: [metrics.md](metrics.md#budgets)). Widths only: the cells of each are measured on its RTL.", ""]
    rows = [[r["form"], r["budget"].upper(), num(r["n_max"]), f"`{r['describe']}`", sci(r["rel_lsb"]),
             sci(r["abs_lsb"]), sci(r["abs_raw"]), num(r["meets"])] for r in d["runs"]]
    out += table(["form", "budget", "n up to", "configuration", "relative", "absolute", "raw", "meets"], rows)
    return out


def section_device_search(d, rel):
    p = provenance(d, rel)
    runs_all = [x for r in d["runs"] for x in r["runs"]]
    sets = lambda blend: ", ".join(sorted({"{" + ",".join(str(k) for k in x["banks"]) + "}" for x in runs_all
                                           if bool(x.get("blend")) == blend}, key=len))
    out = ["## The device's widths per budget", "", run_line(p, rel),
           "`build/bin/device_search --budget B --n-max N` on the golden model "
           "([device.md](device.md#configurations-per-budget), [display_exact.md](display_exact.md#search)): per bank "
           "set the narrowest widths meeting the budget for every `n` in 1..N, then the set with the fewest ROM bits "
           "(ROM 9 + ROM 12) that the RTL builds (one bank per `n`), whose widths and worst errors over those `n` "
           "are in the row: relative = `(|err| - 1 LSB)^+ / ref` in the epicenter, absolute = `(|err| - 1 LSB)^+ / C`, "
           "raw = `|err| / C`, sRGB = the largest difference of 8-bit sRGB codes at `C = 1` (what a viewer sees, "
           "not a budget). A bank set whose default widths miss the budget does not meet it; where none meets it, the "
           "lowest raw error of any single-bank set is given. The last column is the blended device "
           "([display_exact.md](display_exact.md)) with the fewest ROM bits: its bank set, ROM bits, the fraction of "
           "the budget it uses at its worst `n`, and its sRGB codes. Bank sets tried, one bank per `n`: "
           + sets(False) + "; blended: " + sets(True) + ".", ""]

    def blend_cell(r):
        x = r.get("best_blend")
        if not x:
            return "none"
        return ("{" + ",".join(str(k) for k in x["banks"]) + "}" + f": {num(x['rom_bits'])} bits, "
                f"{num(x['budget_used'], 3)} of it, {num(x['srgb8_codes'])} sRGB")

    rows = []
    for r in d["runs"]:
        meets = [x for x in r["runs"] if x.get("meets") and not x.get("blend")]
        singles = [x for x in r["runs"] if not x.get("blend")]
        x = next((x for x in meets if r["best"] and x["banks"] == r["best"]["banks"]), None)
        if x is None:
            raw = min(y["abs_raw"] for y in singles)
            rows.append([r["budget"].upper(), num(r["n_max"]), f"0 of {len(singles)}", "-", "", "", "", "", "", "",
                         f"lowest {sci(raw)}", "", blend_cell(r)])
            continue
        srgb = num(x["srgb8_codes"]) if "srgb8_codes" in x else "-"
        rows.append([r["budget"].upper(), num(r["n_max"]), f"{len(meets)} of {len(singles)}",
                     "{" + ",".join(str(k) for k in x["banks"]) + "}",
                     f"{x['cos_addr_bits']} / {x['cos_data_bits']} / {x['cos_delta_bits']} / {x['cos_frac_bits']}",
                     f"{x['coef_bits']} / {x['coef_frac']}", num(x["psi_mul_frac"]), num(x["rom_bits"]),
                     sci(x["rel_lsb"]), sci(x["abs_lsb"]), sci(x["abs_raw"]), srgb,
                     blend_cell(r)])
    out += table(["budget", "n up to", "bank sets meeting it", "fewest bits", "ROM 12 addr / data / step / weight bits",
                  "ROM 9 bits / fraction", "psi fraction", "ROM bits", "relative", "absolute", "raw", "sRGB",
                  "blended: fewest bits"], rows)
    return out


def section_setup_sweep(d, rel):
    p = provenance(d, rel)
    out = ["## The setup's widths", "", run_line(p, rel),
           "`build/bin/setup_sweep` on the golden model `host::fixed::setup_fixed` "
           "([setup_hw.md](setup_hw.md#widths)): per unit width F, every span checked against the contract "
           "([setup_hw.md](setup_hw.md#the-contract)). Worst = the largest pixel error as a fraction of the setup's "
           "share (0.01 % + 1 LSB; <= 1 passes); decisions = spans whose status or flat flag differs from the "
           "reference outside the guard bands; in a band = decisions that fell inside one (either outcome accepted). "
           f"Random spans: {num(d['random_spans'])} per width; the default F is {d['default_frac']}.", ""]
    scenes = sorted(d["widths"][0].get("scenes", {}))
    rows = []
    for r in d["widths"]:
        h, x = r["hard"], r["random"]
        rows.append([num(r["frac"]), f"{num(h['worst'], 3)} ({num(h['decision_diffs'])})",
                     f"{num(x['worst'], 3)}", num(x["fails"]), num(x["decision_diffs"]), num(x["in_band"]),
                     num(x["max_lsb"], 2)] + [num(r["scenes"][s]["worst"], 3) for s in scenes] +
                    ["yes" if r["meets"] else "no"])
    out += table(["F", "hard and near-degenerate: worst (decisions)", "random: worst", "fail", "decisions",
                  "in a band", "max LSB"] + [f"{s}: worst" for s in scenes] + ["meets"], rows)
    if d.get("scene_spans"):
        out += ["", "The scenes' spans on the [flat path](setup_hw.md#the-flat-path) (`l = 0`, or `N1 = N2` and "
                    "`H1 = He` as codes):", ""]
        rows = [[s, num(v["spans"]), num(v["one_pixel"]), num(v["flat_path"]),
                 f"{100.0 * v['flat_path'] / max(1, v['spans']):.1f} %"] for s, v in sorted(d["scene_spans"].items())]
        out += table(["scene", "spans", "one-pixel", "flat path", "share"], rows)
    return out


def section_build(b, rel):
    p = provenance(b, rel)
    link = os.path.relpath(rel, "docs")

    def s(x):
        return "-" if x is None else num(x, 1) if isinstance(x, float) else num(x)

    out = ["## Build time", "",
           f"Machine: {p['machine']}; {p['date']}; {p['command']}. The rules are those of "
           f"[README.md](README.md#build-time); \"without\" is the alternative each rule rejected. "
           f"Source [`{rel}`]({link}).", ""]
    rows = [[e["rule"], e["what"], f"`{e['commit']}`", s(e["with_s"]), s(e["without_s"]), e["load"]]
            for e in b["compile"]]
    out += table(["rule", "what is compiled", "commit", "with the rule (CPU s)", "without (CPU s)",
                  "other load"], rows)
    out += [""]
    rows = [[e["what"], f"`{e['commit']}`", e["date"], num(e["seconds"]), num(e["budget_seconds"]),
             num(e["ctest_seconds"]), num(e["tests"]), s(e["tests_own_seconds"])] for e in b["make_test"]]
    out += table(["run", "commit", "date", "wall clock (s)", "budget (s)", "of it ctest (s)", "tests",
                  "the tests' own times (s)"], rows)
    out += [""]
    rows = [[e["what"], f"`{e['commit']}`", s(e["with_s"]), s(e["without_s"])] for e in b["formal"]]
    out += table(["proof", "commit", "with (CPU s)", "without (CPU s)"], rows)
    return out


def generate(data):
    """docs/results.md from the loaded sources (load_all)."""
    out = ["<!-- Generated by scripts/results_page.py from the JSON named in each section; do not edit: "
           "re-run the measurement, update the JSON, then `make results-page`. -->", "",
           "# Measured results", "",
           "The figures measured by the runs of the design: counts, errors, speeds, cell counts and Fmax, each "
           "table with the commit, date and machine of its run. The design documents ([README.md](README.md)) "
           "say what is built and why and link here for what it measured. The ctest `docs_results_page` fails "
           "when this page, or a generated table of the README or of a design page, differs from its JSON.", ""]
    out += section_sim(data["sim"], SOURCES["sim"]) + [""]
    out += section_colour(data["sim"], data["flip"], SOURCES["sim"], SOURCES["flip"]) + [""]
    out += section_setup_ii(data["setup_ii"], SOURCES["setup_ii"]) + [""]
    out += section_bench(data["bench"], SOURCES["bench"]) + [""]
    out += section_fpga(data["fpga"], SOURCES["fpga"]) + [""]
    out += section_phong_search(data["phong_search"], SOURCES["phong_search"]) + [""]
    out += section_device_search(data["device_search"], SOURCES["device_search"]) + [""]
    out += section_setup_sweep(data["setup_sweep"], SOURCES["setup_sweep"]) + [""]
    out += section_build(data["build"], SOURCES["build"])
    return "\n".join(out) + "\n"


def load_all(root):
    data = {k: load(root, rel) for k, rel in SOURCES.items()}
    provenance(data["cli"], SOURCES["cli"])
    data["root"] = root
    return data


# ------------------------------------------------------------------ the `specular` CLI's figures
# Each run: the CLI's arguments; docs/measured/specular_cli.json holds its CSV rows.
CLI_RUNS = [["errors", "--model", "patent", "--n", "3"],
            ["errors", "--model", "patent", "--coef", "minimax", "--n", "3"],
            ["errors", "--model", "prototype", "--n", "10,1000"],
            ["errors", "--model", "schlick", "--n", "10,1000"]]


def cli_value(cell):
    """An integer or a finite float as a number (JSON has no nan), anything else as its text."""
    for conv in (int, float):
        try:
            v = conv(cell)
        except ValueError:
            continue
        if math.isfinite(v):
            return v
    return cell


def run_cli(specular, args):
    """The CSV rows of `specular ARGS` as dicts of numbers and strings."""
    try:
        res = subprocess.run([specular, *args], capture_output=True, text=True, timeout=600)
    except OSError as e:
        raise SourceError(f"cannot run {specular}: {e}")
    if res.returncode != 0:
        raise SourceError(f"`{specular} {' '.join(args)}` exited with {res.returncode}: {res.stderr.strip()[:200]}")
    lines = [ln for ln in res.stdout.splitlines() if ln.strip()]
    if not lines:
        raise SourceError(f"`{specular} {' '.join(args)}` printed no CSV")
    head = lines[0].split(",")
    return [{k: cli_value(v) for k, v in zip(head, ln.split(","))} for ln in lines[1:]]


def cli_rows(data, args):
    for r in data["cli"].get("runs", []):
        if r.get("args") == list(args):
            return r["rows"]
    raise SourceError(f"{SOURCES['cli']} has no run of `specular {' '.join(args)}`: record it with "
                      f"`scripts/results_page.py --write --specular build/bin/specular`")


def cli_differences(data, specular):
    """Where docs/measured/specular_cli.json and the CLI disagree (numbers to a relative 1e-9)."""
    out = []
    for args in CLI_RUNS:
        want = run_cli(specular, args)
        cmd = "specular " + " ".join(args)
        try:
            have = cli_rows(data, args)
        except SourceError as e:
            out.append(str(e))
            continue
        if len(have) != len(want):
            out.append(f"{SOURCES['cli']}: `{cmd}` has {len(have)} rows, {specular} prints {len(want)}")
            continue
        for i, (h, w) in enumerate(zip(have, want)):
            for k in sorted(set(h) | set(w)):
                a, b = h.get(k), w.get(k)
                same = (a == b if not (isinstance(a, (int, float)) and isinstance(b, (int, float)))
                        else abs(a - b) <= 1e-9 * max(abs(a), abs(b)))
                if not same:
                    out.append(f"{SOURCES['cli']}: `{cmd}` row {i} {k} is {a} there, {b} from {specular}")
    return out


def record_cli(root, specular):
    """Rewrite docs/measured/specular_cli.json from the CLI (provenance: this checkout's commit, today)."""
    head = subprocess.run(["git", "-C", root, "rev-parse", "--short", "HEAD"], capture_output=True, text=True)
    data = {"provenance": {"commit": head.stdout.strip() or "unknown", "date": datetime.date.today().isoformat(),
                           "machine": "any: the float model is deterministic",
                           "command": "scripts/results_page.py --write --specular build/bin/specular: "
                                      + "; ".join("build/bin/specular " + " ".join(a) for a in CLI_RUNS)},
            "runs": [{"args": a, "rows": run_cli(specular, a)} for a in CLI_RUNS]}
    with open(os.path.join(root, SOURCES["cli"]), "w") as f:
        json.dump(data, f, indent=1, allow_nan=False)
        f.write("\n")


# ------------------------------------------------------------------ generated regions
def sig(x, digits=3):
    """`digits` significant digits, without an exponent."""
    if x == 0:
        return "0"
    d = max(0, digits - 1 - int(math.floor(math.log10(abs(x)))))
    return f"{x:.{d}f}"


def scripts_module(name):
    """scripts/NAME.py beside this file (verdict, hw_plane)."""
    here = os.path.dirname(os.path.abspath(__file__))
    if here not in sys.path:
        sys.path.insert(0, here)
    return importlib.import_module(name)


VERDICT_SPANS = (1, 8, 16, 64)


def verdict_rows(data):
    """scripts/verdict.py on the record: every configuration at the budget it was built for."""
    if "_verdict" not in data:
        verdict, hw_plane = scripts_module("verdict"), scripts_module("hw_plane")
        configs = hw_plane.phong_configs(os.path.join(data["root"], "roms", "phong", "phong_configs.cmake"))
        pts = verdict.record_points(data["fpga"], configs)
        data["_verdict"] = (pts, verdict.verdict(pts, [(str(m), m, None) for m in VERDICT_SPANS]))
    return data["_verdict"]


def ratio(r):
    return "-" if r is None else f"{r:.2f} x"


def pnr(data, core, part):
    """The default configuration's iCE40 run of a core on a part."""
    for r in data["fpga"]["runs"]:
        if r["core"] == core and r["part"].startswith(part) and not r.get("config"):
            return r
    raise SourceError(f"{SOURCES['fpga']} has no run of {core} on the {part}")


def region_results(data):
    """README.md's Results table."""
    sim, bench = data["sim"], data["bench"]
    cfgs = sim["configs"]

    def every(key):
        v = sorted({c[key] for c in cfgs.values()})
        return v[0] if len(v) == 1 else None

    def total(key):
        return (sum(c[key] for c in cfgs.values()) + sum(s[key] for s in sim["scenes"].values())
                + sum(s[key] for s in sim["scenes_stream"].values()) + sim["stream"][key])

    lines, pixels = every("lines"), every("pixels")
    each = (f"{num(lines)} lines, {pixels / 1e6:.1f} M pixels each" if lines is not None and pixels is not None
            else "lines and pixels per configuration in the results")
    ss = sim["scenes_stream"].values()
    px = sum(s["pixels"] for s in ss)
    d, p, one = cfgs["default"], cfgs["patent"], cfgs["single"]
    patent_n3 = cli_rows(data, CLI_RUNS[0])[0]["max_rel_epicenter"]
    hx, up = pnr(data, "specular_stream", "HX8K"), pnr(data, "specular_stream", "UP5K")
    _, res = verdict_rows(data)

    def budget_row(b):
        row = {r["mean"]: r for r in res[b]}
        if any(row[m][k] is None for m in (1, 8, 16, 64) for k in ("host_ratio", "hw_ratio")):
            raise SourceError(f"{SOURCES['fpga']}: the verdict at {b.upper()} lacks a design on one side")
        return row, row[1]["phong"]["name"].split()[1]

    def hw_text(row):
        return (f"{ratio(row[1]['host_ratio'])} ({ratio(row[1]['host_ratio_at_clock'])} at each core's clock); with "
                f"the setup in hardware {ratio(row[8]['hw_ratio'])} on spans of 8 pixels, {ratio(row[16]['hw_ratio'])} "
                f"on spans of 16 ({ratio(row[16]['hw_ratio_at_clock'])} at each core's clock), "
                f"{ratio(row[64]['hw_ratio'])} on spans of 64 or more ({ratio(row[64]['hw_ratio_at_clock'])})")
    for key, build in (("sweep_b2", "default"), ("sweep_b4", "blend-b4")):
        if data[key].get("config") != build:
            raise SourceError(f"{SOURCES[key]} sweeps {data[key].get('config')}, not the build {build}: run "
                              f"device_search --sweep {build} --json {SOURCES[key]}")
    b2, phong2 = budget_row("b2")
    b1, phong1 = budget_row("b1")
    speed = [s["best_isa"]["speedup"] for s in bench["scenes"]]
    rows = [
        [f"RTL against the golden model, every configuration ({each}) and the scenes",
         f"{num(total('mismatches'))} mismatches, {num(total('protocol_errors'))} protocol errors", "`make sim`"],
        ["worst device error against `C cos^n(psi)` (1-LSB allowance), the default build (two banks blended per "
         "`n`, [display_exact.md](docs/display_exact.md)); its dense sweep of every `n <= 1000` as a share of B2 "
         "(`2^-9 C`, no allowance)",
         f"{sig(d['abs_lobe_with_lsb']['value'])} C over the lobe; {data['sweep_b2']['budget_used']:.3f} of B2",
         "`make sim`, `device_search --sweep default`"],
        ["the same, single-bank build (`single`, B1) and patent build",
         f"{sig(100 * one['rel_epicenter_with_lsb']['value'])} % relative in the epicenter, "
         f"{sig(one['abs_lobe_with_lsb']['value'])} C over the lobe; {sig(100 * p['rel_epicenter_with_lsb']['value'])} "
         f"% and {sig(p['abs_lobe_with_lsb']['value'])} C", "`make sim`"],
        ["the patent's method with its own coefficients at `n = 3`, floating point (the patent claims at most 1 %)",
         f"{sig(100 * patent_n3)} %", "`specular errors`"],
        ["`specular_stream`, spans of `l = 0..3` back to back, after the fill",
         f"{sim['stream']['pixels_per_clock_short_spans_steady']:.4f} pixels per clock", "`make sim`"],
        ["the scenes of `scenes/`: clocks per pixel through `specular_stream` / `specular_unit`",
         f"{sum(s['stream_cycles'] for s in ss) / px:.4f} / {sum(s['register_cycles'] for s in ss) / px:.2f}",
         "`make sim`"],
        ["`specular_stream` (default build) on the iCE40-HX8K, out of context",
         f"{num(hx['sb_lut4'])} SB_LUT4, {num(hx['lcs'])} of {num(hx['lcs_available'])} logic cells, "
         f"{num(hx['brams'])} block RAMs, {hx['fmax_mhz']:.2f} MHz", "`make fpga`"],
        ["`specular_stream` (default build) on the iCE40-UP5K",
         f"{num(up['lcs'])} of {num(up['lcs_available'])} logic cells, {up['fmax_mhz']:.2f} MHz", "`make fpga`"],
        ["hardware, ECP5 with MULT18X18D tiles on both sides, `n <= 1000` at B2 (the default build's budget): pixels "
         f"per clock per LFE5U-85F of the device (setup on a host) over the best per-pixel Phong core (`{phong2}`)",
         hw_text(b2), "`make fpga`, `make report`"],
        [f"the same at B1 (the single-bank builds) against `{phong1}`", hw_text(b1), "`make fpga`, `make report`"],
        ["the blend at B4 (`blend-b4`), dense sweep of every `n <= 1000` as a share of B4 (`2^-11 C`); pixels per "
         "clock per part (setup on a host) over the best Phong core at B4",
         f"{data['sweep_b4']['budget_used']:.3f} of B4; {ratio(res['b4'][0]['host_ratio'])} "
         f"(`{res['b4'][0]['phong']['name'].split()[1]}`)", "`device_search --sweep blend-b4`, `make fpga`"],
        ["software: the device method with its setup against per-pixel Phong (SLEEF), per scene",
         f"{min(speed):.2f} to {max(speed):.2f} x as fast", "`scene_bench`"],
    ]
    return table(["what", "measured", "by"], rows)


PART_FAMILIES = ("HX8K", "UP5K", "LFE5U")


def budget_counts(e):
    """LUT4, flip-flops, DSPs, block RAMs and Fmax of an iCE40 or an ECP5 entry."""
    if "lcs" in e:
        return {"LUT4": e["sb_lut4"], "FFs": e["ffs"], "DSPs": e["dsps"], "BRAMs": e["brams"], "Fmax": e["fmax_mhz"]}
    return {"LUT4": e["lut4"], "FFs": e["ffs"], "DSPs": e["mult18x18d"], "BRAMs": e["dp16kd"], "Fmax": e["fmax_mhz"]}


def budget_entries(data):
    """{label: {family: entry}} for specular_stream's default configuration (label None) and the
    configurations per error budget (device_*), placed and routed on each family of parts in its
    multiplier style (iCE40 runs; the ECP5's entry of the current flow, scripts/verdict.py)."""
    verdict = scripts_module("verdict")
    f = data["fpga"]
    labels = [None] + sorted({e["config"] for e in f["runs"] + f.get("ecp5_runs", [])
                              if e["core"] == "specular_stream" and (e.get("config") or "").startswith("device_")})
    out = {}
    for label in labels:
        fam = {}
        for e in f["runs"]:
            if e["core"] == "specular_stream" and e.get("config") == label:
                fam[e["part"].split()[0]] = e
        e = verdict.ecp5_entry(f, "specular_stream", label)
        if e and e.get("placed"):
            fam["LFE5U"] = e
        out[label] = fam
    return out


def region_device_budget(data):
    """docs/device.md: each configuration per error budget against the default build on the same
    family of parts, the lowest to the highest ratio over the families (a DSP ratio only where the
    default has DSPs)."""
    ent = budget_entries(data)
    default = ent.pop(None)
    rows = []
    for label, fam in ent.items():
        m = re.fullmatch(r"device_(b\d)_n(\d+)", label)
        cells = []
        for what in ("LUT4", "FFs", "DSPs", "BRAMs", "Fmax"):
            r = [budget_counts(e)[what] / budget_counts(default[k])[what] for k, e in fam.items()
                 if k in default and budget_counts(default[k])[what]]
            cells.append(f"{min(r):.2f} to {max(r):.2f}" if r else "-")
        rows.append([f"`{label}`", m.group(1).upper() if m else "?", f"<= {m.group(2)}" if m else "?",
                     ", ".join(k for k in PART_FAMILIES if k in fam and k in default)] + cells)
    return table(["configuration", "budget", "`n`", "parts", "x LUT4", "x flip-flops", "x DSPs", "x block RAMs",
                  "x Fmax"], rows)


def positions(e):
    return e["lut4"] + 2 * e["ccu2c"]


def region_phong_cost(data):
    """docs/phong_hw.md: each Phong configuration's ECP5 run (MULT18X18D tiles on both sides) and
    HX8K synthesis (LUT trees) against specular_stream's, as counts and multiples of the stream's."""
    verdict = scripts_module("verdict")
    f = data["fpga"]
    dev = verdict.ecp5_entry(f, "specular_stream")
    hx = pnr(data, "specular_stream", "HX8K")
    if not dev:
        raise SourceError(f"{SOURCES['fpga']} has no ECP5 entry of specular_stream")

    def cell(a, b):
        return f"{num(a)} ({a / b:.1f} x)" if b else num(a)

    rows = [["`specular_stream`", dev["part"].split()[0], num(positions(dev)), num(dev["ffs"]), num(dev["mult18x18d"]),
             f"{dev['fmax_mhz']:.2f}", num(hx["sb_lut4"])]]
    hw_plane = scripts_module("hw_plane")
    order = list(hw_plane.phong_configs(os.path.join(data["root"], "roms", "phong", "phong_configs.cmake")))
    configs = sorted({e["config"] for e in f.get("ecp5_runs", []) if e["core"] == "phong_stream"
                      and not e["config"].endswith("_consth")},  # the verdict's: H per pixel
                     key=lambda c: (order.index(c) if c in order else len(order), c))
    for c in configs:
        e = verdict.ecp5_entry(f, "phong_stream", c)
        h = next((x for x in f.get("synthesis_runs", []) + f["runs"]
                  if x["core"] == "phong_stream" and x.get("config") == c and x["part"].startswith("HX8K")), None)
        rows.append([f"`{c}`", e["part"].split()[0], cell(positions(e), positions(dev)), cell(e["ffs"], dev["ffs"]),
                     cell(e["mult18x18d"], dev["mult18x18d"]), f"{e['fmax_mhz']:.2f}" if e.get("fmax_mhz") else "-",
                     cell(h["sb_lut4"], hx["sb_lut4"]) if h else "-"])
    return table(["core", "ECP5 part", "LUT4 positions", "flip-flops", "MULT18X18D", "Fmax (MHz)",
                  "HX8K SB_LUT4 (LUT trees)"], rows)


def region_verdict(data):
    """docs/phong_hw.md: the verdict of the record, one row per budget: the best Phong core, the device
    with its setup on a host and in hardware per span length (at each core's clock in brackets), the
    system each span length takes, and the break-even span length against the best Phong core."""
    verdict = scripts_module("verdict")
    pts, res = verdict_rows(data)

    def short(name):  # "device system, SetupII=16 (setup in hardware)" -> "16"
        return name.split("SetupII=")[1].split(" ")[0]

    rows = []
    for b, rs in res.items():
        ph = {r["phong"]["name"].split(" ", 1)[1] for r in rs if r["phong"]}
        row = [b.upper(), ", ".join(f"`{x}`" for x in sorted(ph)) or "none meets it"]
        if all(r["host"] is None and r["hw"] is None for r in rs):
            rows.append(row + ["no device design meets it"] + [""] * (len(rs) + 2))
            continue
        row.append(f"{ratio(rs[0]['host_ratio'])} ({ratio(rs[0]['host_ratio_at_clock'])})")
        row += [f"{ratio(r['hw_ratio'])} ({ratio(r['hw_ratio_at_clock'])})" for r in rs]
        row.append(", ".join(short(r["hw"]["name"]) if r["hw"] else "-" for r in rs))
        be = verdict.break_even(pts, b)
        row.append("-" if be is None else f"{be['span']:.1f} pixels" if be["span"] is not None
                   else f"none ({be['ratio_at_long_spans']:.2f} x on long spans)")
        rows.append(row)
    out = table(["budget", "best Phong core", "setup on a host"]
                + [f"setup in hardware, spans of {m}" for m in VERDICT_SPANS]
                + ["`SetupII` per span length", "break-even span"], rows)
    each = [(b, verdict.break_even_each(pts, b)) for b in res]
    lines = [f"{b.upper()}: " + "; ".join(
        f"`{e['phong'].split(' ', 1)[1]}` " + (f"{e['span']:.1f}" if e["span"] is not None else "none")
        for e in es) for b, es in each if len(es) > 1]
    if lines:
        out += ["", "Break-even span length against each Phong core that meets the budget, in pixels: "
                + "; ".join(lines) + "."]
    return out


def region_system_cost(data):
    """docs/setup_hw.md: the setup alone and the system per SetupII on the ECP5 (the entries the
    verdict takes), with the share of an LFE5U-85F on the binding resource."""
    verdict = scripts_module("verdict")
    f = data["fpga"]
    rows = []
    setup = verdict.ecp5_entry(f, "specular_setup")
    iis = sorted({e.get("setup_ii") or 1 for e in f.get("ecp5_runs", []) + f.get("synthesis_runs", [])
                  if e["core"] == "specular_system" and not e.get("config")})
    for name, e, k in ([("setup alone", setup, 1)] if setup else []) + \
            [("system", verdict.ecp5_entry(f, "specular_system", None, None if k == 1 else k), k) for k in iis]:
        sh, res = verdict.share(e)
        rows.append([name, str(k), e["part"].split()[0] if e.get("placed") else "synthesis only",
                     num(positions(e)), num(e["ffs"]), num(e["mult18x18d"]), num(e["dp16kd"]),
                     f"{e['fmax_mhz']:.2f}" if e.get("fmax_mhz") else "-", f"{100 * sh:.1f} % ({res})",
                     f"`{e['rtl']}`"])
    return table(["design", "`SetupII`", "placed on", "LUT4 positions", "flip-flops", "MULT18X18D", "DP16KD",
                  "Fmax (MHz)", "share of an LFE5U-85F (binding)", "RTL"], rows)


def region_claims(data):
    """docs/reflectance.md: the sources' claims against the float model (the `specular` CLI's runs)."""
    def pct(rows, key="max_rel_epicenter"):
        return " and ".join(f"{sig(100 * r[key])} % at `n = {r['n']}`" for r in rows)

    patent, minimax, proto, schlick = (cli_rows(data, a) for a in CLI_RUNS)
    rows = [["`<= 1 %` epicenter error with `k` in {1, 2, 4, 16}", "patent",
             f"not at `n = 3` with its own coefficients: {pct(patent)}; with minimax coefficients {pct(minimax)}"],
            ["the prototype errs by more than 10 %", "patent", f"{pct(proto)}: large, but not 10 % by this metric"],
            ["Schlick's function errs by up to 10 % in the epicenter", "Schlick-modification paper",
             f"{pct(schlick)}: confirmed"],
            ["`lyon-16` is not energy-correct for small `n`; `(n+6)/24.55` fixes it for every `n` in 1..1000",
             "energy-correct paper", "the albedo section of the report (`make report`); the claim depends on the "
             "convention ([metrics.md](metrics.md#hemispherical-albedo))"]]
    return table(["claim", "source", "measured here (`specular errors`)"], rows)


PICTURE_SCENE = "duck_colour"  # scripts/readme_picture.py's default scene


def region_picture(data):
    """README.md's caption of its picture (scripts/readme_picture.py): the colour stage's figures."""
    c = data["sim"].get("colour", {}).get(PICTURE_SCENE)
    f = data["flip"]["scenes"].get(PICTURE_SCENE)
    if c is None or f is None:
        raise SourceError(f"{SOURCES['sim']} or {SOURCES['flip']} has no colour figures of {PICTURE_SCENE}")
    dev = max(c["device_linear_max"])
    return [f"`scenes/{PICTURE_SCENE}.json` (the COLLADA duck of Debian's `assimp-testmodels` under three coloured "
            "lights) rasterized into spans, set up on the host, every span of every light streamed with its specular "
            "colour through `specular_stream` with `Channels = 3` (the default build, budget B2) in Verilator, "
            "the channels added on the host (left, [colour.md](docs/colour.md)); the same composition around "
            "`C cos^n(psi)` of the RTL's own registers in double (middle); their difference in 8-bit sRGB codes, "
            f"amplified (right): at most {dev:.2e} of full scale in linear value ({dev / 2 ** -9:.2f} of `2^-9`), "
            f"{'/'.join(str(x) for x in c['device_srgb8_max'])} codes (R/G/B). Against the composition around the "
            "material's BRDF in double, which adds the setup's error: "
            f"{'/'.join(f'{x:.2e}' for x in c['linear_max'])} of full scale, "
            f"{'/'.join(str(x) for x in c['srgb8_max'])} codes, mean "
            f"{'/'.join(f'{x:.3f}' for x in c['srgb8_mean'])}, mean FLIP {f['mean_flip']:.4f}; "
            f"{num(c['mismatches'])} mismatches against the golden model. `make readme-picture` draws it again "
            "([`scripts/readme_picture.py`](scripts/readme_picture.py)); every scene's figures: "
            "[results.md](docs/results.md#colour)."]


# name: (the file it must be in, its function of the loaded sources)
REGIONS = {
    "results": ("README.md", region_results),
    "picture": ("README.md", region_picture),
    "device_budget": ("docs/device.md", region_device_budget),
    "phong_cost": ("docs/phong_hw.md", region_phong_cost),
    "verdict": ("docs/phong_hw.md", region_verdict),
    "system_cost": ("docs/setup_hw.md", region_system_cost),
    "claims": ("docs/reflectance.md", region_claims),
}
MARK = "(scripts/results_page.py)"
BEGIN = re.compile(r"^<!-- BEGIN generated: (\S+) \(scripts/results_page\.py\) -->$")
END = "<!-- END generated: {} -->"


def markdown_files(root):
    """Every Markdown file of the tree, build directories (those with a CMakeCache.txt) and hidden ones aside."""
    out = []
    for d, dirs, files in os.walk(root):
        dirs[:] = sorted(x for x in dirs if not x.startswith(".")
                         and not os.path.exists(os.path.join(d, x, "CMakeCache.txt")))
        out += [os.path.relpath(os.path.join(d, f), root) for f in sorted(files) if f.endswith(".md")]
    return out


def regions(root, data):
    """{file: (its text now, its text with every region rewritten)} for the files holding regions, and
    the problems (unknown, unclosed, misplaced or missing regions)."""
    out, problems, seen = {}, [], {}
    for rel in markdown_files(root):
        if rel == PAGE:
            continue
        with open(os.path.join(root, rel)) as f:
            text = f.read()
        if MARK not in text:
            continue
        lines = text.split("\n")
        new, i = [], 0
        while i < len(lines):
            new.append(lines[i])
            # A region of another generator (another name in its BEGIN line) is left alone.
            if not (lines[i].startswith("<!-- BEGIN generated:") and MARK in lines[i]):
                i += 1
                continue
            m = BEGIN.match(lines[i])
            if not m:
                problems.append(f"{rel}:{i + 1}: a region's first line must be "
                                f"'<!-- BEGIN generated: NAME (scripts/results_page.py) -->', not '{lines[i]}'")
                i += 1
                continue
            name = m.group(1)
            end = next((j for j in range(i + 1, len(lines)) if lines[j] == END.format(name)), None)
            if end is None:
                problems.append(f"{rel}:{i + 1}: the generated region '{name}' has no line '{END.format(name)}'")
                i += 1
                continue
            if name not in REGIONS:
                problems.append(f"{rel}:{i + 1}: no generated region is called '{name}' "
                                f"(scripts/results_page.py REGIONS: {', '.join(REGIONS)})")
            elif REGIONS[name][0] != rel:
                problems.append(f"{rel}:{i + 1}: the generated region '{name}' belongs in {REGIONS[name][0]}")
            else:
                seen.setdefault(name, []).append(f"{rel}:{i + 1}")
                try:
                    new += REGIONS[name][1](data)
                except (SourceError, KeyError, TypeError, ValueError, IndexError) as e:
                    problems.append(f"{rel}:{i + 1}: cannot generate the region '{name}': {e}")
                    new += lines[i + 1:end]
                new.append(lines[end])
                i = end + 1
                continue
            new += lines[i + 1:end + 1]
            i = end + 1
        out[rel] = (text, "\n".join(new))
    for name, (rel, _) in REGIONS.items():
        if len(seen.get(name, [])) != 1:
            problems.append(f"{rel}: the generated region '{name}' is there {len(seen.get(name, []))} times, not once "
                            f"(its lines: '<!-- BEGIN generated: {name} (scripts/results_page.py) -->' and "
                            f"'{END.format(name)}')")
    return out, problems


def first_difference(have, want):
    """The first line that differs, and the two texts around the first character that does."""
    a, b = have.split("\n"), want.split("\n")
    for i, (x, y) in enumerate(zip(a, b)):
        if x != y:
            c = next((k for k, (p, q) in enumerate(zip(x, y)) if p != q), min(len(x), len(y)))
            lo = max(0, c - 30)
            return i + 1, f"has '...{x[lo:c + 30]}...', expected '...{y[lo:c + 30]}...'"
    return min(len(a), len(b)) + 1, f"{len(a)} lines, expected {len(b)}"


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    g = ap.add_mutually_exclusive_group(required=True)
    g.add_argument("--check", action="store_true",
                   help="exit 1 when docs/results.md or a generated region is not what --write writes")
    g.add_argument("--write", action="store_true", help="rewrite docs/results.md and every generated region")
    ap.add_argument("--root", default=ROOT, help="repository root (default: this script's)")
    ap.add_argument("--specular", help="the `specular` CLI: check (--check) or record (--write) its figures")
    a = ap.parse_args(argv)
    try:
        data = load_all(a.root)
        stale = cli_differences(data, a.specular) if a.specular else []
        if stale and a.write:
            record_cli(a.root, a.specular)
            print(f"results_page: recorded the `specular` CLI's figures in {SOURCES['cli']}")
            data, stale = load_all(a.root), []
        text = generate(data)
        files, problems = regions(a.root, data)
    except (SourceError, KeyError, TypeError) as e:
        print(f"results_page: cannot generate {PAGE}: {e}", file=sys.stderr)
        return 2
    for msg in problems:
        print(f"results_page: {msg}", file=sys.stderr)
    path = os.path.join(a.root, PAGE)
    if a.write:
        with open(path, "w") as f:
            f.write(text)
        for rel, (old, new) in files.items():
            if new != old:
                with open(os.path.join(a.root, rel), "w") as f:
                    f.write(new)
                print(f"results_page: rewrote the generated regions of {rel}")
        print(f"results_page: wrote {PAGE}")
        return 1 if problems else 0
    failures = list(problems) + stale
    try:
        with open(path) as f:
            have = f.read()
    except OSError:
        have = None
    if have != text:
        why = "is missing" if have is None else "differs from what its JSON gives (first at line %d: %s)" % \
            first_difference(have, text)
        failures.append(f"{PAGE} {why}")
    for rel, (old, new) in files.items():
        if new != old:
            line, what = first_difference(old, new)
            name = next((BEGIN.match(x).group(1) for x in reversed(old.split("\n")[:line]) if BEGIN.match(x)), "?")
            failures.append(f"{rel}:{line}: the generated region '{name}' differs from what its JSON gives ({what})")
    for msg in failures[len(problems):]:
        print(f"results_page: {msg}", file=sys.stderr)
    if failures:
        print(f"results_page: {len(failures)} problems; run `make results-page` (scripts/results_page.py --write"
              + (f" --specular {a.specular}" if a.specular else "") + ") and commit the result", file=sys.stderr)
        return 1
    print(f"results_page: {PAGE} and {len(files)} files of generated regions agree with their JSON"
          + (" and the `specular` CLI" if a.specular else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
