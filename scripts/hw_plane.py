# SPDX-License-Identifier: Apache-2.0
"""The hardware speed-against-error plane of `make report` (docs/speed_error.md#hardware-configurations):
the device's build configurations and the per-pixel Blinn-Phong core `phong_stream`'s
(docs/phong_hw.md) as points of error against cost.

  measure_phong(...)  BUILD/bin/phong_search --measure CONFIG --n-step S --json OUT/phong_CONFIG.json
                      (the error of each Phong configuration, golden model, measured in this run)
  phong_figures(...)  the Phong configurations' cells from docs/fpga_figures.json (scripts/fpga.py:
                      HX8K Yosys counts, ECP5 place and route)
  points(...)         one row per point: cost (cells) and error per n range
  plot(...), write(...)  the figure OUT/hw_plane.png and the report section

Used by scripts/make_report.py; tests/report/check_make_report.py recomputes the table from
OUT/report_data.json, OUT/phong_*.json and OUT/hw_plane_cells.json.
"""
import json
import os
import re
import subprocess
import time

import fpga_parts  # scripts/fpga_parts.py, beside this file

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

def phong_configs(path=os.path.join(ROOT, "roms", "phong", "phong_configs.cmake")):
    """The Phong configurations of docs/phong_hw.md and the budget each is built for, from the
    fragment phong_romgen writes (model/device/phong_model.hpp's phong_configs()): name -> budget."""
    with open(path) as f:
        text = f.read()
    names = re.search(r"set\(PHONG_CONFIGS ([^)]*)\)", text).group(1).split()
    return {n: re.search(rf"set\(PHONG_CONFIG_{n}_BUDGET (\w+)\)", text).group(1) for n in names}


# Every Phong configuration is a point of the plane (names of roms/phong/phong_configs.cmake).
PHONG_CONFIGS = tuple(phong_configs())
# The n ranges of the plane: 1..64, 1..128, 1..1000 (the ranges the Phong presets serve).
RANGES = (64, 128, 1000)
REL_BUDGET, ABS_BUDGET = 1e-3, 1e-2  # 0.10 % + 1 LSB in the epicenter, 0.01 C over the lobe
ICE40_MAX_LC = fpga_parts.ICE40_MAX_LC


def worst(ns, vals, hi):
    sel = [float(v) for n, v in zip(ns, vals) if 1 <= n <= hi]
    return max(sel) if sel else None


def run_logged(cmd, log, timeout):
    with open(log, "w") as lf:
        lf.write("$ " + " ".join(cmd) + "\n")
        lf.flush()
        return subprocess.run(cmd, cwd=ROOT, stdout=lf, stderr=subprocess.STDOUT, timeout=timeout).returncode


def measure_phong(exe, out, logs, n_step, missing, timings):
    """name -> phong_search --measure JSON (n, rel_lsb, abs_lsb) for every PHONG_CONFIGS."""
    res = {}
    if not exe:
        missing.append("phong_search was not built: no Phong errors in the hardware plane")
        return res
    t0 = time.time()
    for name in PHONG_CONFIGS:
        path = os.path.join(out, f"phong_{name}.json")
        if os.path.exists(path):
            os.remove(path)
        rc = run_logged([exe, "--measure", name, "--n-step", str(n_step), "--json", path],
                        os.path.join(logs, f"phong_{name}.log"), timeout=3600)
        if rc != 0 or not os.path.exists(path):
            missing.append(f"phong_search --measure {name} failed (exit {rc}), see logs/phong_{name}.log")
            continue
        with open(path) as f:
            res[name] = json.load(f)
    timings["phong_search --measure (all Phong configurations)"] = time.time() - t0
    return res


def load_figures(path):
    """docs/fpga_figures.json (or the file at path) as a dict; {} when it is missing or unreadable."""
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return {}


