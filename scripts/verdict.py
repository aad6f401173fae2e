# SPDX-License-Identifier: Apache-2.0
"""The hardware verdict of `make report` (docs/phong_hw.md#verdict): per error budget
(docs/metrics.md#budgets) and mean span length, which unit delivers the most pixels per clock
for its FPGA area, the device or the per-pixel Blinn-Phong core in either form, in one currency.

The currency, stated once: a core's area is the share of an LFE5U-85F it occupies on its binding
resource, max(LUT4 positions / 83,640, flip-flops / 83,640, MULT18X18D / 156, DP16KD / 208),
from the ECP5 runs of docs/fpga_figures.json (scripts/fpga.py --device ecp5, MULT18X18D tiles on
both sides; Yosys' counts, LUT4 positions = LUT4 + 2 CCU2C). A share above 1 does not fit the
part. A design's figure of merit is pixels per clock per part, (pixels per clock) / share, and
at its own clock, pixels per second per part; the verdict compares designs by it, as ratios.
The raw counts stay beside it in the report.

Pixels per clock: every Phong core and the device's stream core take one pixel per clock on any
span (tested: rtl_phong, make sim); the device with its setup in hardware (specular_system) takes
at most one span every SetupII clocks, so on spans of m pixels it gives min(1, m / SetupII)
pixels per clock (docs/setup_hw.md#the-folded-setup), its best SetupII chosen per m.

  candidates(...)   the designs per budget: the Phong configurations whose measured errors meet
                    it, the device's stream configurations that meet it, the system per SetupII
  verdict(...)      per budget and span length the figures of every design and the winner
  write(...)        the report's section; plot(...) one figure per budget: error against area
"""
import json
import os

import fpga_parts  # scripts/fpga_parts.py, beside this file

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUDGETS = {  # name: (relative epicenter bound, absolute lobe bound, raw absolute bound); LSB allowance in the first two
    "b1": (1e-3, 1e-2, None),
    "b2": (None, None, 1.0 / 512.0),
    "b3": (1e-2, 1e-2, None),
    "b4": (None, None, 1.0 / 2048.0),
}
SPAN_LENGTHS = (1, 2, 4, 8, 16, 64)
PART = fpga_parts.LFE5U[-1]  # LFE5U-85F: (name, size flag, LUT4 positions = FFs, MULT18X18D, DP16KD)


def share(e):
    """The share of the LFE5U-85F an ECP5 entry occupies on its binding resource, and that resource."""
    parts = {"LUT4 positions": (e["lut4"] + 2 * e["ccu2c"]) / PART[2], "FF": e["ffs"] / PART[2],
             "MULT18X18D": e["mult18x18d"] / PART[3], "DP16KD": e["dp16kd"] / PART[4]}
    res = max(parts, key=parts.get)
    return parts[res], res


def budget_error(err, budget):
    """The worst error of a configuration as a fraction of the budget's bound (<= 1: meets it), from
    its worst rel_lsb, abs_lsb and abs_raw over n (None where a figure the budget needs is missing)."""
    rel, ab, raw = BUDGETS[budget]
    vals = []
    for bound, key in ((rel, "rel_lsb"), (ab, "abs_lsb"), (raw, "abs_raw")):
        if bound is None:
            continue
        if err.get(key) is None:
            return None
        vals.append(err[key] / bound)
    return max(vals)


def pixels_per_clock(setup_ii, mean_span):
    """A design's pixels per clock on spans of mean_span pixels: 1 for a core fed at one span per
    clock or faster (setup_ii None: the setup on a host, or a per-pixel core), else the setup's
    span rate."""
    return 1.0 if setup_ii is None else min(1.0, mean_span / setup_ii)


def candidates(points, budget):
    """The points that meet the budget: each point {name, kind (device | phong), ecp5 entry,
    err {rel_lsb, abs_lsb, abs_raw} or None when its budget membership is given instead
    (meets: [budgets]), setup_ii (None or k)}."""
    out = []
    for p in points:
        if p.get("meets") is not None:
            ok = budget in p["meets"]
        else:
            be = budget_error(p["err"], budget) if p.get("err") else None
            ok = be is not None and be <= 1.0
        if ok and p.get("ecp5"):
            out.append(p)
    return out


