#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Smoke test of scripts/make_report.py: run it in --smoke mode (report_data with a coarse n
grid, scene_bench on one small scene) and cross-check the tables of report.md against the
report_data.json and scene_bench.json it read. Every expected cell is recomputed here from
the JSON, not taken from make_report.py.

  check_make_report.py --build BUILD [--out DIR]   run make_report.py, then check
  check_make_report.py --check-only DIR            check an existing DIR/report.md
Exit 0 when every table agrees with the JSON, 1 otherwise (one line per mismatch).
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def val(v):
    return float(v)  # report_data writes non-finite numbers as "inf" / "nan" strings


def pct(v):
    if math.isinf(v):
        return "unbounded"
    return f"{100 * v:.3g} %"


def table_rows(md):
    """Markdown table rows as lists of stripped cells."""
    rows = []
    for line in md.splitlines():
        if line.startswith("|") and not line.startswith("|---"):
            rows.append([c.strip() for c in line.strip().strip("|").split("|")])
    return rows


def table_after(md, header_start):
    """Rows (lists of cells) of the markdown table whose header row starts with header_start;
    None when there is no such table."""
    lines = md.splitlines()
    for k, line in enumerate(lines):
        if line.startswith(header_start):
            rows = []
            for row in lines[k + 2:]:
                if not row.startswith("|"):
                    break
                rows.append([c.strip() for c in row.strip().strip("|").split("|")])
            return rows
    return None