def phong_figures(path=os.path.join(ROOT, "docs", "fpga_figures.json")):
    """The committed scripts/fpga.py figures of phong_stream per configuration (make fpga
    --top phong --phong-config CFG; synthesis and place and route of the Phong core take longer
    than a report run, so the report reads them): (cfg, "ice40") -> the HX8K run's Yosys counts
    (LUT trees; the core needs more logic cells than any iCE40 has, so there is no placement),
    (cfg, "ecp5") -> the placed and routed ECP5 run (MULT18X18D tiles) with its Fmax and part.
    Each with the RTL commit of its run."""
    d = load_figures(path)
    res = {}
    for e in d.get("synthesis_runs", []) + d.get("runs", []):
        if e.get("core") == "phong_stream" and e.get("part", "").startswith("HX8K"):
            res[(e["config"], "ice40")] = {"counts": {"SB_LUT4": e["sb_lut4"], "SB_DFF*": e["ffs"],
                                                      "SB_RAM40_4K": e["brams"]}, "rtl": e["rtl"]}
    for e in d.get("ecp5_runs", []):
        if e.get("core") == "phong_stream":
            res[(e["config"], "ecp5")] = {"counts": {"LUT4": e["lut4"], "MULT18X18D": e["mult18x18d"],
                                                     "DP16KD": e["dp16kd"], "TRELLIS_FF": e["ffs"],
                                                     "fmax_mhz": e["fmax_mhz"], "part": e["part"]},
                                          "rtl": e["rtl"]}
    return res


def points(data, phong, cells, phong_cells):
    """The plane's rows: the device's build configurations (specular_unit, and specular_stream of
    the default configuration), then the Phong configurations. Each row: name, core, cost
    (lut4, ff, bram, lc_min = max(LUT4, FF): every flip-flop and every LUT4 takes a logic cell),
    ecp5 counts, and the worst relative (+1 LSB) and absolute error over n = 1..R per RANGES."""
    rows = []
    hw = {h["name"]: h for h in data.get("hardware", [])}
    for key, h in [(h["name"], h) for h in data.get("hardware", [])] + \
            ([("default-stream", hw["default"])] if "default" in hw else []):
        c = cells.get(key, {})
        rows.append({"name": f"device {key}", "kind": "device",
                     "core": "specular_stream" if key.endswith("-stream") else "specular_unit",
                     "lut4": c.get("lut4"), "ff": c.get("ff"), "bram": c.get("bram"),
                     "fit": c.get("fit", True), "fit_reason": c.get("fit_reason", ""),
                     "rel": {r: worst(h["n"], h["max_rel_epicenter_lsb"], r) for r in RANGES},
                     "abs": {r: worst(h["n"], h["max_abs_lobe"], r) for r in RANGES}})
    for name in PHONG_CONFIGS:
        p = phong.get(name)
        if p is None:
            continue
        ci = phong_cells.get((name, "ice40"), {}).get("counts", {})
        ce = phong_cells.get((name, "ecp5"), {}).get("counts")
        rows.append({"name": f"phong {name}", "kind": "phong", "core": "phong_stream",
                     "lut4": ci.get("SB_LUT4"), "ff": ci.get("SB_DFF*"), "bram": ci.get("SB_RAM40_4K"),
                     "fit": False, "fit_reason": "",
                     "ecp5": ce,
                     "rel": {r: worst(p["n"], p["rel_lsb"], r) for r in RANGES},
                     "abs": {r: worst(p["n"], p["abs_lsb"], r) for r in RANGES}})
    for r in rows:
        r["cost"] = r["lut4"] + r["ff"] if r["lut4"] is not None and r["ff"] is not None else None
        r["lc_min"] = max(r["lut4"], r["ff"]) if r["cost"] is not None else None
    return rows


def meets(row, rng):
    return (row["rel"][rng] is not None and row["rel"][rng] <= REL_BUDGET
            and row["abs"][rng] is not None and row["abs"][rng] <= ABS_BUDGET)