def verdict(points, spans):
    """spans: [(label, mean pixels per span, {SetupII: measured pixels per clock of the system} or
    None)]; a measured figure replaces min(1, m / SetupII) for that SetupII. Returns {budget: [row]},
    row = {span, mean, designs: [{name, kind, setup_ii, px_per_clock, share, per_part,
    mpx_s_per_part or None}], host / hw / phong: the best design of the device with its setup on a
    host, of the device with its setup in hardware and of the Phong cores (None when none meets the
    budget), host_ratio / hw_ratio: its pixels per clock per part over the best Phong core's (None
    when a side has no design), and the same at each design's clock (*_at_clock) where both have one}."""
    res = {}
    for b in BUDGETS:
        cand = candidates(points, b)
        rows = []
        for label, m, measured in spans:
            designs = []
            for p in cand:
                ppc = pixels_per_clock(p.get("setup_ii"), m)
                if p.get("setup_ii") is not None and measured and measured.get(p["setup_ii"]) is not None:
                    ppc = measured[p["setup_ii"]]
                sh, _ = share(p["ecp5"])
                per_part = ppc / sh
                fmax = p["ecp5"].get("fmax_mhz")
                designs.append({"name": p["name"], "kind": p["kind"], "setup_ii": p.get("setup_ii"),
                                "px_per_clock": ppc, "share": sh,
                                "per_part": per_part, "mpx_s_per_part": per_part * fmax if fmax else None})
            # The device with its setup on a host (the stream core) and in hardware (the system).
            groups = {"host": [d for d in designs if d["kind"] == "device" and d["setup_ii"] is None],
                      "hw": [d for d in designs if d["kind"] == "device" and d["setup_ii"] is not None],
                      "phong": [d for d in designs if d["kind"] == "phong"]}
            row = {"span": label, "mean": m, "designs": designs}
            for g, ds in groups.items():
                row[g] = max(ds, key=lambda d: (d["per_part"], d["name"])) if ds else None
                timed = [d for d in ds if d["mpx_s_per_part"]]
                row[g + "_at_clock"] = max(timed, key=lambda d: d["mpx_s_per_part"]) if timed else None
            p = row["phong"]
            for g in ("host", "hw"):
                d = row[g]
                row[g + "_ratio"] = d["per_part"] / p["per_part"] if d and p else None
                dc, pc = row[g + "_at_clock"], row["phong_at_clock"]
                row[g + "_ratio_at_clock"] = dc["mpx_s_per_part"] / pc["mpx_s_per_part"] if dc and pc else None
            rows.append(row)
        res[b] = rows
    return res


def break_even(points, budget, phong=None):
    """The mean span length from which the device with its setup in hardware gives as many pixels
    per clock per part as the best Phong core meeting `budget`, or as the Phong point `phong`
    (docs/phong_hw.md#verdict). With
    SetupII = k and share s_k it gives min(1, m / k) pixels per clock from s_k, a Phong core 1 from
    s_P: it ties at m = k s_k / s_P, and only where s_k <= s_P (from m >= k its figure is 1 / s_k).
    Returns {"span": m or None, "design": name, "phong": name, "ratio_at_long_spans": s_P / s_k of
    the design with the best long-span figure}, None when a side has no design."""
    cand = candidates(points, budget)
    hw = [p for p in cand if p["kind"] == "device" and p.get("setup_ii") is not None]
    ph = [p for p in cand if p["kind"] == "phong"]
    if not hw or not ph:
        return None
    best_p = phong if phong is not None else min(ph, key=lambda p: (share(p["ecp5"])[0], p["name"]))
    s_p = share(best_p["ecp5"])[0]
    ties = [(p["setup_ii"] * share(p["ecp5"])[0] / s_p, p["name"]) for p in hw if share(p["ecp5"])[0] <= s_p]
    long_best = min(hw, key=lambda p: (share(p["ecp5"])[0], p["name"]))
    out = {"phong": best_p["name"], "ratio_at_long_spans": s_p / share(long_best["ecp5"])[0],
           "long_span_design": long_best["name"]}
    if ties:
        m, name = min(ties)
        out.update(span=m, design=name)
    else:
        out.update(span=None, design=None)
    return out


def break_even_each(points, budget):
    """break_even against every Phong core meeting `budget`, smallest share first ([] when a side
    has no design)."""
    cand = candidates(points, budget)
    ph = sorted((p for p in cand if p["kind"] == "phong"), key=lambda p: (share(p["ecp5"])[0], p["name"]))
    out = [break_even(points, budget, p) for p in ph]
    return [be for be in out if be is not None]