def check_system(out, md):
    """Section 7 (System) against scene_bench.json: the three tables, the goals, the break-even
    sentence and plot, the headline."""
    errors = []
    path = os.path.join(out, "scene_bench.json")
    if not os.path.exists(path):
        return ["scene_bench.json missing: make_report.py did not run scene_bench"]
    with open(path) as f:
        sb = json.load(f)
    scenes = sb.get("scenes", [])
    if not scenes:
        return ["scene_bench.json has no scenes"]
    if "## 7. System: the speed per scene, setup included" not in md:
        errors.append("section 7 (System) heading missing")
    main = table_after(md, "| scene | spans | pixels | mean span (px) | H | device ns/px |")
    split = table_after(md, "| scene | setup ns/span | setup ns/px | shading ns/px |")
    isa = table_after(md, "| scene | AVX2: device ns/px |")
    feed = table_after(md, "| scene | mean span (px) | setup M spans/s (one host core) |")
    for name, t in (("per-scene", main), ("setup/shading", split), ("instruction-set", isa), ("feeding", feed)):
        if t is None:
            errors.append(f"System: the {name} table is missing")
        elif len(t) != len(scenes):
            errors.append(f"System: the {name} table has {len(t)} rows, scene_bench.json {len(scenes)} scenes")
    if errors:
        return errors
    for x, r, q, ir, fd in zip(scenes, main, split, isa, feed):
        t = x["ns_per_pixel"]
        for key in ("device", "phong_sleef", "phong_scalar", "pow_cos"):
            if not t[key] > 0:
                errors.append(f"System {x['scene']}: ns per pixel of {key} is {t[key]}")
        ps = t["phong_sleef"]
        want = [x["scene"], str(x["spans"]), str(x["pixels"]), f"{x['pixels'] / x['spans']:.2f}",
                ", ".join(sorted(set(x["lights"]))), f"{t['device']:.2f}", f"{ps:.2f}", f"{t['phong_scalar']:.2f}",
                f"{t['pow_cos']:.2f}", f"{ps / t['device']:.2f}", f"{ps / t['phong_scalar']:.2f}", f"{ps / t['pow_cos']:.2f}"]
        if r != want:
            errors.append(f"System per-scene row {r} != {want} (from scene_bench.json)")
        sp = x["device_setup_ns_per_span"] * x["spans"] / x["pixels"]
        sh = x["device_shade_ns_per_pixel"]
        want = [x["scene"], f"{x['device_setup_ns_per_span']:.2f}", f"{sp:.2f}", f"{sh:.2f}", f"{100 * sp / (sp + sh):.0f} %"]
        if q != want:
            errors.append(f"System setup/shading row {q} != {want}")
        want = [x["scene"]]
        for key in ("avx2", "avx512"):
            m = x.get("isa_matched", {}).get(key)
            want += ([f"{m['device']:.2f}", f"{m['phong_sleef']:.2f}", f"{m['phong_sleef'] / m['device']:.2f}"] if m
                     else ["n/a"] * 3)
        if ir != want:
            errors.append(f"System instruction-set row {ir} != {want}")
        setup_rate = 1e3 / x["device_setup_ns_per_span"]
        core_rate = sb["fmax_mhz"] * x["spans"] / x["pixels"]
        want = [x["scene"], f"{x['pixels'] / x['spans']:.2f}", f"{setup_rate:.1f}", f"{core_rate:.1f}",
                f"{core_rate / setup_rate:.2f}"]
        if fd != want:
            errors.append(f"System feeding row {fd} != {want}")
    # The Fmax comes from the one committed file.
    with open(os.path.join(ROOT, "docs", "fpga_figures.json")) as f:
        fig = json.load(f)
    # The default configuration's entry (no "config"; a --label run names its own, rtl/fpga/README.md#how-to-run).
    fmax = [r["fmax_mhz"] for r in fig["runs"] if r["core"] == "specular_stream" and r["part"].startswith("HX8K")
            and not r.get("config")]
    if fmax != [sb["fmax_mhz"]]:
        errors.append(f"scene_bench's Fmax {sb['fmax_mhz']} is not docs/fpga_figures.json's {fmax}")
    if f"({sb['fmax_mhz']:.2f} MHz, `specular_stream`; read from `docs/fpga_figures.json`)" not in md:
        errors.append("System: the Fmax sentence does not name docs/fpga_figures.json and its value")
    # Goals and headline, recomputed for each configuration the run measured.
    configs = [("as scene_bench defines it", {x["scene"]: x["ns_per_pixel"]["phong_sleef"] / x["ns_per_pixel"]["device"]
                                                for x in scenes})]
    for key, label in (("avx2", "AVX2 throughout"), ("avx512", "AVX-512 throughout (Phong with SLEEF powf16)")):
        if all(key in x.get("isa_matched", {}) for x in scenes):
            m = {x["scene"]: x["isa_matched"][key] for x in scenes}
            configs.append((label, {n: v["phong_sleef"] / v["device"] for n, v in m.items()}))
    goal_lines = [l for l in md.splitlines() if l.startswith("- ") and ">= 5 x where the mean span" in l]
    if len(goal_lines) != len(configs):
        errors.append(f"System goals: {len(goal_lines)} lines, {len(configs)} configurations measured")
    long_ = [x["scene"] for x in scenes if x["pixels"] / x["spans"] >= 8]
    for (label, ratio), line in zip(configs, goal_lines):
        if not line.startswith(f"- {label}"):
            errors.append(f"System goals: line '{line[:60]}' is not for '{label}'")
        below = [n for n, v in ratio.items() if v < 1.0]
        want = "**met** (lowest" if not below else "**missed** on " + ", ".join(f"{n} {ratio[n]:.2f} x" for n in below)
        if want not in line.split("; >= 5 x")[0]:
            errors.append(f"System goals ({label}): the 1.0 x verdict '{want}' not in '{line}'")
        if long_:
            below5 = [n for n in long_ if ratio[n] < 5.0]
            want = "**met** (lowest" if not below5 else "**missed** on " + ", ".join(f"{n} {ratio[n]:.2f} x" for n in below5)
            if want not in line.split("; >= 5 x")[1]:
                errors.append(f"System goals ({label}): the 5 x verdict '{want}' not in '{line}'")
        elif "no such scene" not in line:
            errors.append(f"System goals ({label}): no scene has a mean span >= 8 but the line says otherwise")
    head = next((l for l in md.splitlines() if l.startswith("**Headline (per scene")), "")
    ratio = configs[0][1]
    if f"**{min(ratio.values()):.2f}-{max(ratio.values()):.2f} x**" not in head:
        errors.append(f"headline '{head[:80]}...' does not give the range of {ratio}")
    for label, r in configs[1:]:
        if f"{label}: {min(r.values()):.2f}-{max(r.values()):.2f} x" not in head:
            errors.append(f"headline does not give the {label} range of {r}")
    # Break-even: the first length where the device is at or below phong_sleef.
    be = sb.get("break_even", [])
    if not be:
        errors.append("scene_bench.json has no break-even rows")
    else:
        first = next((r["l"] for r in be if r["device"] <= r["phong_sleef"]), None)
        if sb.get("break_even_l") != first:
            errors.append(f"break_even_l {sb.get('break_even_l')} is not the first crossing {first}")
        for key, dev, ph in (("avx2", "device_avx2", "phong_sleef"), ("avx512", "device_avx512", "phong_sleef_avx512")):
            if dev in be[0]:
                f2 = next((r["l"] for r in be if r[dev] <= r[ph]), None)
                if sb.get("break_even_l_isa", {}).get(key, "absent") != f2:
                    errors.append(f"break_even_l_isa.{key} is not the first crossing {f2}")
        if first is not None and f"from **l = {first} ({first + 1} pixels per span)**" not in md:
            errors.append(f"System: the break-even sentence does not give l = {first}")
        if not os.path.exists(os.path.join(out, "break_even.png")) or "![break-even](break_even.png)" not in md:
            errors.append("System: break_even.png missing or not shown")
    return errors