def conclusion(rows):
    """Per range: the cheapest device core and the cheapest Phong core (by LUT4) that meet the
    budget over n = 1..R, and the ratios Phong / device of LUT4 and of LUT4 + FF.
    None for a range where either side has no measured cells or no configuration within budget."""
    out = {}
    for rng in RANGES:
        best = {}
        for kind in ("device", "phong"):
            cand = [r for r in rows if r["kind"] == kind and r["lut4"] is not None and meets(r, rng)]
            best[kind] = min(cand, key=lambda r: (r["lut4"], r["name"])) if cand else None
        if best["device"] and best["phong"]:
            d, p = best["device"], best["phong"]
            out[rng] = {"device": d["name"], "phong": p["name"], "lut4_ratio": p["lut4"] / d["lut4"],
                        "cost_ratio": p["cost"] / d["cost"]}
        else:
            out[rng] = None
    return out


def fmt(v):
    return "n/a" if v is None else f"{v:.3g}"


def ecp5_runs(path=os.path.join(ROOT, "docs", "fpga_figures.json")):
    """The ECP5 entries of docs/fpga_figures.json (scripts/fpga.py --device ecp5, the same harness for
    every core): name -> entry, for the default specular_system at each SetupII ("specular_system" is
    SetupII 1, "specular_system SetupII=K" the others) and each phong_stream configuration
    ("phong CONFIG"); a placed and routed run replaces the synthesis counts of the same core."""
    d = load_figures(path)
    out = {}

    def add(e):
        if e.get("core") == "specular_system" and not e.get("config"):  # a --label run is not the system's default
            ii = e.get("setup_ii", 1)
            out["specular_system" + (f" SetupII={ii}" if ii != 1 else "")] = e
        elif e.get("core") == "phong_stream":
            out[f"phong {e.get('config')}"] = e
    for e in d.get("synthesis_runs", []):
        if e.get("part") == "ECP5":
            add(e)
    for e in d.get("ecp5_runs", []):
        add(e)
    return out


def setup_ii_of(name):
    """SetupII of an ecp5_runs() key of specular_system."""
    return int(name.split("=")[1]) if "=" in name else 1


def setup_ii_sim(path=os.path.join(ROOT, "docs", "measured", "sim_setup_ii.json")):
    """sim_regression --setup-ii's system stage (make sim-setup-ii, committed as
    docs/measured/sim_setup_ii.json): SetupII -> run -> figures; {} when absent."""
    try:
        with open(path) as f:
            d = json.load(f).get("system_setup_ii", {})
    except (OSError, ValueError):
        return {}
    return {int(k): v for k, v in d.items()}