# The ECP5 synthesis of the current flow (scripts/fpga.py: rtl/fpga/README.md#merged-cells, the
# DSP tiles' own registers of rtl/prim/specular_mul_tile.sv): a comparison takes every core's
# entry of it where one is recorded. An entry is of the current flow when its synthesis string
# holds every marker.
CURRENT_FLOW = ("-DSPECULAR_ECP5_MULT18X18D", "synth_ecp5 -nowidelut")


def current_flow(e):
    return all(m in e.get("synthesis", "") for m in CURRENT_FLOW)


def ecp5_entry(figs, core, config=None, setup_ii=None):
    """The docs/fpga_figures.json ECP5 entry of a core with MULT18X18D tiles: a placed and routed run
    (ecp5_runs) first, else the synthesis counts (synthesis_runs, part ECP5); of either, one of the
    current flow first, then the latest."""
    def best(entries):
        return max(entries, key=lambda e: (current_flow(e), e.get("date", ""))) if entries else None
    placed = best([e for e in figs.get("ecp5_runs", [])
                   if e.get("core") == core and e.get("config") == config and e.get("setup_ii") == setup_ii
                   and e.get("multipliers", "").startswith("MULT18X18D")])
    synth = best([e for e in figs.get("synthesis_runs", [])
                  if e.get("core") == core and e.get("part") == "ECP5" and e.get("config") == config
                  and (e.get("setup_ii") or 1) == (setup_ii or 1)])
    if placed and (current_flow(placed) or not synth or not current_flow(synth)):
        return dict(placed, placed=True)
    if synth:
        return dict(synth, placed=False, fmax_mhz=None)
    return None


def device_errors(data, search):
    """Config label -> the worst {rel_lsb, abs_lsb, abs_raw} of a device stream configuration for
    n <= 1000, for the plots: the default build (None) from this run's report_data (no raw error
    there), a labelled budget configuration from the device search that found it
    (docs/measured/device_search.json: the run of its bank set at its widths)."""
    out = {}
    for name, label in BUILDS:
        h = next((h for h in data.get("hardware", []) if h.get("name") == name), None)
        if h:
            out[label] = {"rel_lsb": max(h["max_rel_epicenter_lsb"]), "abs_lsb": max(h["max_abs_lobe"]), "abs_raw": None}
    for r in (search or {}).get("runs", []):
        best = r.get("best")
        if not best or r.get("n_max") != 1000:
            continue
        same = [x for x in r.get("runs", []) if x.get("meets") and all(x.get(k) == v for k, v in best.items())]
        if same:
            out[f"device_{r['budget']}_n1000"] = {k: same[0][k] for k in ("rel_lsb", "abs_lsb", "abs_raw")}
    return out


def load_points(figs, phong_errors, device_meets, phong_configs, device_errs=None):
    """The verdict's points from the record (figs), this run's Phong errors (config -> worst
    {rel_lsb, abs_lsb, abs_raw} over n <= 1000) and the device's budgets (config label ->
    [budgets met]; None: the default build) and errors for the plots (device_errors)."""
    pts = []
    device_errs = device_errs or {}
    for label, meets in device_meets.items():
        e = ecp5_entry(figs, "specular_stream", label)
        name = "device stream" + (f" {label}" if label else "") + " (setup on a host)"
        pts.append({"name": name, "kind": "device", "ecp5": e, "meets": meets, "setup_ii": None,
                    "err": device_errs.get(label)})
    # The system at every SetupII recorded: the default configuration, and a budget configuration's
    # stream inside it (fpga.py --top system --label device_bK_n1000) at the budgets that stream meets.
    systems = sorted({(e.get("config") or "", e.get("setup_ii") or 1)
                      for e in figs.get("ecp5_runs", []) + figs.get("synthesis_runs", [])
                      if e.get("core") == "specular_system" and (e.get("part") == "ECP5" or "multipliers" in e)
                      and (not e.get("config") or e["config"] in device_meets)})
    for cfg, k in systems:
        label = cfg or None
        e = ecp5_entry(figs, "specular_system", label, None if k == 1 else k)
        if e:
            name = "device system" + (f" {label}" if label else "") + f", SetupII={k} (setup in hardware)"
            pts.append({"name": name, "kind": "device", "ecp5": e, "meets": device_meets.get(label, []),
                        "setup_ii": k, "err": device_errs.get(label)})
    for c in phong_configs:
        if c.endswith("_consth"):
            continue  # constant H serves only a directional light and a distant viewer
        pts.append({"name": f"phong {c}", "kind": "phong", "ecp5": ecp5_entry(figs, "phong_stream", c),
                    "err": phong_errors.get(c), "setup_ii": None})
    return pts