def check_plane(out, md, data):
    """Section 4b (the hardware plane) against report_data.json, the phong_*.json of
    phong_search --measure and hw_plane_cells.json: every cell of its table, and the ratios
    of its conclusion, recomputed here."""
    errors = []
    if "## 4b. The hardware plane" not in md:
        return ["section 4b (the hardware plane) heading missing"]
    t = table_after(md, "| point | core | SB_LUT4 |")
    if t is None:
        return ["hardware plane: the table is missing"]
    ranges = (64, 128, 1000)

    def worst(ns, vs, hi):
        sel = [val(v) for n, v in zip(ns, vs) if n <= hi]
        return max(sel) if sel else None

    def g(v):
        return "n/a" if v is None else f"{v:.3g}"
    with open(os.path.join(out, "hw_plane_cells.json")) as f:
        cells = json.load(f)
    expect = []  # (name, kind, lut4, ff, bram, ecp5, rel per range, abs per range)
    fits = {}  # name -> (the HX8K run's fit, its reason): the device's configurations
    hw = {h["name"]: h for h in data["hardware"]}
    for name in [h["name"] for h in data["hardware"]] + ["default-stream"]:
        h = hw[name.replace("-stream", "")]
        c = cells["device"].get(name)
        fits[f"device {name}"] = (c.get("fit", True), c.get("fit_reason", "")) if c else (True, "")
        expect.append((f"device {name}", "specular_stream" if name.endswith("-stream") else "specular_unit",
                       c and c["lut4"], c and c["ff"], c and c["bram"], None,
                       [worst(h["n"], h["max_rel_epicenter_lsb"], r) for r in ranges],
                       [worst(h["n"], h["max_abs_lobe"], r) for r in ranges]))
    phong_names = ("n1000", "n128", "n64", "n1000_consth", "n64_consth", "b2_n1000", "b3_n1000", "b4_n1000",
                   "cross_n1000", "cross_n1000_consth", "cross_b2_n1000", "cross_b3_n1000", "cross_b4_n1000")
    for name in phong_names:
        path = os.path.join(out, f"phong_{name}.json")
        if not os.path.exists(path):
            errors.append(f"hardware plane: {path} missing (phong_search --measure {name} did not run)")
            continue
        with open(path) as f:
            p = json.load(f)
        step = p["n_step"]
        grid = list(range(1, 1001, step)) + ([1000] if (999 % step) else [])
        if p["n"] != grid or len(p["rel_lsb"]) != len(grid) or len(p["abs_lsb"]) != len(grid):
            errors.append(f"hardware plane: phong_{name}.json's n grid is not 1, 1+{step}, ..., 1000")
        ci = cells["phong"].get(f"{name}/ice40")
        expect.append((f"phong {name}", "phong_stream", ci and ci["SB_LUT4"], ci and ci["SB_DFF*"],
                       ci and ci["SB_RAM40_4K"], cells["phong"].get(f"{name}/ecp5", "not run"),
                       [worst(p["n"], p["rel_lsb"], r) for r in ranges],
                       [worst(p["n"], p["abs_lsb"], r) for r in ranges]))
    if len(t) != len(expect):
        errors.append(f"hardware plane: {len(t)} table rows, the JSON files give {len(expect)} points")
    rows = {r[0]: r for r in t}
    for name, core, lut4, ff, bram, ecp5, rel, ab in expect:
        r = rows.get(name)
        if r is None:
            errors.append(f"hardware plane: no row for {name}")
            continue
        if lut4 is None:
            cost = ["n/a"] * 5
        else:
            lc = max(lut4, ff)
            fit, reason = fits.get(name, (False, ""))
            cost = [str(lut4), str(ff), str(bram), str(lc),
                    "no: does not fit any iCE40" if lc > 7680 else ("yes" if fit else f"no: {reason}")]
        e = "-" if ecp5 is None else ("not run" if ecp5 == "not run" else
                                       f"{ecp5['LUT4']} / {ecp5['MULT18X18D']} / {ecp5['DP16KD']} / "
                                       f"{ecp5['TRELLIS_FF']}, {ecp5['fmax_mhz']:.2f} MHz ({ecp5['part']})")
        want = [name, core] + cost + [e] + [g(v) for v in rel] + [g(v) for v in ab]
        if r != want:
            errors.append(f"hardware plane row {r} != {want} (from the JSON)")
    # The conclusion: per range the cheapest (LUT4) configuration of each side within the
    # budget (relative <= 1e-3, absolute <= 1e-2) over n = 1..R, and the ratios.
    for k, rng in enumerate(ranges):
        best = {}
        for side in ("device", "phong"):
            cand = [(x[2], x[0], x[3]) for x in expect if (x[0].startswith("phong ") == (side == "phong"))
                    and x[2] is not None and x[6][k] is not None and x[6][k] <= 1e-3 and x[7][k] <= 1e-2]
            best[side] = min(cand) if cand else None
        line = next((l for l in md.splitlines() if l.startswith(f"- n <= {rng}: ")), None)
        if line is None:
            errors.append(f"hardware plane: no conclusion line for n <= {rng}")
        elif best["device"] and best["phong"]:
            d, p = best["device"], best["phong"]
            want = (f"- n <= {rng}: {d[1]} against {p[1]}: the Phong core takes **{p[0] / d[0]:.1f} x** the "
                    f"device's LUT4 and {(p[0] + p[2]) / (d[0] + d[2]):.1f} x its LUT4 + FF.")
            if line != want:
                errors.append(f"hardware plane conclusion '{line}' != '{want}'")
        elif "not computed" not in line:
            errors.append(f"hardware plane: conclusion for n <= {rng} without measured cells: '{line}'")
    # Clocks per pixel per scene, when the run has a regression with the Phong stage.
    sim_path = os.path.join(out, "sim.json")
    sim = json.load(open(sim_path)) if os.path.exists(sim_path) else {}
    ph, ds = sim.get("phong", {}), sim.get("scenes_stream", {})
    if ph or ds:
        st = table_after(md, "| scene | device stream clocks/pixel |")
        names = sorted(set(ph) | set(ds))
        if st is None or [r[0] for r in st] != names:
            errors.append(f"hardware plane: the clocks-per-pixel table does not list the scenes {names}")
        else:
            for r in st:
                p, d = ph.get(r[0], {}), ds.get(r[0], {})
                if p and r[2] != f"{p['cycles'] / p['pixels']:.4f}":
                    errors.append(f"hardware plane: {r[0]} phong clocks/pixel {r[2]}, sim.json {p['cycles']}/{p['pixels']}")
                if d and r[1] != f"{float(d['stream_clocks_per_pixel']):.4f}":
                    errors.append(f"hardware plane: {r[0]} device clocks/pixel {r[1]}, sim.json {d}")
    has_cells = any(x[2] is not None for x in expect)
    if has_cells != ("![hardware plane](hw_plane.png)" in md and os.path.exists(os.path.join(out, "hw_plane.png"))):
        errors.append("hardware plane: the figure is missing, or shown without cells")
    return errors