def write_system_cost(w, runs, ii_sim=None):
    """The device with its setup in hardware against the Phong cores: ECP5 synthesis counts per
    SetupII, and per scene the LUT4 per pixel per clock (the system stage's pixels per clock)."""
    systems = sorted(((setup_ii_of(k), v) for k, v in runs.items() if k.startswith("specular_system")),
                     key=lambda x: x[0])
    phong = sorted((k, v) for k, v in runs.items() if k.startswith("phong "))
    if not systems or not phong:
        w("The device with its setup in hardware (`specular_system`): no ECP5 counts in docs/fpga_figures.json.\n")
        return
    w("The device with its setup in hardware (`specular_system`; `SetupII` = 1 takes one span per clock, `SetupII` = k "
      "at most one every k clocks with the setup folded over them, docs/setup_hw.md#the-folded-setup) "
      "against the Phong cores, in the same harness and flow (`scripts/fpga.py --device ecp5`; the system's Yosys "
      "`synth_ecp5` counts where it fits no ECP5, placed and routed counts where a run has them; "
      "from docs/fpga_figures.json, not measured in this run):\n")
    w("| core | RTL | LUT4 | CCU2C | MULT18X18D | DP16KD | FF |")
    w("|---|---|---|---|---|---|---|")
    for k, v in systems:
        w(f"| specular_system SetupII={k} | {v['rtl']} | {v['lut4']} | {v['ccu2c']} | {v['mult18x18d']} | "
          f"{v['dp16kd']} | {v['ffs']} |")
    for k, v in phong:
        w(f"| {k} | {v['rtl']} | {v['lut4']} | {v['ccu2c']} | {v['mult18x18d']} | {v['dp16kd']} | {v['ffs']} |")
    w("")
    ii_sim = ii_sim or {}
    scenes = sorted({s for k, _ in systems for s in ii_sim.get(k, {}) if s not in ("l0", "random")})
    # The competitor that serves every n the device serves (1..1000).
    ref_name = "phong n1000" if "phong n1000" in runs else phong[-1][0]
    ref = runs[ref_name]
    if not scenes:
        worst = min(systems[0][1]["lut4"] / v["lut4"] for _, v in phong)
        w(f"No system stage per SetupII in docs/measured/sim_setup_ii.json (make sim-setup-ii): at `SetupII` = "
          f"{systems[0][0]} the system takes at least {worst:.1f} x the LUT4 of every Phong configuration.\n")
        return
    w("Cost per pixel per clock, per scene: the system's LUT4 divided by its pixels per clock in the system stage "
      "(`make sim-setup-ii`, spans back to back, `px_ready_i` high, steady state; docs/measured/sim_setup_ii.json, "
      f"not measured in this run), against {ref_name}'s LUT4 at one pixel per clock; below 1 the device system is "
      "cheaper per pixel:\n")
    hdr = "| scene | " + " | ".join(f"px/clock SetupII={k}" for k, _ in systems) + " | " + \
        " | ".join(f"LUT4 per px/clock SetupII={k} / {ref_name}" for k, _ in systems) + " |"
    w(hdr)
    w("|" + "---|" * (hdr.count("|") - 1))
    best = {}
    for s in scenes:
        ppc, rat = [], []
        for k, v in systems:
            x = ii_sim.get(k, {}).get(s, {})
            p = float(x["px_per_clock_steady"]) if x.get("px_per_clock_steady") else None
            ppc.append("n/a" if p is None else f"{p:.4f}")
            r = v["lut4"] / p / ref["lut4"] if p else None
            rat.append("n/a" if r is None else f"{r:.2f}")
            if r is not None and (s not in best or r < best[s][1]):
                best[s] = (k, r)
        w(f"| {s} | " + " | ".join(ppc) + " | " + " | ".join(rat) + " |")
    w("")
    lo = min(best.items(), key=lambda x: x[1][1])
    hi = max(best.items(), key=lambda x: x[1][1])
    wins = [s for s, (_, r) in best.items() if r < 1.0]
    w(f"With the setup in hardware, the best `SetupII` per scene costs {lo[1][1]:.2f} x ({lo[0]}, SetupII={lo[1][0]}) "
      f"to {hi[1][1]:.2f} x ({hi[0]}, SetupII={hi[1][0]}) the LUT4 per pixel per clock of {ref_name}: "
      + ("the device system is cheaper per pixel on " + ", ".join(wins) + " only. " if wins else
         "per-pixel Phong is cheaper per pixel on every scene. ")
      + f"In MULT18X18D the device system needs {min(v['mult18x18d'] for _, v in systems)} at its most shared "
      f"(SetupII={systems[-1][0]}) against {ref['mult18x18d']}."
      + (" The device wins on area only where its setup stays on the host (the ratios above).\n" if not wins else "\n"))


def plot(rows, path, plt):
    pts = [r for r in rows if r["cost"] is not None]
    if not pts:
        return False
    fig, axes = plt.subplots(1, len(RANGES), figsize=(16, 5.5), sharey=True)
    for ax, rng in zip(axes, RANGES):
        for i, r in enumerate(pts):
            y = r["rel"][rng]
            if y is None:
                continue
            y = max(y, 1e-6)  # an error of 0 on the log axis
            ax.scatter([r["cost"]], [y], marker="o" if r["kind"] == "device" else "s",
                       color="tab:blue" if r["kind"] == "device" else "tab:red")
            ax.annotate(r["name"], (r["cost"], y), textcoords="offset points", xytext=(4, 4 + 7 * (i % 3)),
                        fontsize=7)
        ax.axhline(REL_BUDGET, color="gray", linestyle="--", linewidth=1)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("cost: SB_LUT4 + flip-flops (Yosys synth_ice40)")
        ax.set_title(f"n = 1..{rng}")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("max relative epicenter error, (|err| - 1 LSB) / ref")
    fig.suptitle("Hardware plane: device (circles) and per-pixel Blinn-Phong (squares); dashed: the 0.10 % budget; "
                 "an error of 0 drawn at 1e-6")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return True