def worst_errors(phong_json, n_max=1000):
    """phong_search --measure JSON -> the worst rel_lsb, abs_lsb, abs_raw over n <= n_max."""
    out = {}
    for key in ("rel_lsb", "abs_lsb", "abs_raw"):
        vals = [v for n, v in zip(phong_json.get("n", []), phong_json.get(key, [])) if n <= n_max]
        out[key] = max(vals) if vals else None
    return out


# The budgets a configuration built for one meets: B1's bounds are B3's or tighter, B4's B2's.
IMPLIED = {"b1": ["b1", "b3"], "b2": ["b2"], "b3": ["b3"], "b4": ["b2", "b4"]}
# The build configurations of model/device/rom_image.cpp with entries of their own in the record
# (report_data name, record label) and the budget each was built for: the default build (no
# label), the blend that meets B2 (its dense sweep, docs/display_exact.md#search), and the
# single-bank build (label "single"), which meets B1 (docs/device.md).
BUILDS = (("default", None), ("single", "single"))
BUILT_FOR = {None: "b2", "single": "b1"}


def labelled_device_budgets(figs):
    """The device's budget configurations in the record (scripts/fpga.py --label device_bK_n1000,
    roms/budget/budget_configs.json): label -> the budgets met (the search that found it held it to
    bK for n <= 1000)."""
    return {e["config"]: IMPLIED[e["config"].split("_")[1]] for e in figs.get("ecp5_runs", [])
            if e.get("core") == "specular_stream" and (e.get("config") or "").startswith("device_b")
            and e["config"].endswith("_n1000")}


def device_budgets(data, figs):
    """Config label -> the budgets a device stream configuration meets: the builds of BUILDS by
    this run's measured errors (report_data's hardware section, n <= 1000) at B1 and B3 (B2 and B4
    bound the raw error, which report_data does not give: the default build meets B2 by its dense
    sweep, a ctest), the labelled ones by labelled_device_budgets."""
    out = {}
    for name, label in BUILDS:
        h = next((h for h in data.get("hardware", []) if h.get("name") == name), None)
        if h:
            err = {"rel_lsb": max(h["max_rel_epicenter_lsb"]), "abs_lsb": max(h["max_abs_lobe"])}
            met = [b for b in ("b1", "b3") if budget_error(err, b) <= 1.0]
            out[label] = sorted(set(met) | ({"b2"} if BUILT_FOR[label] == "b2" else set()))
    out.update(labelled_device_budgets(figs))
    return out


def report_spans(sim, ii_sim):
    """The rows: SPAN_LENGTHS, then every scene of this run's Phong stage (mean pixels per span =
    pixels / spans) with the system's measured pixels per clock per SetupII where
    docs/measured/sim_setup_ii.json has the scene."""
    rows = [(str(m), m, None) for m in SPAN_LENGTHS]
    for name, v in sorted((sim or {}).get("phong", {}).items()):
        if v.get("spans"):
            measured = {k: float(x[name]["px_per_clock_steady"]) for k, x in (ii_sim or {}).items()
                        if x.get(name, {}).get("px_per_clock_steady")}
            rows.append((f"{name} ({v['pixels'] / v['spans']:.2f})", v["pixels"] / v["spans"], measured or None))
    return rows


def fmt_ratio(r):
    return "n/a" if r is None else f"{r:.2f}"