def check(out):
    errors = []
    with open(os.path.join(out, "report_data.json")) as f:
        data = json.load(f)
    with open(os.path.join(out, "report.md")) as f:
        md = f.read()
    rows = table_rows(md)

    # Hardware configurations: one row per JSON config, every model-side cell recomputed.
    hw = data["hardware"]
    if not hw:
        errors.append("report_data.json has no hardware configurations")
    # The section 4 table only: the simulation's tables (section 5) have a row per
    # configuration too.
    hw_rows = table_after(md, "| config | ROM 12 addr/data bits |") or []
    for h in hw:
        mine = [r for r in hw_rows if r and r[0] == h["name"]]
        if len(mine) != 1:
            errors.append(f"hardware {h['name']}: {len(mine)} table rows, expected 1")
            continue
        r = mine[0]
        rel = [val(v) for v in h["max_rel_epicenter"]]
        ab = [val(v) for v in h["max_abs_lobe"]]
        want = {
            1: f"{'interp' if h['cos_interp'] else 'direct'} {h['cos_addr_bits']}/{h['cos_data_bits']}",
            2: h["policy"],
            3: "{" + ",".join(map(str, h["banks"])) + "} (" + ",".join(map(str, h["bank_max_n"])) + ")",
            4: f"{h['coef_rom_bits'] + h['cos_rom_bits']} ({h['coef_rom_bits']} + {h['cos_rom_bits']})",
            5: pct(max(rel)),
            6: pct(max(val(v) for v in h["max_rel_epicenter_lsb"])),
        }
        for col, w in want.items():
            if r[col] != w:
                errors.append(f"hardware {h['name']} column {col}: report '{r[col]}', JSON gives '{w}'")
        if f"{max(ab):.3g}" not in r:
            errors.append(f"hardware {h['name']}: worst abs. lobe {max(ab):.3g} (JSON) not in the row {r}")
        # ROM 12 bits from the configuration itself (banks x 2^addr x word: the value with its
        # integer bit and the step when interpolated, the saturating value when direct), not
        # from the JSON's own sums; ROM 9 has 2^10 words (n up to 1000) of a whole number of bits.
        word = h["cos_data_bits"] + 1 + h["cos_delta_bits"] if h["cos_interp"] else h["cos_data_bits"]
        cos_bits = len(h["banks"]) * (1 << h["cos_addr_bits"]) * word
        if h["cos_rom_bits"] != cos_bits or h["coef_rom_bits"] % 1024 != 0:
            errors.append(f"hardware {h['name']}: ROM bits {h['coef_rom_bits']} + {h['cos_rom_bits']}, "
                          f"formats give 1024 x w + {cos_bits}")

    # The published-claims line of the patent: the worst of the JSON's patent evaluator.
    ev = {e["name"]: e for e in data["evaluators"]}
    for name, label in (("patent", "Patent (k in {1,2,4,16}, maclaurin a"),):
        worst = max(val(v) for v in ev[name]["max_rel_epicenter"])
        line = next((l for l in md.splitlines() if label in l), None)
        if line is None:
            errors.append(f"claims: no line for {name}")
        elif f"measured worst {pct(worst)}" not in line:
            errors.append(f"claims: {name} worst {pct(worst)} (JSON) not in '{line}'")
        elif ("holds" if worst <= 0.01 else "does NOT hold") not in line:
            errors.append(f"claims: {name} verdict does not follow from {worst}")

    # Albedo table: every printed value equals the JSON value at that n (3 decimals).
    header = next((r for r in rows if r[:2] == ["series", "convention"]), None)
    if header is None:
        errors.append("albedo table missing")
    else:
        ns = [int(c.split("=")[1]) for c in header[2:]]
        checked = 0
        for s in data["albedo"]:
            for conv in ("phong", "blinn"):
                r = next((r for r in rows if r[:2] == [s["name"], conv]), None)
                if r is None:
                    errors.append(f"albedo row {s['name']} / {conv} missing")
                    continue
                m = dict(zip(s["n"], s[conv]))
                for n, cell in zip(ns, r[2:]):
                    want = f"{val(m[n]):.3f}" if n in m else ""
                    checked += 1
                    if cell != want:
                        errors.append(f"albedo {s['name']} {conv} n={n}: report '{cell}', JSON '{want}'")
        if checked == 0:
            errors.append("albedo table: nothing compared")
    errors += check_system(out, md)
    errors += check_plane(out, md, data)
    return errors


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build")
    ap.add_argument("--out")
    ap.add_argument("--check-only")
    a = ap.parse_args()
    if a.check_only:
        out = a.check_only
    else:
        out = a.out or tempfile.mkdtemp(prefix="make_report_smoke_")
        p = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "make_report.py"), "--build", a.build,
                            "--out", out, "--smoke", "--n-step", "111"], cwd=ROOT)
        if p.returncode != 0:
            print(f"make_report.py --smoke failed with exit code {p.returncode}")
            return 1
    errors = check(out)
    for e in errors:
        print(e)
    print(f"{len(errors)} mismatches between {out}/report.md and report_data.json, scene_bench.json, "
          "phong_*.json, hw_plane_cells.json")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
