#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Speed-against-error report (docs/speed_error.md): `make report`.

Runs this build's measurement programs and writes OUT/report.md with PNG plots beside it.
Every figure in the text is taken from the outputs of this run:
  BUILD/bin/evaluator_bench   Google Benchmark timing of the C++ evaluators (ns per pixel)
  BUILD/bin/scene_bench       the speed per scene, setup included (docs/system.md): every span of
                              every scenes/*.json by the device method and its competitors, the
                              break-even span length, the host cores it takes to feed the core
  BUILD/bin/report_data       errors (docs/metrics.md), albedo, device error of RTL
                              configurations (golden model), the hard cases of docs/scanline_setup.md
  scripts/fpga.py --top unit   HX8K cell counts per RTL build configuration (committed ROMs)
  BUILD/bin/phong_search      the per-pixel Blinn-Phong core's error per configuration (section 4b,
                              scripts/hw_plane.py; its cells from docs/fpga_figures.json)
  BUILD/bin/sim_regression    Verilator regression throughput (reduced random count)
  scripts/fpga.py             out-of-context place and route (nextpnr-ice40, HX8K and UP5K)
Missing programs are reported in the text, not silently skipped.

usage: scripts/make_report.py --build build --out build/report [--random N] [--jobs J] [--scene-reps R]
"""
import argparse
import concurrent.futures
import datetime
import glob
import json
import math
import os
import platform
import re
import subprocess
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import hw_plane  # noqa: E402  (scripts/hw_plane.py: the hardware plane, section 4b)
import verdict  # noqa: E402  (scripts/verdict.py: the verdict per budget and span length, section 4c)
import plot_break_even  # noqa: E402  (scripts/plot_break_even.py, beside this file)
import rtl_filelist as rtl_filelist_reader  # noqa: E402  (scripts/rtl_filelist.py)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def rtl_filelist():
    """The device core's filelist rtl/core/core.f expanded by scripts/rtl_filelist.py (the one
    reader of the format, rtl/README.md#filelists): sources in compile order and include
    directories, absolute."""
    exp = rtl_filelist_reader.expand(["rtl/core/core.f"], ROOT)
    return [os.path.join(ROOT, s) for s in exp.sources], [os.path.join(ROOT, d) for d in exp.incdirs]


def rtl_sources():
    return rtl_filelist()[0]


BENCH_NS = [5, 50, 500]
BANDS = [(1, 6), (7, 100), (101, 1000)]
# Evaluators in table order: key, label, how it is fed.
EVALUATORS = [
    ("pow", "exact std::pow", "c = N.H"),
    ("exp2poly", "exp2(n log2 c), own polynomials", "c"),
    ("lut256", "256-entry LUT, linear interpolation", "c"),
    ("schlick", "Schlick", "c"),
    ("schlick_mod", "modified Schlick", "c"),
    ("lyon16", "lyon-16", "c"),
    ("prototype", "prototype cos^2(ax)", "angle"),
    ("patent", "patent, float (maclaurin a)", "angle"),
    ("patent_minimax", "patent, float, minimax a", "angle"),
    ("device", "golden fixed-point device model, patent build (direct ROM 12, maclaurin)", "registers"),
    ("device_minimax", "golden fixed-point device model, default build (interpolated ROM 12, minimax)", "registers"),
    # whole-span evaluators (model/reference/span_shade.hpp): span parameters in, nothing precomputed per pixel
    ("pow_cos", "span: scalar double std::pow(cos psi, n)", "psi0, dpsi"),
    ("phong_scalar", "span: per-pixel Phong, float (lerp N, normalize, N.H, powf)", "N0, N1, H"),
    ("phong_sleef", "span: per-pixel Phong, AVX2 + SLEEF powf8", "N0, N1, H"),
    ("device_simd", "span: device method cos^k(a psi), float, vectorized (AVX2)", "psi0, dpsi"),
    ("device_simd_sse2", "span: the same kernel, x86-64 baseline build (SSE2)", "psi0, dpsi"),
]
COLORS = {key: plt.get_cmap("tab20")(i % 20) for i, (key, _, _) in enumerate(EVALUATORS)}
TOLERANCE = 0.0025  # the "within 0.25 % epicenter error" headline


def fnum(v):
    """JSON numbers from report_data: non-finite ones arrive as strings."""
    return float(v) if not isinstance(v, (int, float)) else float(v)


def fmt_err(v, pct=True):
    if v is None:
        return "n/a"
    if math.isinf(v):
        return "unbounded"
    if math.isnan(v):
        return "nan"
    return f"{100 * v:.3g} %" if pct else f"{v:.3g}"


def bench_args(out_path, min_time=0.05, repetitions=3, filt=None):
    """evaluator_bench's command-line options: JSON to out_path, median of the repetitions."""
    args = ["--benchmark_format=json", f"--benchmark_out={out_path}", "--benchmark_out_format=json",
            f"--benchmark_min_time={min_time}", f"--benchmark_repetitions={repetitions}",
            "--benchmark_report_aggregates_only=true"]
    return args + ([f"--benchmark_filter={filt}"] if filt else [])


def parse_bench(data):
    """evaluator_bench's Google Benchmark JSON to (per_pixel, per_span): per_pixel[evaluator][n]
    is ns per pixel for the benchmarks named "<evaluator>/<n>", per_span[name] ns per span for
    the scanline-setup benchmarks named without "/<n>" (items are spans there). Medians only.
    Raises ValueError on a name of any other form, naming it, so that a new benchmark name
    fails loudly instead of breaking the report later (tests/report/check_bench_parse.py)."""
    per_pixel, per_span = {}, {}
    for b in data.get("benchmarks", []):
        if b.get("aggregate_name") != "median":
            continue
        name = b.get("run_name", "")
        ips = b.get("items_per_second")
        if not ips or ips <= 0:
            raise ValueError(f"benchmark '{name}' has no positive items_per_second")
        parts = name.split("/")
        if len(parts) == 1 and parts[0]:
            per_span[name] = 1e9 / ips
        elif len(parts) == 2 and parts[0] and parts[1].isdigit():
            per_pixel.setdefault(parts[0], {})[int(parts[1])] = 1e9 / ips
        else:
            raise ValueError(f"benchmark name '{name}' is neither '<evaluator>/<n>' nor a plain setup name")
    return per_pixel, per_span


def run(cmd, log, timeout=600, cwd=ROOT, env=None):
    t0 = time.time()
    with open(log, "w") as lf:
        lf.write("$ " + " ".join(cmd) + "\n")
        lf.flush()
        p = subprocess.run(cmd, cwd=cwd, stdout=lf, stderr=subprocess.STDOUT, timeout=timeout, env=env)
    return p.returncode, time.time() - t0


class Report:
    def __init__(self, args):
        self.args = args
        self.build = os.path.abspath(args.build)
        self.out = os.path.abspath(args.out)
        self.bin = os.path.join(self.build, "bin")
        self.logs = os.path.join(self.out, "logs")
        os.makedirs(self.logs, exist_ok=True)
        self.missing = []  # what could not be measured, quoted in the report
        self.setup_ns = {}  # evaluator_bench's setup benchmarks, ns per span (parse_bench)
        self.timings = {}

    def exe(self, name):
        path = os.path.join(self.bin, name)
        return path if os.access(path, os.X_OK) else None

    # ---------------------------------------------------------------- measurements
    def bench(self):
        exe = self.exe("evaluator_bench")
        if not exe:
            self.missing.append("evaluator_bench was not built: no timings")
            return {}
        path = os.path.join(self.out, "bench.json")
        rc, secs = run([exe] + bench_args(path), os.path.join(self.logs, "bench.log"))
        self.timings["evaluator_bench"] = secs
        if rc != 0:
            self.missing.append(f"evaluator_bench failed (exit {rc}), see logs/bench.log")
            return {}
        data = json.load(open(path))
        self.bench_context = data.get("context", {})
        try:
            ns, self.setup_ns = parse_bench(data)
        except ValueError as e:
            self.missing.append(f"evaluator_bench's JSON could not be read: {e}")
            return {}
        return ns

    def model_data(self):
        exe = self.exe("report_data")
        if not exe:
            self.missing.append("report_data was not built: no errors, albedo or hard cases")
            return {}
        path = os.path.join(self.out, "report_data.json")
        rc, secs = run([exe, "--out", path, "--n-step", str(self.args.n_step)], os.path.join(self.logs, "report_data.log"))
        self.timings["report_data"] = secs
        if rc != 0:
            self.missing.append(f"report_data failed (exit {rc}), see logs/report_data.log")
            return {}
        return json.load(open(path))

    def synth_one(self, cfg):
        """Cells of cfg['top'] (default specular_unit) for one build configuration of report_data's
        hardware section: scripts/fpga.py on the HX8K (the one flow of every FPGA figure,
        rtl/fpga/README.md), its committed ROM files and its parameters by --param; LUT trees
        (MulTileBits=0), as on the HX8K. fpga.py reuses a run whose sources, ROMs, parameters
        and tools are unchanged (--fresh-synth forces it)."""
        top = cfg.get("top", "specular_unit")
        for rom in (cfg["coef_rom"], cfg["cos_rom"]):
            if not os.path.exists(os.path.join(ROOT, rom)):
                return {"error": f"ROM file {rom} missing (make roms)"}
        nb = len(cfg["banks"])
        # BankMaxN is {bank_max_n[nb-1], ..., bank_max_n[0]}, 10 bits each.
        packed = sum(v << (10 * j) for j, v in enumerate(cfg["bank_max_n"]))
        params = {"CoefBits": cfg["coef_bits"], "CoefFrac": cfg["coef_frac"], "PsiMulFrac": cfg["psi_mul_frac"],
                  "CosInterp": 1 if cfg["cos_interp"] else 0, "CosAddrBits": cfg["cos_addr_bits"],
                  "CosDataBits": cfg["cos_data_bits"], "CosDeltaBits": cfg["cos_delta_bits"],
                  "CosFracBits": cfg["cos_frac_bits"], "NumBanks": nb, "BankMaxN": f"{10 * nb}'h{packed:x}",
                  "CoefRomFile": cfg["coef_rom"], "CosRomFile": cfg["cos_rom"]}
        out = os.path.join(self.out, "synth", cfg["name"])
        cmd = [sys.executable, os.path.join(ROOT, "scripts", "fpga.py"), "--top", {"specular_unit": "unit"}.get(top, "stream"),
               "--device", "hx8k", "--out", out]
        for k, v in params.items():
            cmd += ["--param", f"{k}={v}"]
        if self.args.fresh_synth:
            cmd.append("--fresh")
        log = os.path.join(self.logs, f"synth_{cfg['name']}.log")
        t0 = time.time()
        try:
            rc, _ = run(cmd, log, timeout=3600, env=self.fpga_env())
        except subprocess.TimeoutExpired:
            return {"error": "scripts/fpga.py timed out"}
        if rc != 0:
            return {"error": f"scripts/fpga.py exit {rc} (logs/{os.path.basename(log)})"}
        try:
            r = json.load(open(os.path.join(out, "summary.json")))["runs"][0]
        except (OSError, ValueError, KeyError, IndexError):
            return {"error": f"scripts/fpga.py wrote no summary (logs/{os.path.basename(log)})"}
        y = r["yosys"]
        return {"lut4": y["lut4"], "ff": y["ff"], "bram": y["bram"], "carry": y["carry"],
                "fmax_mhz": r.get("fmax_mhz"), "fit": bool(r.get("fit")),
                "fit_reason": "" if r.get("fit") else re.sub(r" \(.*\)$", "", r.get("reason", "")),
                "reused": "result reused" in open(log).read(),
                "seconds": time.time() - t0}

    def fpga_env(self):
        """scripts/fpga.py's environment: its pinned tools in BUILD/venv, as `make fpga` has them
        (scripts/tools_venv.py installs them on first use)."""
        return dict(os.environ, SPECULAR_VENV=os.environ.get("SPECULAR_VENV", os.path.join(self.build, "venv")))

    def synth(self, configs):
        if not configs:
            return {}
        t0 = time.time()
        with concurrent.futures.ThreadPoolExecutor(max_workers=self.args.jobs) as pool:
            res = dict(zip([c["name"] for c in configs], pool.map(self.synth_one, configs)))
        self.timings["yosys (all configurations)"] = time.time() - t0
        for name, r in res.items():
            if "error" in r:
                self.missing.append(f"synthesis of {name}: {r['error']}")
        return res

    def pnr(self):
        """Out-of-context place and route (scripts/fpga.py: harnesses rtl/fpga/, Yosys synth_ice40,
        nextpnr-ice40) of the default specular_unit and specular_stream on the HX8K and the UP5K.
        A configuration that does not fit is a row with fit = no, not a failure."""
        out = os.path.join(self.out, "fpga")
        log = os.path.join(self.logs, "fpga.log")
        t0 = time.time()
        try:
            rc, _ = run([sys.executable, os.path.join(ROOT, "scripts", "fpga.py"), "--out", out], log, timeout=3600,
                        env=self.fpga_env())
        except subprocess.TimeoutExpired:
            rc = -1
        self.timings["place and route (scripts/fpga.py)"] = time.time() - t0
        try:
            runs = json.load(open(os.path.join(out, "summary.json")))["runs"]
        except (OSError, ValueError, KeyError):
            runs = []
        if rc != 0 or not runs:
            self.missing.append(f"scripts/fpga.py failed (exit {rc}), see logs/fpga.log")
        return runs

    def hardware_plane(self, data, cells):
        """Section 4b (scripts/hw_plane.py): the Phong configurations' errors (phong_search --measure,
        this run) and cells (docs/fpga_figures.json: make fpga's runs), the plane's rows and figure."""
        self.phong = hw_plane.measure_phong(self.exe("phong_search"), self.out, self.logs,
                                            max(self.args.n_step, 111) if self.args.smoke else self.args.n_step,
                                            self.missing, self.timings)
        self.phong_cells = hw_plane.phong_figures()
        if not self.phong_cells:
            self.missing.append("docs/fpga_figures.json has no phong_stream runs: no Phong cells in the hardware plane")
        self.plane_rows = hw_plane.points(data, self.phong, cells, self.phong_cells)
        # The raw counts the table was made from (tests/report/check_make_report.py reads them).
        with open(os.path.join(self.out, "hw_plane_cells.json"), "w") as f:
            json.dump({"device": {k: v for k, v in cells.items() if "lut4" in v},
                       "phong": {f"{c}/{m}": v["counts"] for (c, m), v in self.phong_cells.items()}}, f, indent=1)
        png = os.path.join(self.out, "hw_plane.png")
        if not hw_plane.plot(self.plane_rows, png, plt) and os.path.exists(png):
            os.remove(png)  # no cells in this run: no figure (not a stale one)

    def write_verdict(self, w, data, sim):
        """Section 4c (scripts/verdict.py): per budget and span length the device against the Phong
        cores in one currency, from this run's errors and the record's ECP5 cells; one figure per
        budget (verdict_b1.png, ...) and verdict.json."""
        figs = hw_plane.load_figures(os.path.join(ROOT, "docs", "fpga_figures.json"))
        errors = {c: verdict.worst_errors(j) for c, j in getattr(self, "phong", {}).items()}
        search = hw_plane.load_figures(os.path.join(ROOT, "docs", "measured", "device_search.json"))
        pts = verdict.load_points(figs, errors, verdict.device_budgets(data, figs), hw_plane.PHONG_CONFIGS,
                                  verdict.device_errors(data, search))
        res = verdict.verdict(pts, verdict.report_spans(sim, hw_plane.setup_ii_sim()))
        with open(os.path.join(self.out, "verdict.json"), "w") as f:
            json.dump({"points": [{k: v for k, v in p.items()} for p in pts], "verdict": res}, f, indent=1)
        verdict.write(w, res, pts)
        for path in verdict.plot(pts, self.out, plt):
            w(f"![{os.path.basename(path)}]({os.path.basename(path)})\n")

    def sim(self):
        exe = self.exe("sim_regression")
        if not exe:
            self.missing.append("sim_regression was not built: no simulation throughput")
            return {}
        path = os.path.join(self.out, "sim.json")
        rc, secs = run([exe, "--random", str(self.args.random), "--json", path,
                        "--images-dir", os.path.join(self.out, "scenes")], os.path.join(self.logs, "sim.log"))
        self.timings["sim_regression"] = secs
        if not os.path.exists(path):
            self.missing.append(f"sim_regression wrote no JSON (exit {rc}), see logs/sim.log")
            return {}
        data = json.load(open(path))
        data["exit_code"] = rc
        # The mean FLIP of the colour images the run wrote (docs/colour.md#flip; installs the pinned
        # flip-evaluator into the project's venv on first use).
        if data.get("colour"):
            flip = os.path.join(self.out, "colour_flip.json")
            frc, _ = run([sys.executable, os.path.join(ROOT, "scripts", "colour_flip.py"), "--sim-json", path,
                          "--json", flip], os.path.join(self.logs, "colour_flip.log"))
            if frc == 0 and os.path.exists(flip):
                data["colour_flip"] = json.load(open(flip))["scenes"]
            else:
                self.missing.append(f"scripts/colour_flip.py failed (exit {frc}), see logs/colour_flip.log: no FLIP")
        return data

    def scene_bench(self):
        """BUILD/bin/scene_bench over every scenes/*.json (docs/system.md); --smoke: one small scene,
        one round, a 4-length break-even sweep (the numbers are then only checked, not meaningful)."""
        exe = self.exe("scene_bench")
        if not exe:
            self.missing.append("scene_bench was not built: no per-scene speed")
            return {}
        path = os.path.join(self.out, "scene_bench.json")
        if os.path.exists(path):
            os.remove(path)
        if self.args.smoke:
            scenes = [os.path.join(ROOT, "scenes", "spheres.json")]
            opts = ["--reps", "1", "--min-time", "0.001", "--max-len", "3", "--break-even-spans", "256"]
        else:
            scenes = sorted(glob.glob(os.path.join(ROOT, "scenes", "*.json")))
            opts = ["--reps", str(self.args.scene_reps), "--min-time", "0.02"]
        rc, secs = run([exe, "--json", path] + opts + scenes, os.path.join(self.logs, "scene_bench.log"), timeout=1800)
        self.timings["scene_bench"] = secs
        if rc != 0 or not os.path.exists(path):
            self.missing.append(f"scene_bench failed (exit {rc}), see logs/scene_bench.log")
            return {}
        data = json.load(open(path))
        if data.get("break_even"):
            plot_break_even.plot(data, os.path.join(self.out, "break_even.png"))
        return data

    # ---------------------------------------------------------------- analysis
    @staticmethod
    def worst(ns, vals, lo=1, hi=1000):
        sel = [fnum(v) for n, v in zip(ns, vals) if lo <= n <= hi]
        return max(sel) if sel else None

    def error_rows(self, data):
        """name -> {n, rel, abs} for float evaluators and the two single-bank device builds."""
        rows = {}
        for e in data.get("evaluators", []):
            rows[e["name"]] = {"n": e["n"], "rel": [fnum(v) for v in e["max_rel_epicenter"]],
                               "abs": [fnum(v) for v in e["max_abs_lobe"]]}
        for h in data.get("hardware", []):
            key = {"patent": "device", "single": "device_minimax"}.get(h["name"])
            if key:
                rows[key] = {"n": h["n"], "rel": [fnum(v) for v in h["max_rel_epicenter"]],
                             "abs": [fnum(v) for v in h["max_abs_lobe"]]}
        return rows

    # ---------------------------------------------------------------- plots
    def plot_plane(self, rows, speed):
        fig, axes = plt.subplots(1, 2, figsize=(13, 5.5))
        for ax, metric, title in ((axes[0], "rel", "max relative error in the epicenter"),
                                  (axes[1], "abs", "max absolute error over the lobe")):
            for key, label, _ in EVALUATORS:
                if key not in rows or key not in speed:
                    continue
                t = [speed[key][n] for n in BENCH_NS if n in speed[key]]
                x = sum(t) / len(t)
                # n = 1 is excluded from the plotted worst case: its epicenter reaches pi/2 where
                # relative error is unbounded for every shape that does not vanish there.
                y = self.worst(rows[key]["n"], rows[key][metric], 2, 1000)
                if y is None or not math.isfinite(y):
                    continue
                floor = 1e-9  # exact to rounding: drawn on the floor so the scale stays readable
                shown = max(y, floor)
                ax.scatter([x], [shown], s=50, color=COLORS[key])
                ax.annotate(key + (" (< 1e-9)" if y < floor else ""), (x, shown), textcoords="offset points",
                            xytext=(6, -12 if key in ("device_minimax", "schlick_mod", "patent_minimax") else 4), fontsize=9)
            if metric == "rel":
                ax.axhline(TOLERANCE, color="grey", ls="--", lw=1)
                ax.text(ax.get_xlim()[0], TOLERANCE * 1.15, " 0.25 %", color="grey", fontsize=8)
            ax.set_yscale("log")
            ax.set_xscale("log")
            ax.set_xlabel("ns per pixel, log scale (mean of n = 5, 50, 500; this run)")
            ax.set_ylabel("worst over n = 2..1000")  # the metric is the title
            ax.set_title(title)
            ax.grid(True, which="both", alpha=0.3)
        fig.suptitle("Speed against error (docs/speed_error.md)")
        fig.tight_layout()
        fig.savefig(os.path.join(self.out, "plane.png"), dpi=110)
        plt.close(fig)

    def plot_err_vs_n(self, rows):
        fig, axes = plt.subplots(1, 2, figsize=(14, 5.5))
        for key, label, _ in EVALUATORS:
            if key not in rows:
                continue
            r = rows[key]
            for ax, metric in ((axes[0], "rel"), (axes[1], "abs")):
                pts = [(n, v) for n, v in zip(r["n"], r[metric]) if math.isfinite(v) and v > 0]
                if pts:
                    ax.plot([p[0] for p in pts], [p[1] for p in pts], label=key, lw=1.3, color=COLORS[key],
                            ls="--" if key.startswith("device") else "-")
        axes[0].axhline(TOLERANCE, color="grey", ls="--", lw=1)
        axes[0].axhline(0.01, color="grey", ls=":", lw=1)
        axes[0].set_ylabel("max relative error in the epicenter")
        axes[1].set_ylabel("max absolute error over [0, pi/2]")
        # Exact values (k = n, or the LUT at n = 1) drop to rounding level; clip them.
        axes[0].set_ylim(1e-6, 2)
        axes[1].set_ylim(1e-7, 2)
        for ax in axes:
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel("n")
            ax.grid(True, which="both", alpha=0.3)
        axes[0].legend(fontsize=8, ncol=2)
        fig.suptitle("Error against n (dashed: 0.25 %, dotted: the patent's 1 %)")
        fig.tight_layout()
        fig.savefig(os.path.join(self.out, "error_vs_n.png"), dpi=110)
        plt.close(fig)

    def plot_err_vs_angle(self, curves):
        fig, axes = plt.subplots(2, len(curves), figsize=(5 * len(curves), 8.5), squeeze=False)
        for j, c in enumerate(curves):
            x = c["x"]
            ref = c["reference"]
            top, bot = axes[0][j], axes[1][j]
            top.plot(x, ref, "k", lw=2.5, label="cos^n (reference)")
            for key, _, _ in EVALUATORS:
                if key not in c["series"] or key == "pow":
                    continue
                y = [fnum(v) for v in c["series"][key]]
                top.plot(x, y, lw=1.2, label=key, color=COLORS[key])
                bot.plot(x, [a - b for a, b in zip(y, ref)], lw=1.2, label=key, color=COLORS[key])
            for ax in (top, bot):
                ax.axvline(c["epicenter_end"], color="grey", ls="--", lw=1)
                ax.grid(True, alpha=0.3)
                ax.set_xlabel("angle x (rad); dashed: end of the epicenter")
            top.set_title(f"n = {c['n']}")
            top.set_ylabel("F(x)")
            bot.set_ylabel("F(x) - cos^n(x)")
        axes[0][0].legend(fontsize=8)
        fig.suptitle("Shapes and their error against the angle")
        fig.tight_layout()
        fig.savefig(os.path.join(self.out, "error_vs_angle.png"), dpi=110)
        plt.close(fig)

    def plot_albedo(self, albedo):
        fig, axes = plt.subplots(1, 2, figsize=(14, 5.5))
        for ax, conv in ((axes[0], "phong"), (axes[1], "blinn")):
            for s in albedo:
                ls = "--" if "fit" in s["name"] else "-"
                ax.plot(s["n"], [fnum(v) for v in s[conv]], ls, label=s["name"], lw=1.3)
            ax.axhline(1.0, color="k", lw=1.5)
            ax.set_xscale("log")
            ax.set_yscale("log")  # kutlog's blinn-convention albedo (~4) would flatten the rest
            ax.set_xlabel("n")
            ax.set_ylabel("hemispherical albedo, light at the normal")
            ax.set_title(f"{conv} convention (angle = {'theta' if conv == 'phong' else 'theta/2'})")
            ax.grid(True, which="both", alpha=0.3)
        axes[0].legend(fontsize=8)
        fig.suptitle("Albedo against n (energy-correct means <= 1)")
        fig.tight_layout()
        fig.savefig(os.path.join(self.out, "albedo.png"), dpi=110)
        plt.close(fig)

    def plot_hardware(self, hw, cells):
        fig, axes = plt.subplots(1, 2, figsize=(13, 5.5))
        for h in hw:
            y = self.worst(h["n"], h["max_rel_epicenter"])
            bits = h["coef_rom_bits"] + h["cos_rom_bits"]
            axes[0].scatter([bits / 1024], [y])
            axes[0].annotate(h["name"], (bits / 1024, y), textcoords="offset points", xytext=(4, 4), fontsize=8)
            c = cells.get(h["name"], {})
            if "lut4" in c:
                axes[1].scatter([c["lut4"]], [y])
                axes[1].annotate(h["name"], (c["lut4"], y), textcoords="offset points", xytext=(4, 4), fontsize=8)
        axes[0].set_xlabel("ROM Kbit (ROM 9 + ROM 12)")
        axes[1].set_xlabel("ice40 LUT4 cells (Yosys synth_ice40)")
        for ax in axes:
            ax.set_ylabel("device: worst max relative epicenter error, n = 1..1000")
            ax.set_yscale("log")
            ax.grid(True, which="both", alpha=0.3)
        fig.suptitle("RTL configurations: device error against cost")
        fig.tight_layout()
        fig.savefig(os.path.join(self.out, "hardware.png"), dpi=110)
        plt.close(fig)

    # ---------------------------------------------------------------- text
    # The configurations of the per-scene comparison: (key, label, ratio of phong_sleef's time to the device's).
    SYSTEM_CONFIGS = (
        ("default", "as scene_bench defines it (setup_batch's automatic path: the widest instruction set of the machine; AVX2 shading)",
         lambda x: x["speedup_vs_phong_sleef"]["device"]),
        ("avx2", "AVX2 throughout", lambda x: x.get("isa_matched", {}).get("avx2", {}).get("speedup")),
        ("avx512", "AVX-512 throughout (Phong with SLEEF powf16)",
         lambda x: x.get("isa_matched", {}).get("avx512", {}).get("speedup")),
    )

    @classmethod
    def system_goals(cls, sb):
        """The goals of docs/system.md per configuration: a list of (key, label, {scene: ratio},
        scenes below 1.0 x, scenes with mean span >= 8 below 5 x, names of the scenes with mean span >= 8).
        Configurations this run did not measure are left out."""
        scenes = sb.get("scenes", [])
        out = []
        for key, label, f in cls.SYSTEM_CONFIGS:
            ratio = {x["scene"]: f(x) for x in scenes}
            if not scenes or any(v is None for v in ratio.values()):
                continue
            long_ = [x["scene"] for x in scenes if x["mean_span"] >= 8]
            out.append((key, label, ratio, [n for n, v in ratio.items() if v < 1.0],
                        [n for n in long_ if ratio[n] < 5.0], long_))
        return out

    @staticmethod
    def goal_text(ratio, below, long_below, long_):
        def where(names):
            return ", ".join(f"{n} {ratio[n]:.2f} x" for n in names)
        lo = min(ratio, key=ratio.get)
        t = ("**met** (lowest " + where([lo]) + ")" if not below else "**missed** on " + where(below))
        t += "; >= 5 x where the mean span is >= 8 pixels: "
        if not long_:
            return t + "no such scene"
        lo5 = min(long_, key=lambda n: ratio[n])
        return t + ("**met** (lowest " + where([lo5]) + ")" if not long_below else "**missed** on " + where(long_below))

    def write(self, speed, data, cells, sim, pnr=(), sb=None):
        rows = self.error_rows(data)
        md = []
        w = md.append
        w("# Speed against error: report\n")
        w(f"Generated {datetime.datetime.now().strftime('%Y-%m-%d %H:%M')} by `scripts/make_report.py` from the "
          f"build in `{os.path.relpath(self.build, ROOT)}`; every number below comes from this run "
          "(raw outputs beside this file: `bench.json`, `report_data.json`, `sim.json`, `synth/*/summary.json`, `logs/`).")
        ctx = getattr(self, "bench_context", {})
        if ctx:
            w(f"Host: {ctx.get('num_cpus', '?')} CPUs at {ctx.get('mhz_per_cpu', '?')} MHz, {platform.machine()}, "
              f"load average {ctx.get('load_avg', '?')} (other jobs share the machine; timings are medians of 3 repetitions).")
            if ctx.get("library_build_type") == "debug":
                w("Debian's libbenchmark reports itself as a debug build; that concerns the harness only (entered once per "
                  "2048-pixel line), the timed loops are this project's Release (-O3) code.")
        if self.missing:
            w("\n**Not measured in this run:**\n")
            for m in self.missing:
                w(f"- {m}")
        w("")

        # --- the headline: per scene, setup included (section 7)
        sb = sb or {}
        goals = self.system_goals(sb)
        if goals:
            key, label, ratio, below, long_below, long_ = goals[0]
            lo = min(ratio, key=ratio.get)
            worst = next(x for x in sb["scenes"] if x["scene"] == lo)
            w("**Headline (per scene, scanline setup included; section 7):** the device method in software -- the batched "
              "setup of every span plus its pixels, over all spans of all lights of a scene -- against per-pixel Phong "
              f"with SLEEF: **{min(ratio.values()):.2f}-{max(ratio.values()):.2f} x** over the {len(ratio)} scenes {label} "
              f"(slowest: {lo}, {worst['mean_span']:.2f} pixels per span)"
              + "".join(f"; {lab}: {min(r.values()):.2f}-{max(r.values()):.2f} x" for _, lab, r, _, _, _ in goals[1:])
              + ". Goal >= 1.0 x on every scene, "
              + "; ".join(f"{lab}: " + self.goal_text(r, b_, lb, lg) for _, lab, r, b_, lb, lg in goals) + ".\n")

        # --- headline and the plane
        w("## 1. Speed against error of the C++ evaluators\n")
        w("All evaluators shade the same scanline of 2048 pixels (l = 2047) across the highlight lobe, timed side by side "
          "with Google Benchmark in one run (`evaluator_bench`). Each gets its natural input precomputed outside the timed "
          "loop: `c = cos x` (a dot product in a renderer) for pow, exp2poly, lut256, Schlick, modified Schlick and lyon-16; "
          "the angle x for the cos^k(a x) family (prototype, patent); the device registers for the golden fixed-point model "
          "(`DeviceModel::line`, integer arithmetic of the RTL). Per-n state (LUT, coefficient, ROMs) is built outside the "
          "loop, as once per material; the LUT rebuild itself costs "
          + ", ".join(f"{speed['lut256_build'][n] * 256 / 1000:.2f} us (n = {n})" for n in BENCH_NS
                      if n in speed.get("lut256_build", {})) + ".\n")
        w("Errors are the metrics of docs/metrics.md, evaluated with `shape_error` (dense sampling plus golden-section "
          f"refinement) for every n = 1, {1 + data.get('n_step', 1)}, ..., 1000 (step {data.get('n_step', 1)}); the device rows use the golden model over "
          "2048-pixel scanlines per n (section 4 below). At n = 1 the epicenter reaches pi/2 where cos^n = 0, so the "
          "relative error there is unbounded for every shape that does not vanish at pi/2 (marked 'unbounded').\n")
        pow_t = speed.get("pow", {})
        hdr = "| evaluator | input | " + " | ".join(f"ns/px n={n}" for n in BENCH_NS) + \
              " | x std::pow | worst rel. epicenter n=1..1000 | " + " | ".join(f"n={a}..{b}" for a, b in BANDS) + \
              " | worst abs. lobe |"
        w(hdr)
        w("|" + "---|" * (hdr.count("|") - 1))
        best = best_float = None
        for key, label, inp in EVALUATORS:
            t = speed.get(key, {})
            times = [t.get(n) for n in BENCH_NS]
            ratios = [t[n] / pow_t[n] for n in BENCH_NS if n in t and n in pow_t]
            ratio = sum(ratios) / len(ratios) if ratios else None
            r = rows.get(key)
            worst = self.worst(r["n"], r["rel"]) if r else None
            bands = [self.worst(r["n"], r["rel"], a, b) if r else None for a, b in BANDS]
            wabs = self.worst(r["n"], r["abs"]) if r else None
            tcells = " | ".join(f"{x:.2f}" if x else "n/a" for x in times)
            rtxt = f"{ratio:.2f}" if ratio else "n/a"
            w(f"| {label} | {inp} | {tcells} | {rtxt} | {fmt_err(worst)} | "
              + " | ".join(fmt_err(b) for b in bands) + f" | {fmt_err(wabs, False)} |")
            if worst is not None and worst <= TOLERANCE and ratio is not None and key != "pow":
                mean_t = sum(x for x in times if x) / len([x for x in times if x])
                if best is None or mean_t < best[1]:
                    best = (label, mean_t, ratio, worst)
                if not key.startswith("device") and (best_float is None or mean_t < best_float[1]):
                    best_float = (label, mean_t, ratio, worst)
        w("")
        if best:
            w(f"**Fastest per-pixel evaluator** (one 2048-pixel line, inputs precomputed, no setup) within "
              f"{100 * TOLERANCE:g} % epicenter error over all n = 1..1000: "
              f"**{best[0]}**: {best[1]:.2f} ns per pixel, {best[2]:.2f} x the time of `std::pow` "
              f"(worst epicenter error {fmt_err(best[3])}).\n")
            if best_float and best_float[0] != best[0]:
                w(f"Among the floating-point evaluators it is **{best_float[0]}**: {best_float[1]:.2f} ns per pixel, "
                  f"{best_float[2]:.2f} x `std::pow` (worst {fmt_err(best_float[3])}).\n")
        else:
            w(f"**Fastest per-pixel evaluator:** no evaluator other than std::pow stays within {100 * TOLERANCE:g} % epicenter "
              "error for all n in this run.\n")
        # --- the device method as a software renderer would call it, against what it would otherwise use
        ds, ps, pc = speed.get("device_simd", {}), speed.get("phong_sleef", {}), speed.get("pow_cos", {})
        common = [n for n in BENCH_NS if n in ds and n in ps and n in pc]
        if common:
            r_ps = [ps[n] / ds[n] for n in common]
            r_pc = [pc[n] / ds[n] for n in common]
            wd = self.worst(rows["device_simd"]["n"], rows["device_simd"]["rel"], 2, 1000) if "device_simd" in rows else None
            w(f"**Per-pixel figure (software span evaluators, same benchmark run; one 2048-pixel line, l = 2047, the "
              f"scanline setup excluded -- section 7 has the scenes with the setup):** `device_simd` (the device method "
              f"cos^k(a psi) vectorized over a span, float) is **{min(r_ps):.1f}-{max(r_ps):.1f} x faster per pixel than per-pixel Phong "
              f"with AVX2 + SLEEF** (`phong_sleef`) and **{min(r_pc):.1f}-{max(r_pc):.1f} x faster than scalar "
              f"`std::pow(cos psi, n)`** (`pow_cos`) over n = {', '.join(map(str, common))}, at a worst epicenter error of "
              f"{fmt_err(wd)} over n = 2..1000 (goal: >= 10 x, >= 40 x, <= 0.1 %).\n")
            w("| n | " + " | ".join(f"{k} ns/px" for k in ("pow_cos", "phong_scalar", "phong_sleef", "device_simd_sse2", "device_simd"))
              + " | phong_sleef / device_simd | pow_cos / device_simd |")
            w("|---|---|---|---|---|---|---|---|")
            for n in common:
                bcells = [speed.get(k, {}).get(n) for k in ("pow_cos", "phong_scalar", "phong_sleef", "device_simd_sse2", "device_simd")]
                w(f"| {n} | " + " | ".join(f"{c:.3f}" if c else "n/a" for c in bcells) + f" | {ps[n] / ds[n]:.1f} | {pc[n] / ds[n]:.1f} |")
            w("")
        w("![speed against error](plane.png)\n")
        if self.setup_ns:
            ref = self.setup_ns.get("setup_scalar")
            w("The scanline setup, per span, in the same `evaluator_bench` run (4096 synthetic spans, "
              "docs/scanline_setup.md#batched-setup; `setup_scalar` is the scalar double reference):\n")
            w("| setup | ns per span | x setup_scalar |")
            w("|---|---|---|")
            for name in sorted(self.setup_ns):
                t = self.setup_ns[name]
                w(f"| {name} | {t:.2f} | " + (f"{ref / t:.2f}" if ref else "n/a") + " |")
            w("")
        w("![error against n](error_vs_n.png)\n")
        w("![error against angle](error_vs_angle.png)\n")

        # --- published claims
        w("## 2. Published claims, re-measured\n")

        def wr(key, lo=1, hi=1000, metric="rel"):
            r = rows.get(key)
            return self.worst(r["n"], r[metric], lo, hi) if r else None

        claims = []
        p = wr("patent")
        if p is not None:
            claims.append(f"Patent (k in {{1,2,4,16}}, maclaurin a, float): claimed <= 1 % epicenter error; measured worst "
                          f"{fmt_err(p)} over n = 1..1000 -> {'holds' if p <= 0.01 else 'does NOT hold'}. With minimax a: "
                          f"{fmt_err(wr('patent_minimax'))}.")
        p = wr("prototype", 2, 1000)
        if p is not None:
            claims.append(f"Prototype cos^2(ax): claimed > 10 %; measured worst {fmt_err(p)} over n = 2..1000 -> "
                          f"{'consistent' if p > 0.1 else 'contradicted'}.")
        p = wr("schlick", 2, 1000)
        if p is not None:
            claims.append(f"Schlick: claimed up to 10 % in the epicenter; measured worst {fmt_err(p)} over n = 2..1000 -> "
                          f"{'consistent' if p <= 0.1 * 1.05 else 'larger than claimed'}.")
        alb = {s["name"]: s for s in data.get("albedo", [])}
        for name in ("lyon16 (n+8)/(8 pi)", "f16 (n+6)/24.55"):
            s = alb.get(name)
            if not s:
                continue
            for conv in ("blinn", "phong"):
                vals = [fnum(v) for v in s[conv]]
                over = [n for n, v in zip(s["n"], vals) if v > 1.0]
                claims.append(f"{name}, {conv} convention: albedo range {min(vals):.3f}..{max(vals):.3f}; above 1 for "
                              + (f"{len(over)} of the {len(vals)} sampled n (n = {over[0]}..{over[-1]})" if over else "no sampled n")
                              + ".")
        for c in claims:
            w(f"- {c}")
        w("\nThe energy-correct-BRDF paper claims lyon-16 is not energy-correct for small n and that (n+6)/24.55 fixes it "
          "for all n in 1..1000; the albedo lines above and the figure below are the measurement (the paper uses the blinn "
          "convention).\n")

        # --- albedo
        w("## 3. Albedo against n\n")
        w("Hemispherical albedo with the light at the normal, both conventions of docs/metrics.md (phong: angle = theta; "
          "blinn: angle = theta/2), for Blinn-Phong with (n+8)/(8 pi), lyon-16 with the same factor, f16 = (n+6)/24.55 "
          "lyon-16, and kutlog (k = 2, Q = 0.3 and Q = 0.7, one in each range of the paper's fits) with the exact "
          "(integrated) coef and with the paper's fits, n = k+1..1000. Energy-correct means <= 1 (black line).\n")
        w("![albedo](albedo.png)\n")
        pick = [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000]
        if alb:
            w("| series | convention | " + " | ".join(f"n={n}" for n in pick) + " |")
            w("|---|---|" + "---|" * len(pick))
            for s in data["albedo"]:
                for conv in ("phong", "blinn"):
                    m = dict(zip(s["n"], s[conv]))
                    w(f"| {s['name']} | {conv} | " + " | ".join(
                        f"{fnum(m[n]):.3f}" if n in m else "" for n in pick) + " |")
            w("")

        # --- hardware
        hw = data.get("hardware", [])
        w("## 4. Hardware configurations\n")
        w("The build configurations of `model/device/rom_image.cpp` (`build_configs()`): the RTL default, the patent's own "
          "configuration and two variants; `sim_regression` verilates each with its parameters and checks it bit-exactly "
          "against the golden model (section 5), so every figure here is one the RTL produces. Device error: the golden "
          "fixed-point model over three scanlines of 2048 pixels for every n = 1..1000: psi in [0, x_e(n)] for the "
          "relative epicenter error, [0, min(pi/2, 12/sqrt n)] and [0, pi/2] for the absolute lobe error, reference "
          "C cos^n(psi_i) at the exact quantized pixel angles, C = 1. 'worst rel. epicenter' is raw (output quantization "
          "included; n = 1 over [0, pi/3], cos >= 1/2); 'goal metric' is the hardware goal: (|err| - 1 output LSB) / ref "
          "over the epicenter, n = 1 over all of [0, pi/2] wherever the reference is at least 4 LSB. Decoder tables are "
          "derived from the bank set (`model/device/decoder_table.hpp`: bank j+1 takes over at the first n where its float error "
          "is not larger; this reproduces the patent's 1 | 2 | 3..6 | 7..1000 for {1,2,4,16}). Cells: Yosys "
          "`synth_ice40` counts of `scripts/fpga.py --top unit --device hx8k` (the out-of-context harness with registered "
          "IO, its cells included; rtl/fpga/README.md) with `--param` for the configuration and its committed ROM files; "
          "multipliers are LUT trees (no DSP on the HX8K). (r): fpga.py did not re-run because the RTL sources, both ROM "
          "files, the parameters and the tools are those of its previous run in `synth/<config>/` (`--fresh-synth` "
          "forces it).\n")
        hdr = ("| config | ROM 12 addr/data bits | policy | banks (decoder max n) | ROM bits (coef + cos) | worst rel. epicenter | "
               "goal metric (+1 LSB, n = 1 to pi/2) | "
               + " | ".join(f"n={a}..{b}" for a, b in BANDS) + " | worst abs. lobe | LUT4 | FF | SB_RAM40_4K | SB_CARRY |")
        w(hdr)
        w("|" + "---|" * (hdr.count("|") - 1))
        for h in hw:
            c = cells.get(h["name"], {})
            rel = [fnum(v) for v in h["max_rel_epicenter"]]
            rel_lsb = [fnum(v) for v in h.get("max_rel_epicenter_lsb", [])]
            ab = [fnum(v) for v in h["max_abs_lobe"]]
            cc = " | ".join(str(c.get(k, "n/a")) for k in ("lut4", "ff", "bram", "carry")) if "lut4" in c else \
                " | ".join(["n/a"] * 4)
            if c.get("reused"):
                cc += " (r)"
            kind = "interp" if h.get("cos_interp") else "direct"
            w(f"| {h['name']} | {kind} {h['cos_addr_bits']}/{h['cos_data_bits']} | {h['policy']} | "
              f"{{{','.join(map(str, h['banks']))}}} ({','.join(map(str, h['bank_max_n']))}) | "
              f"{h['coef_rom_bits'] + h['cos_rom_bits']} ({h['coef_rom_bits']} + {h['cos_rom_bits']}) | "
              f"{fmt_err(self.worst(h['n'], rel))} | {fmt_err(self.worst(h['n'], rel_lsb)) if rel_lsb else 'n/a'} | "
              + " | ".join(fmt_err(self.worst(h["n"], rel, a, b)) for a, b in BANDS)
              + f" | {fmt_err(self.worst(h['n'], ab), False)} | {cc} |")
        cpp = [(name, p.get("cycles_per_pixel"), p.get("cycles_per_pixel_long_lines"))
               for name, p in (sim or {}).get("configs", {}).items()]
        if cpp:
            w("\nCycles per pixel of the register interface (`specular_unit`, l + latency + 1 clocks per line), measured "
              "by the Verilator regression (section 5): "
              + "; ".join(f"{n}: {a:.4f} over all lines, {b:.4f} on l = 2047 lines" for n, a, b in cpp)
              + ". The streaming core sustains one pixel per clock whatever l (section 5).\n")
        else:
            w("\nCycles per pixel: not measured in this run (no regression).\n")
        if pnr:
            w("Out-of-context place and route of the default configuration (`scripts/fpga.py`, `make fpga`; "
              "harnesses with registered IO in `rtl/fpga/`): Yosys `synth_ice40` (`-dsp` on the UP5K), "
              "nextpnr-ice40 with a fixed seed and the frequency target shown. LCs: logic cells used after "
              "packing; FFs: Yosys flip-flop count; both include the harness (serial-in input register, output "
              "register and XOR tree). Pixels per second: Fmax at one pixel per clock.\n")
            w("| core | device | fit | LCs | FFs | BRAMs | DSPs | Fmax (MHz) | target (MHz) | pixels per second |")
            w("|---|---|---|---|---|---|---|---|---|---|")
            for r in pnr:
                y, npr = r.get("yosys", {}), r.get("nextpnr", {})
                fit = {True: "yes", False: "no"}.get(r.get("fit"), "error")
                lc = r.get("luts")
                lcs = f"{lc} / {npr['ICESTORM_LC']['available']}" if lc is not None and "ICESTORM_LC" in npr else "-"
                bram = npr.get("ICESTORM_RAM", {}).get("used", y.get("bram")) if r.get("fit") else y.get("bram")
                dsp = npr.get("ICESTORM_DSP", {}).get("used", y.get("dsp")) if r.get("fit") else y.get("dsp")
                fm = r.get("fmax_mhz")
                fms = "-" if fm is None else f"{fm:.2f}" + ("" if r.get("timing_met") else " (missed)")
                w(f"| {r['core']} | {r['part']} | {fit} | {lcs} | {y.get('ff', '-')} | {bram} | {dsp} | {fms} | "
                  f"{r['target_mhz']:g} | {'-' if fm is None else f'{fm * 1e6:.3g}'} |")
            notes = []
            for r in pnr:
                if r.get("fit") is not True:
                    notes.append(f"- {r['core']} on {r['part']}: {r.get('status')}: {r.get('reason', '')}")
                cp = r.get("critical_path")
                if cp:
                    notes.append(f"- {r['core']} on {r['part']}: critical path {cp['total_ns']} ns from net "
                                 f"`{cp['from_net']}` to net `{cp['to_net']}` (through {', '.join(cp.get('through', [])) or '-'})")
            w("\n" + "\n".join(notes) + "\n" if notes else "")
        if hw:
            w("![hardware](hardware.png)\n")
        hw_plane.write(w, getattr(self, "plane_rows", []), getattr(self, "phong", {}), sim, self.args.n_step,
                       bool(getattr(self, "phong_cells", {})))
        self.write_verdict(w, data, sim)

        # --- simulation
        w("## 5. Simulation throughput\n")
        if sim:
            w(f"`sim_regression --random {self.args.random} --json sim.json` (exit code {sim.get('exit_code')}, "
              f"overall {'PASS' if sim.get('ok') else 'FAIL'}):\n")
            w("| configuration | lines | pixels | mismatches vs golden model | cycles/pixel | wall s | RTL (Verilator) s | "
              "RTL share | other (golden model, reference, checks) share | simulated pixels/s | checked pixels/s |")
            w("|---|---|---|---|---|---|---|---|---|---|---|")
            for name, p in sim.get("configs", {}).items():
                tot = p.get("seconds", 0) or 0
                rtl = p.get("sim_seconds", 0) or 0
                gold = p.get("golden_seconds")
                ref = p.get("reference_seconds")
                other = (f"golden {100 * gold / tot:.0f} %, reference {100 * ref / tot:.0f} %"
                         if gold is not None and ref is not None and tot else
                         (f"{100 * (tot - rtl) / tot:.0f} %" if tot else "n/a"))
                w(f"| {name} | {p.get('lines')} | {p.get('pixels')} | {p.get('mismatches')} | "
                  f"{p.get('cycles_per_pixel', 0):.3f} | {tot:.2f} | {rtl:.2f} | "
                  f"{(100 * rtl / tot if tot else 0):.0f} % | {other} | {p.get('simulated_pixels_per_second', 0):.3g} | "
                  f"{p.get('checked_pixels_per_second', 0):.3g} |")
            w("\nDevice error seen by the regression over every simulated pixel (RTL output against C cos^n(psi_i) in "
              "double precision; relative error raw where the reference is >= C/2 -- inside the epicenter, and the "
              "level where section 4's sweep stops for n = 1; absolute lobe error divided by C with one output LSB "
              "allowed), next to the golden-model sweep of section 4 for the same ROM and the regression's budget:\n")
            w("| configuration | regression max rel. epicenter | at n, psi | regression max abs. lobe / C | at n, psi | "
              "sweep worst rel. epicenter | sweep worst abs. lobe | budget rel. / abs. |")
            w("|---|---|---|---|---|---|---|---|")
            sweep = {h["name"]: h for h in data.get("hardware", [])}
            for name, p in sim.get("configs", {}).items():
                rr, ra = p.get("rel_epicenter_raw_ref_ge_half", {}), p.get("abs_lobe_with_lsb", {})
                h = sweep.get(name)
                sw_r = fmt_err(self.worst(h["n"], h["max_rel_epicenter"])) if h else "n/a"
                sw_a = fmt_err(self.worst(h["n"], h["max_abs_lobe"]), False) if h else "n/a"
                b = p.get("budget", {})
                where = lambda e: f"{e.get('n', '?')}, {e.get('psi', float('nan')):.4f}" if e else "n/a"  # noqa: E731
                w(f"| {name} | {fmt_err(rr.get('value'))} | {where(rr)} | {fmt_err(ra.get('value'), False)} | "
                  f"{where(ra)} | {sw_r} | {sw_a} | {fmt_err(b.get('rel_epicenter'))} / {fmt_err(b.get('abs_lobe'), False)} |")
            scenes = sim.get("scenes", {})
            if scenes:
                w("\nScenes (`scenes/*.json`, every covered pixel through the RTL; device error = RTL - C cos^n(psi_i) "
                  "from the loaded registers, interpolation-model error = spherical-interpolation float model - per-pixel "
                  "Phong; images in `scenes/` beside this report):\n")
                w("| scene | configuration | spans | pixels | bit-exact mismatches | max abs device error | max rel. epicenter "
                  "(+1 LSB) | max abs interpolation error | simulated pixels/s |")
                w("|---|---|---|---|---|---|---|---|---|")
                for sname, sc in sorted(scenes.items()):
                    for pname, p in sc.get("by_config", {}).items():
                        w(f"| {sname} | {pname} | {p.get('spans', 'n/a')} | {p.get('pixels')} | {p.get('mismatches')} | "
                          f"{fnum(p.get('max_device_error_abs')):.3g} | {fmt_err(p.get('max_device_rel_epicenter'))} | "
                          f"{fnum(p.get('max_interp_error_abs')):.3g} | {fnum(p.get('simulated_pixels_per_second')):.3g} |")
            colour = sim.get("colour", {})
            if colour:
                flip = sim.get("colour_flip", {})
                w("\nColour (`docs/colour.md`): every scene through the RGB core with its specular colours, composed on "
                  "the host, against the composition around the material's BRDF in double; images "
                  "`scenes/<scene>_colour_{rtl,reference,diff}.png` beside this report:\n")
                w("| scene | mismatches | worst R/G/B (sRGB codes) | mean R/G/B | mean FLIP |")
                w("|---|---|---|---|---|")
                for sname, c in sorted(colour.items()):
                    mf = flip.get(sname, {}).get("mean_flip")
                    w(f"| {sname} | {c.get('mismatches')} | {'/'.join(str(x) for x in c.get('srgb8_max', []))} | "
                      f"{'/'.join(f'{x:.3f}' for x in c.get('srgb8_mean', []))} | "
                      f"{'n/a' if mf is None else f'{mf:.5f}'} |")
            st = sim.get("stream")
            if st:
                w("\nStreaming core (`specular_stream`, default build): random spans with random gaps, random `px_ready_i` "
                  "patterns (always high, toggling, random, long stalls) and resets mid-stream; every pixel checked "
                  "bit-exactly against the golden model's stream view, with its tag, `last` flag, count and order:\n")
                w("| spans | pixels | cycles | resets | mismatches | protocol errors | pixels/clock, l = 0..3, ready high "
                  "| same, mixed l |")
                w("|---|---|---|---|---|---|---|---|")
                w(f"| {st.get('spans')} | {st.get('pixels')} | {st.get('cycles')} | {st.get('resets')} | "
                  f"{st.get('mismatches')} | {st.get('protocol_errors')} | "
                  f"{fnum(st.get('pixels_per_clock_short_spans')):.4f} | {fnum(st.get('pixels_per_clock_mixed_spans')):.4f} |")
            ss = sim.get("scenes_stream", {})
            if ss:
                w("\nClocks per pixel on the scenes' spans: the streaming core with spans back to back and `px_ready_i` "
                  "high, against the register interface (`specular_unit`, l + L + 1 clocks per line, L its latency), both measured:\n")
                w("| scene | spans | pixels | stream clocks/pixel | register interface clocks/pixel | mismatches |")
                w("|---|---|---|---|---|---|")
                for sname, x in sorted(ss.items()):
                    w(f"| {sname} | {x.get('spans')} | {x.get('pixels')} | {fnum(x.get('stream_clocks_per_pixel')):.4f} | "
                      f"{fnum(x.get('register_clocks_per_pixel')):.4f} | {x.get('mismatches')} |")
            sc_u, sc_s = cells.get("default", {}), cells.get("default-stream", {})
            if "lut4" in sc_u and "lut4" in sc_s:
                w("\nCells (Yosys `synth_ice40`, default configuration): "
                  f"`specular_unit` {sc_u['lut4']} LUT4, {sc_u['ff']} FF, {sc_u['bram']} SB_RAM40_4K; "
                  f"`specular_stream` {sc_s['lut4']} LUT4, {sc_s['ff']} FF, {sc_s['bram']} SB_RAM40_4K "
                  "(the unit is the stream plus its host registers and start latch, with a 1-bit tag where the stream "
                  "carries a 16-bit tag through its stages).\n")
            if not any("golden_seconds" in p for p in sim.get("configs", {}).values()):
                w("\nThe regression's JSON reports the time inside the Verilator model (`sim_seconds`) and the total; the "
                  "golden model and the floating-point reference are not timed separately, so their shares are given "
                  "together.\n")
        else:
            w("No simulation measurement in this run (see the list at the top).\n")

        # --- hard cases
        w("## 6. Numerical hard cases of the scanline setup (docs/scanline_setup.md)\n")
        w("Each through `scanline_setup`, then the golden model (minimax ROM) on the quantized registers; 'device err' is "
          "the largest |device - C cos^n(psi_i)| over the line.\n")
        w("| case | n | l | status | A | gamma | C | psi0 | dpsi | finite | device peak | device err | note |")
        w("|---|---|---|---|---|---|---|---|---|---|---|---|---|")

        def g(v):
            v = fnum(v)
            return f"{v:.6g}"
        for c in data.get("hardcases", []):
            w(f"| {c['case'].replace('|', '&#124;')} | {c['n']:g} | {c['l']} | {c['status']} | {g(c['A'])} | {g(c['gamma'])} | {g(c['C'])} | "
              f"{g(c['psi0'])} | {g(c['dpsi'])} | {'yes' if c['finite'] else 'NO'} | {c['device_peak']:.5f} | "
              f"{c['device_max_abs_error']:.2e} | {c['note'].replace('|', '&#124;')} |")
        w("")

        # --- system
        self.write_system(w, sb, pnr)

        # --- run
        w("## 8. This run\n")
        for k, v in self.timings.items():
            w(f"- {k}: {v:.1f} s")
        for k, v in data.get("seconds", {}).items():
            w(f"- report_data section {k}: {v:.2f} s")
        w("")
        with open(os.path.join(self.out, "report.md.tmp"), "w") as f:
            f.write("\n".join(md) + "\n")
        os.replace(os.path.join(self.out, "report.md.tmp"), os.path.join(self.out, "report.md"))

    def write_system(self, w, sb, pnr):
        w("## 7. System: the speed per scene, setup included\n")
        scenes = sb.get("scenes", [])
        if not scenes:
            w("Not measured in this run (see the list at the top).\n")
            return
        w("`scene_bench` (`model/bench/scene_bench.cpp`, `docs/system.md`) rasterizes each scene once "
          "(not timed), then times shading **every span of every light** by each method, the per-span work included: "
          "`device` = the batched scanline setup (`host::setup_batch`, vectors to register codes) plus the device method "
          "from the registers (`device_span`'s float arithmetic, vectorized across spans); `phong_sleef` / `phong_scalar` = "
          "per-pixel Phong (lerp N, normalize, N.H, pow with SLEEF powf8 / libm powf; H per pixel from the surface point "
          "when the light is a point light or the camera is perspective, constant otherwise), its per-span preparation "
          "included; `pow_cos` = the scalar setup (`scanline_setup` + `load_registers`) plus scalar double "
          f"`std::pow(cos psi, n)`. ns per shaded pixel, {sb.get('timer', '')}; x phong_sleef = phong_sleef's time / "
          f"the method's (above 1: faster). SIMD: {sb.get('simd', '?')}.\n")
        w("| scene | spans | pixels | mean span (px) | H | device ns/px | phong_sleef ns/px | phong_scalar ns/px | "
          "pow_cos ns/px | device x phong_sleef | phong_scalar x phong_sleef | pow_cos x phong_sleef |")
        w("|---|---|---|---|---|---|---|---|---|---|---|---|")
        for x in scenes:
            t, r = x["ns_per_pixel"], x["speedup_vs_phong_sleef"]
            h = ", ".join(sorted(set(x.get("lights", []))))
            w(f"| {x['scene']} | {x['spans']} | {x['pixels']} | {x['mean_span']:.2f} | {h} | {t['device']:.2f} | "
              f"{t['phong_sleef']:.2f} | {t['phong_scalar']:.2f} | {t['pow_cos']:.2f} | {r['device']:.2f} | "
              f"{r['phong_scalar']:.2f} | {r['pow_cos']:.2f} |")
        w("\nThe device method's two parts, each timed alone in the same rounds: the setup per span (and per pixel of "
          "the scene), the shading per pixel (from fixed registers).\n")
        w("| scene | setup ns/span | setup ns/px | shading ns/px | setup share |")
        w("|---|---|---|---|---|")
        for x in scenes:
            sp, sh = x["device_setup_ns_per_pixel"], x["device_shade_ns_per_pixel"]
            w(f"| {x['scene']} | {x['device_setup_ns_per_span']:.2f} | {sp:.2f} | {sh:.2f} | "
              f"{100 * sp / (sp + sh) if sp + sh > 0 else 0:.0f} % |")
        w("\nAt one instruction set: `setup_batch`'s automatic path takes AVX-512 where the CPU has it, while `device` "
          "and `phong_sleef` above shade with AVX2. AVX2 throughout: the setup held to AVX2. AVX-512 throughout: both "
          "shaders built for AVX-512 as well (Phong with SLEEF `Sleef_powf16_u10avx512f`). n/a: the CPU lacks it.\n")
        w("| scene | AVX2: device ns/px | AVX2: phong_sleef ns/px | AVX2: device x phong_sleef | AVX-512: device ns/px | "
          "AVX-512: phong_sleef ns/px | AVX-512: device x phong_sleef |")
        w("|---|---|---|---|---|---|---|")
        for x in scenes:
            cells = []
            for isa in ("avx2", "avx512"):
                m = x.get("isa_matched", {}).get(isa)
                cells += [f"{m['device']:.2f}", f"{m['phong_sleef']:.2f}", f"{m['speedup']:.2f}"] if m else ["n/a"] * 3
            w(f"| {x['scene']} | " + " | ".join(cells) + " |")
        goals = self.system_goals(sb)
        if goals:
            w("\nGoals, device (setup included) >= 1.0 x phong_sleef on every scene:\n")
            for _, lab, r, b_, lb, lg in goals:
                w(f"- {lab}: " + self.goal_text(r, b_, lb, lg) + ".")
            w("")
        be = sb.get("break_even", [])
        if be:
            bl = sb.get("break_even_l")
            w("**Break-even span length** (synthetic spans `host::random_spans_of_length`, He = H1: a directional light "
              f"and an orthographic camera, so Phong's H is constant; {be[0].get('spans', 'the same number of')} spans per "
              f"length, lengths l = {be[0]['l']}..{be[-1]['l']}): "
              + (f"the device method (setup included) is at or below per-pixel SLEEF Phong from **l = {bl} "
                 f"({bl + 1} pixels per span)** on" if bl is not None else "the device method is slower at every length")
              + f"; at l = {be[0]['l']}: device {be[0]['device']:.2f} ns/px, phong_sleef {be[0]['phong_sleef']:.2f}; at "
              f"l = {be[-1]['l']}: device {be[-1]['device']:.2f}, phong_sleef {be[-1]['phong_sleef']:.2f}."
              + "".join(f" {lab}: " + (f"from l = {v} ({v + 1} pixels per span)." if v is not None else "never.")
                        for k, lab in (("avx2", "AVX2 throughout"), ("avx512", "AVX-512 throughout"))
                        for v in [sb.get("break_even_l_isa", {}).get(k, "absent")] if v != "absent") + "\n")
            w("![break-even](break_even.png)\n")
        w("**Feeding the core.** With the device, the host only does the setup. The streaming core takes one pixel per "
          f"clock, so at the HX8K Fmax of `make fpga` ({sb.get('fmax_mhz', 0):.2f} MHz, `specular_stream`; read from "
          f"`{os.path.relpath(sb.get('fmax_source', '?').split(':')[0], ROOT)}`) it consumes Fmax / (pixels per span) "
          "spans per second; the batched setup's rate is measured alone on one host core of this machine.\n")
        pr = [p for p in pnr if p.get("core") == "specular_stream" and str(p.get("part", "")).startswith("HX8K")
              and p.get("fmax_mhz")]
        if pr and abs(pr[0]["fmax_mhz"] - sb.get("fmax_mhz", 0)) > 0.005:
            w(f"(This run's place and route, section 4, gave {pr[0]['fmax_mhz']:.2f} MHz for the same core: "
              "`docs/fpga_figures.json` is out of date.)\n")
        w("| scene | mean span (px) | setup M spans/s (one host core) | core M spans/s at Fmax | host cores to feed one core |")
        w("|---|---|---|---|---|")
        for x in scenes:
            w(f"| {x['scene']} | {x['mean_span']:.2f} | {x['setup_mspans_per_s']:.1f} | "
              f"{x['core_mspans_per_s_at_fmax']:.1f} | {x['host_cores_to_feed']:.2f} |")
        w("")

    def main(self):
        t0 = time.time()
        smoke = self.args.smoke  # tests/report/check_make_report.py: tables from report_data only
        speed = self.bench() if not smoke else {}
        sb = self.scene_bench()
        data = self.model_data()
        hw_cfgs = data.get("hardware", [])
        # The streaming core of the default configuration, next to specular_unit's cells.
        stream_cfgs = [dict(h, name=h["name"] + "-stream", top="specular_stream")
                       for h in hw_cfgs if h["name"] == "default"]
        cells = self.synth(hw_cfgs + stream_cfgs) if not smoke else {}
        pnr = self.pnr() if not smoke else ()
        self.hardware_plane(data, cells)
        sim = self.sim() if not (self.args.no_sim or smoke) else {}
        rows = self.error_rows(data)
        if rows and speed:
            self.plot_plane(rows, speed)
        if rows:
            self.plot_err_vs_n(rows)
        if data.get("curves"):
            self.plot_err_vs_angle(data["curves"])
        if data.get("albedo"):
            self.plot_albedo(data["albedo"])
        if data.get("hardware"):
            self.plot_hardware(data["hardware"], cells)
        self.timings["whole report"] = time.time() - t0
        self.write(speed, data, cells, sim, pnr, sb)
        print(f"wrote {os.path.join(self.out, 'report.md')} ({time.time() - t0:.0f} s)")
        return 0


def parse_args(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default="build", help="CMake build directory (binaries in BUILD/bin)")
    ap.add_argument("--out", default=None, help="output directory (default BUILD/report)")
    ap.add_argument("--random", type=int, default=100000, help="random scanlines per policy for sim_regression (0..1000000)")
    ap.add_argument("--jobs", type=int, default=2, help="parallel scripts/fpga.py runs of the build configurations (1..16)")
    ap.add_argument("--n-step", type=int, default=1, help="sample n = 1, 1+S, ..., 1000 for the error sweeps (1..999)")
    ap.add_argument("--fresh-synth", action="store_true",
                    help="re-run Yosys even when RTL, ROMs and script are unchanged since the last run")
    ap.add_argument("--no-sim", action="store_true", help="skip the Verilator regression")
    ap.add_argument("--scene-reps", type=int, default=5, help="scene_bench rounds per scene (1..100; the median is reported)")
    ap.add_argument("--smoke", action="store_true",
                    help="fast check run: report_data and a one-scene scene_bench only (no evaluator benchmark, synthesis, "
                         "place and route or simulation)")
    args = ap.parse_args(argv)
    for name, lo, hi in (("--random", 0, 1000000), ("--jobs", 1, 16), ("--n-step", 1, 999), ("--scene-reps", 1, 100)):
        v = getattr(args, name[2:].replace("-", "_"))
        if not lo <= v <= hi:
            print(f"make_report.py: {name} must be in {lo}..{hi} (got {v})", file=sys.stderr)
            sys.exit(2)
    if not os.path.isdir(args.build):
        print(f"make_report.py: --build '{args.build}' is not a directory (run `make build` first)", file=sys.stderr)
        sys.exit(2)
    if args.out is None:
        args.out = os.path.join(args.build, "report")
    return args


if __name__ == "__main__":
    sys.exit(Report(parse_args(sys.argv[1:])).main())