def write(w, res, points):
    """The report's section 4c."""
    w("## 4c. The verdict: which unit to build, per budget and span length\n")
    w("Currency (one number, its conversion stated): the share of an LFE5U-85F that a core occupies on its binding "
      "resource, max(LUT4 positions / 83,640, FF / 83,640, MULT18X18D / 156, DP16KD / 208), ECP5 counts of "
      "docs/fpga_figures.json with MULT18X18D tiles on both sides (placed and routed where the run placed, "
      "synthesis counts and no clock otherwise). Figure of merit: pixels per clock per "
      "part = pixels per clock / share; the device with its setup in hardware takes at most one span every SetupII "
      "clocks, so min(1, mean span / SetupII) pixels per clock (best SetupII per row). Ratio = device / best Phong "
      "core: above 1 the device gives more pixels per clock from the same part.\n")
    w("| design | LUT4 | CCU2C | FF | MULT18X18D | DP16KD | Fmax MHz | binding resource | share of LFE5U-85F | "
      "budgets met |")
    w("|---|---|---|---|---|---|---|---|---|---|")
    for p in points:
        e = p.get("ecp5")
        if not e:
            w(f"| {p['name']} | not run | | | | | | | | |")
            continue
        sh, r = share(e)
        met = [b for b in BUDGETS if p in candidates([p], b)]
        fm = f"{e['fmax_mhz']:.2f}" if e.get("fmax_mhz") else "synthesis only"
        w(f"| {p['name']} | {e['lut4']} | {e['ccu2c']} | {e['ffs']} | {e['mult18x18d']} | {e['dp16kd']} | {fm} | "
          f"{r} | {sh:.3f} | {', '.join(met) if met else 'none'} |")
    w("")
    for b, rows in res.items():
        w(f"**{b.upper()}** ({budget_text(b)}):\n")
        w("| mean span (pixels) | device, setup on a host | device, setup in hardware | best Phong core | "
          "host-setup device / Phong | hardware-setup device / Phong | at each core's clock: host-setup device / Phong "
          "| at each core's clock: hardware-setup device / Phong (placed designs) |")
        w("|---|---|---|---|---|---|---|---|")

        def cell(d):
            return f"{d['name']}: {d['per_part']:.2f}" if d else "none meets it"
        for r in rows:
            w(f"| {r['span']} | {cell(r['host'])} | {cell(r['hw'])} | {cell(r['phong'])} | "
              f"{fmt_ratio(r['host_ratio'])} | {fmt_ratio(r['hw_ratio'])} | {fmt_ratio(r['host_ratio_at_clock'])} | "
              f"{fmt_ratio(r['hw_ratio_at_clock'])} |")
        w("")
        be = break_even(points, b)
        if be is None:
            w("Break-even span length: no design on one side.\n")
        elif be["span"] is None:
            w(f"Break-even span length: none. Even on spans long enough for one pixel per clock the best device with "
              f"its setup in hardware ({be['long_span_design']}) gives {be['ratio_at_long_spans']:.2f} times the "
              f"pixels per clock per part of {be['phong']}.\n")
        else:
            w(f"Break-even span length: {be['span']:.1f} pixels ({be['design']} against {be['phong']}).\n")
        each = break_even_each(points, b)
        if len(each) > 1:
            w("Against each Phong core that meets it: " + "; ".join(
                f"{e['phong']}: {e['span']:.1f} pixels ({e['design']})" if e["span"] is not None else
                f"{e['phong']}: none ({e['ratio_at_long_spans']:.2f} times on long spans)" for e in each) + ".\n")


def budget_text(b):
    rel, ab, raw = BUDGETS[b]
    if raw is not None:
        return f"every pixel within {raw:.3g} of full scale"
    return f"{rel:.2%} of the pixel + 1 LSB in the epicenter, {ab:g} C + 1 LSB over the lobe"


KINDS = {  # marker, colour and key text of each kind of design in the plots
    "host": ("o", "tab:blue", "device, setup on a host"),
    "hw": ("^", "tab:green", "device, setup in hardware"),
    "phong": ("s", "tab:red", "per-pixel Phong"),
}


def kind_of(p):
    return "phong" if p["kind"] == "phong" else "hw" if p.get("setup_ii") is not None else "host"


def label_offsets(xy, box=(16, 11)):
    """Offsets in points, one per point (display coordinates xy), for the points' number labels: the
    first of a few positions around the point whose box overlaps no label placed before, so that
    points at one place (the systems per SetupII share an error) keep readable numbers."""
    tries = [(5, 4), (5, -13), (-20, 4), (-20, -13), (5, 15), (-20, 15), (5, -24), (-20, -24), (26, 4), (-41, 4)]
    placed, out = [], []
    for x, y in xy:
        for dx, dy in tries:
            bx, by = x + dx, y + dy
            if all(abs(bx - px) >= box[0] or abs(by - py) >= box[1] for px, py in placed):
                break
        placed.append((bx, by))
        out.append((dx, dy))
    return out