TABLE_HEADER = ("| point | core | SB_LUT4 | FF | SB_RAM40_4K | logic cells (at least) | fits an iCE40 | "
                "ECP5 LUT4 / MULT18X18D / DP16KD / FF | "
                + " | ".join(f"rel. n<={r}" for r in RANGES) + " | "
                + " | ".join(f"abs. n<={r}" for r in RANGES) + " |")


def fit_text(lc_min, fit, reason):
    """The plane's "fits an iCE40" cell: more logic cells than any iCE40 has, or the HX8K run's own
    verdict (scripts/fpga.py: block RAMs and DSPs are checked there too)."""
    if lc_min > ICE40_MAX_LC:
        return "no: does not fit any iCE40"
    return "yes" if fit else f"no: {reason}"


def table_row(r):
    if r["cost"] is None:
        cost = ["n/a"] * 5
    else:
        fits = fit_text(r["lc_min"], r["fit"], r["fit_reason"])
        cost = [str(r["lut4"]), str(r["ff"]), str(r["bram"]), str(r["lc_min"]), fits]
    e = r.get("ecp5")
    ecp5 = (f"{e['LUT4']} / {e['MULT18X18D']} / {e['DP16KD']} / {e['TRELLIS_FF']}, {e['fmax_mhz']:.2f} MHz "
            f"({e['part']})" if e else
            ("not run" if r["kind"] == "phong" else "-"))
    return ([r["name"], r["core"]] + cost + [ecp5] + [fmt(r["rel"][g]) for g in RANGES]
            + [fmt(r["abs"][g]) for g in RANGES])