def plot(points, out_dir, plt):
    """One figure per budget: every point's worst error as a fraction of the budget's bound against
    its share of an LFE5U-85F (a point without the figure the budget needs is left out: the default
    device build at B2, whose raw error report_data does not give). The points are numbered, the
    numbers placed apart (label_offsets), and a key beside the plot names each number."""
    written = []
    for b in BUDGETS:
        pts = []
        for p in points:
            err = budget_error(p["err"], b) if p.get("err") else None
            if p.get("ecp5") and err is not None:
                pts.append((p, share(p["ecp5"])[0], max(err, 1e-3)))
        if not pts:
            continue
        fig, ax = plt.subplots(figsize=(12, 6))
        for k, (marker, colour, text) in KINDS.items():
            sel = [(x, y) for p, x, y in pts if kind_of(p) == k]
            if sel:
                ax.scatter([x for x, _ in sel], [y for _, y in sel], marker=marker, color=colour, label=text, zorder=3)
        ax.axhline(1.0, color="gray", linestyle="--", linewidth=1)
        ax.set_xscale("log")
        ax.set_yscale("log")
        xs, ys = [x for _, x, _ in pts], [y for _, _, y in pts]
        ax.set_xlim(min(xs) / 1.6, max(xs) * 1.6)
        ax.set_ylim(min(ys + [1.0]) / 2, max(ys + [1.0]) * 2)
        ax.set_xlabel("share of an LFE5U-85F on the binding resource (ECP5, MULT18X18D tiles)")
        ax.set_ylabel(f"worst error / {b.upper()} bound, n = 1..1000")
        ax.set_title(f"{b.upper()}: {budget_text(b)}", fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(loc="upper left", fontsize=8)
        fig.subplots_adjust(left=0.07, right=0.62, bottom=0.1, top=0.93)
        xy = ax.transData.transform([(x, y) for _, x, y in pts]) * 72.0 / fig.dpi
        for i, ((p, x, y), off) in enumerate(zip(pts, label_offsets(xy)), start=1):
            ax.annotate(str(i), (x, y), textcoords="offset points", xytext=off, fontsize=8,
                        color=KINDS[kind_of(p)][1])
        key = "\n".join(f"{i:>2}  {p['name']}" for i, (p, _, _) in enumerate(pts, start=1))
        fig.text(0.64, 0.93, key, fontsize=7.5, va="top", family="monospace")
        path = os.path.join(out_dir, f"verdict_{b}.png")
        fig.savefig(path, dpi=110)
        plt.close(fig)
        written.append(path)
    return written


def record_points(figs, configs):
    """The points of the record alone, each configuration at the budget it was built for (no error
    measured): the device's builds (BUILT_FOR) and labelled runs, and the Phong configurations
    for n <= 1000 of configs (name -> budget, hw_plane.phong_configs())."""
    phong = {c: IMPLIED[b] for c, b in configs.items() if c.endswith("n1000")}
    dev = labelled_device_budgets(figs)
    for label, b in BUILT_FOR.items():
        dev[label] = IMPLIED[b]
    pts = load_points(figs, {}, dev, list(phong))
    for p in pts:
        if p["kind"] == "phong":
            p["meets"] = phong[p["name"].split()[1]]
    return pts


def main():
    import argparse
    import hw_plane  # scripts/hw_plane.py: the Phong configurations and their budgets
    ap = argparse.ArgumentParser(description="The verdict of the record alone (every configuration at the budget "
                                             "it was built for); make report measures the errors instead.")
    ap.add_argument("--figures", default=os.path.join(ROOT, "docs", "fpga_figures.json"))
    ap.add_argument("--json", help="write the verdict as JSON to FILE")
    a = ap.parse_args()
    with open(a.figures) as f:
        figs = json.load(f)
    pts = record_points(figs, hw_plane.phong_configs())
    res = verdict(pts, [(str(m), m, None) for m in SPAN_LENGTHS])
    if a.json:
        with open(a.json, "w") as f:
            json.dump(res, f, indent=1)
    write(print, res, pts)


if __name__ == "__main__":
    main()