def write(w, rows, phong, sim, n_step, synth_ran):
    w("## 4b. The hardware plane: the device against per-pixel Blinn-Phong in hardware\n")
    if not rows:
        w("Not measured in this run (see the list at the top).\n")
        return
    steps = sorted({p.get("n_step") for p in phong.values()})
    w("Every hardware configuration is a point: the device's build configurations of section 4 (`specular_unit`, and "
      "`specular_stream` of the default configuration, the core with the same pixel interface as the competitor) and "
      "the per-pixel Blinn-Phong core `phong_stream` (docs/phong_hw.md) in the configurations found by its search. "
      "Cost, in one flow (`scripts/fpga.py`, the out-of-context harness with registered IO, its cells included): the "
      "HX8K's Yosys `synth_ice40` cells (LUT-tree multipliers in both, the HX8K has no DSP): the device's configurations "
      "from this run, the Phong core's from docs/fpga_figures.json (`make fpga`, commit in its entries; not re-run here); "
      f"'logic cells (at least)' is max(SB_LUT4, FF), since every LUT4 and every flip-flop takes a logic cell of its own "
      f"(an iCE40 has at most {ICE40_MAX_LC}); the ECP5 column is the Phong core placed and routed with MULT18X18D "
      "tiles (LUT4 / MULT18X18D / DP16KD / FF, Fmax, part; docs/fpga_figures.json). Error: the worst over "
      "n = 1..R of the relative epicenter error with the 1-LSB allowance, (|err| - 1 LSB) / ref, and of the absolute "
      "lobe error / C: the device from section 4's sweep (its absolute error without the allowance), the Phong core "
      "from its golden model in this run (`phong_search --measure CONFIG --n-step S`, the sweep of "
      "docs/phong_hw.md#error-measurement, seed 1, n = 1, 1+S, ..., 1000 with "
      f"S = {', '.join(map(str, steps)) or n_step}; raw results `phong_*.json`). Budget: relative <= 1e-3, absolute "
      "<= 1e-2.\n")
    w(TABLE_HEADER)
    w("|" + "---|" * (TABLE_HEADER.count("|") - 1))
    for r in rows:
        w("| " + " | ".join(table_row(r)) + " |")
    w("")
    if any(r["cost"] is not None for r in rows):
        w("![hardware plane](hw_plane.png)\n")
    con = conclusion(rows)
    w("**Conclusion (from this run's numbers).** Both cores deliver one pixel per clock on every span length, so at an "
      "equal clock the cost per pixel is the area. Per n range, the cheapest configuration of each that meets the "
      "budget over n = 1..R, and the ratio Phong / device:\n")
    for rng in RANGES:
        c = con[rng]
        if c is None:
            why = "no cell counts in this run (synthesis not run)" if not synth_ran else \
                "no configuration of one of the two meets the budget there, or its cells are missing"
            w(f"- n <= {rng}: not computed: {why}.")
        else:
            w(f"- n <= {rng}: {c['device']} against {c['phong']}: the Phong core takes "
              f"**{c['lut4_ratio']:.1f} x** the device's LUT4 and {c['cost_ratio']:.1f} x its LUT4 + FF.")
    w("")
    write_system_cost(w, ecp5_runs(), setup_ii_sim())
    # Clocks per pixel per scene.
    ph, ds, sy = (sim or {}).get("phong", {}), (sim or {}).get("scenes_stream", {}), (sim or {}).get("system")
    if ph or ds:
        w("Clocks per pixel per scene (`sim_regression`, section 5; spans back to back, pixel side always ready; the "
          "Phong core n1000 with its per-span work in the core, the device's `specular_stream` fed with registers):\n")
        lut = {r["name"]: r["lut4"] for r in rows}
        dl, pl = lut.get("device default-stream"), lut.get("phong n1000")
        w("Pixels per clock per 1,000 LUT4: 1000 / (clocks per pixel x SB_LUT4), the cells of the table above "
          "(`specular_stream` default, `phong_stream` n1000); times the clock, pixels per second per 1,000 LUT4.\n")
        w("| scene | device stream clocks/pixel | phong_stream clocks/pixel | phong_stream spans | phong_stream pixels | "
          "device px/clock per 1,000 LUT4 | phong px/clock per 1,000 LUT4 |")
        w("|---|---|---|---|---|---|---|")
        for s in sorted(set(ph) | set(ds)):
            d, p = ds.get(s, {}), ph.get(s, {})
            dc = float(d["stream_clocks_per_pixel"]) if "stream_clocks_per_pixel" in d else None
            pc = p["cycles"] / p["pixels"] if p.get("pixels") else None
            dk = f"{1000 / (dc * dl):.3f}" if dc and dl else "n/a"
            pk = f"{1000 / (pc * pl):.3f}" if pc and pl else "n/a"
            w(f"| {s} | {'n/a' if dc is None else f'{dc:.4f}'} | {'n/a' if pc is None else f'{pc:.4f}'} | "
              f"{p.get('spans', 'n/a')} | {p.get('pixels', 'n/a')} | {dk} | {pk} |")
        w("")
        if sy:
            # sim_regression's system stage (specular_system, the setup in hardware): pixels per
            # clock with the pipeline's fill and in the steady state, per run.
            w("The device with its hardware setup (`specular_system`, the `system` section of sim.json): clocks per "
              "pixel = 1 / pixels per clock, with the pipeline's fill and in the steady state:\n")
            w("| run | spans | pixels | mismatches | clocks/pixel (fill) | clocks/pixel (steady) |")
            w("|---|---|---|---|---|---|")
            for s, x in sorted(sy.items()) if isinstance(sy, dict) else []:
                x = x if isinstance(x, dict) else {}
                inv = [f"{1 / float(x[k]):.4f}" if x.get(k) else "n/a"
                       for k in ("px_per_clock_fill", "px_per_clock_steady")]
                w(f"| {s} | {x.get('spans', 'n/a')} | {x.get('pixels', 'n/a')} | {x.get('mismatches', 'n/a')} | "
                  f"{inv[0]} | {inv[1]} |")
            w("")
        else:
            w("The device's setup runs on the host in this build (section 7): its `specular_stream` clocks above take "
              "register spans, while the Phong core's include its own per-span work.\n")
    else:
        w("Clocks per pixel per scene: not measured in this run (no regression with `--config all`).\n")
