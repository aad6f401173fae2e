#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The device's configurations per error budget (docs/device.md#configurations-per-budget) as ROM
files and scripts/fpga.py parameters, read from docs/measured/device_search.json (the cheapest
configuration per budget and n range that build/bin/device_search found).

    scripts/budget_roms.py --romgen build/bin/romgen            write roms/budget/ (make roms runs it)
    scripts/budget_roms.py --romgen build/bin/romgen --check    regenerate into a temporary folder and
                                                                compare with roms/budget/ (ctest
                                                                budget_roms_up_to_date)
    scripts/budget_roms.py --list                               the configurations: label, budget, n ranges
    scripts/budget_roms.py --fpga-args LABEL                    scripts/fpga.py's --param ... --label LABEL
                                                                for that configuration, one a line

One configuration per distinct search result of a budget (every field of its "best": bank set,
decoder table, ROM 9 and ROM 12 widths, PsiMulFrac), labelled device_<budget>_n<N> with N the
largest n range it was found for (it serves the smaller ones too). Its ROM files (romgen with the
result's widths, bank set and decoder table; policy minimax, the search's) go to
roms/budget/<budget>/, or roms/budget/<label>/ when the configurations of one budget differ in
their ROM contents. roms/budget/budget_configs.json lists each configuration: its budget, n
ranges, ROM bits, folder and fpga.py parameters (rtl/core/specular_params.svh names them), so
that an FPGA figure's "config" (fpga.py --label, docs/fpga_figures.json) maps back to the budget
it meets. Exit 0 when done or up to date, 1 when stale or romgen fails, 2 on bad arguments.
"""
import argparse
import filecmp
import json
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SEARCH = "docs/measured/device_search.json"
OUT = "roms/budget"
MANIFEST = "budget_configs.json"
N_BITS = 10  # NBits, the device's default (rtl/core/specular_params.svh): BankMaxN's field width
# The fields of a search result that decide the ROM files' contents (roms/README.md#contents);
# psi_mul_frac and cos_frac_bits are datapath widths only.
ROM_FIELDS = ("banks", "bank_max_n", "coef_bits", "coef_frac", "cos_addr_bits", "cos_data_bits", "cos_delta_bits")


BUILD_CONFIGS = "roms/build_configs.cmake"


def build_blend_configs(root):
    """{name: {param: value}} of the blend builds of roms/build_configs.cmake (romgen --all writes
    it from build_configs() in model/device/rom_image.cpp): every parameter (<ID>_ALL_ARGS)."""
    import re
    with open(os.path.join(root, BUILD_CONFIGS)) as f:
        text = f.read()
    out = {}
    for m in re.finditer(r'^set\(SPECULAR_BUILD_CONFIG_(\w+)_ALL_ARGS(.*)\)$', text, re.M):
        args = dict(re.findall(r'"-G(\w+)=(.*?)"(?= |$)', m.group(2).replace('\\"', "")))
        if args.get("Blend") == "1'b1":
            bits = re.search(rf'^set\(SPECULAR_BUILD_CONFIG_{m.group(1)}_ROM_BITS (\d+)\)$', text, re.M)
            if not bits:
                raise KeyError(f"{BUILD_CONFIGS} has no ROM_BITS of {m.group(1)}: run `make roms`")
            out[m.group(1)] = dict(args, rom_bits=int(bits.group(1)))
    return out


def blend_configurations(root, runs):
    """The blend configurations (B2, B4: no single bank meets them, docs/display_exact.md): one per
    distinct "best_blend" that a build of roms/build_configs.cmake implements, its ROM files that
    build's (romgen --all); a best_blend no build implements is reported, not emitted."""
    builds = build_blend_configs(root)
    out = []
    for r in runs:
        b = r.get("best_blend")
        if r.get("best") or not b:
            continue
        key = tuple(json.dumps(b.get(k)) for k in ROM_FIELDS + ("psi_mul_frac", "cos_frac_bits", "weight_bits"))
        same = next((c for c in out if c["budget"] == r["budget"] and c["key"] == key), None)
        if same:
            same["n_max"].append(r["n_max"])
            continue
        nb = len(b["banks"])
        packed = sum(v << (N_BITS * j) for j, v in enumerate(b["bank_max_n"]))
        want = {"CoefBits": str(b["coef_bits"]), "CoefFrac": str(b["coef_frac"]), "PsiMulFrac": str(b["psi_mul_frac"]),
                "CosAddrBits": str(b["cos_addr_bits"]), "CosDataBits": str(b["cos_data_bits"]),
                "CosDeltaBits": str(b["cos_delta_bits"]), "CosFracBits": str(b["cos_frac_bits"]),
                "NumBanks": str(nb), "BankMaxN": f"{N_BITS * nb}'h{packed:x}", "WeightBits": str(b["weight_bits"])}
        # The build may carry more ROM 12 data bits (and the step field they need) than the search
        # found: its dense sweep (device_search --sweep) decides them (docs/display_exact.md#search).
        wider = ("CosDataBits", "CosDeltaBits")

        def implements(a):
            return all(a.get(k) == v for k, v in want.items() if k not in wider) and \
                all(k in a and int(a[k]) >= int(want[k]) for k in wider)
        name = next((n for n, a in builds.items() if implements(a)), None)
        if name is None or any(b.get("bank_shift") or []):
            print(f"budget_roms.py: note: the blend of budget {r['budget']} at n <= {r['n_max']} has no build in "
                  f"{BUILD_CONFIGS} (model/device/rom_image.cpp build_configs)", file=sys.stderr)
            continue
        a = builds[name]
        params = [f"{k}={a[k]}" for k in ("CoefBits", "CoefFrac", "PsiMulFrac")] + ["CosInterp=1"] + \
                 [f"{k}={a[k]}" for k in ("CosAddrBits", "CosDataBits", "CosDeltaBits", "CosFracBits", "NumBanks",
                                           "BankMaxN")] + [f"Blend={a['Blend']}", f"WeightBits={a['WeightBits']}",
                                                           f"CoefRomFile={a['CoefRomFile']}",
                                                           f"CosRomFile={a['CosRomFile']}"]
        out.append({"budget": r["budget"], "n_max": [r["n_max"]], "best": b, "key": key, "policy": "blend", "build": name,
                    "params": params, "rom_bits": a["rom_bits"], "dir": os.path.dirname(a["CoefRomFile"])})
    for c in out:
        c["n_max"].sort()
        c["label"] = f"device_{c['budget']}_n{c['n_max'][-1]}"
    return out


def configurations(root):
    """[{label, budget, n_max: [...], best, policy}] from the search results, in file order."""
    with open(os.path.join(root, SEARCH)) as f:
        d = json.load(f)
    out = []
    for r in d["runs"]:
        best = r.get("best")
        if not best:
            continue  # no single-bank set meets the budget (B2, B4): blend_configurations
        same = next((c for c in out if c["budget"] == r["budget"] and c["best"] == best
                     and c["policy"] == r["policy"]), None)
        if same:
            same["n_max"].append(r["n_max"])
        else:
            out.append({"budget": r["budget"], "n_max": [r["n_max"]], "best": best, "policy": r["policy"]})
    for c in out:
        c["n_max"].sort()
        c["label"] = f"device_{c['budget']}_n{c['n_max'][-1]}"
        rom_key = tuple(json.dumps(c["best"][k]) for k in ROM_FIELDS) + (c["policy"],)
        siblings = {tuple(json.dumps(x["best"][k]) for k in ROM_FIELDS) + (x["policy"],)
                    for x in out if x["budget"] == c["budget"]}
        c["rom_key"] = rom_key
        c["dir"] = f"{OUT}/{c['budget']}" if len(siblings) == 1 else f"{OUT}/{c['label']}"
    return out


def romgen_args(c):
    b = c["best"]
    return ["--policy", c["policy"], "--coef-bits", str(b["coef_bits"]), "--coef-frac", str(b["coef_frac"]),
            "--cos-addr-bits", str(b["cos_addr_bits"]), "--cos-data-bits", str(b["cos_data_bits"]),
            "--cos-delta-bits", str(b["cos_delta_bits"]), "--cos-frac-bits", str(b["cos_frac_bits"]),
            "--interp", "--banks", ",".join(map(str, b["banks"])),
            "--bank-max-n", ",".join(map(str, b["bank_max_n"]))]


def fpga_params(c, files):
    """The core parameters of the configuration (rtl/core/specular_params.svh), in the form of
    scripts/fpga.py --param; BankMaxN packs NBits per bank, bank 0 in the least significant bits."""
    b = c["best"]
    nb = len(b["banks"])
    packed = sum(v << (N_BITS * j) for j, v in enumerate(b["bank_max_n"]))
    coef = next(f for f in files if os.path.basename(f).startswith("coef_"))
    cos = next(f for f in files if os.path.basename(f).startswith("cos_k_"))
    return [f"CoefBits={b['coef_bits']}", f"CoefFrac={b['coef_frac']}", f"PsiMulFrac={b['psi_mul_frac']}",
            "CosInterp=1", f"CosAddrBits={b['cos_addr_bits']}", f"CosDataBits={b['cos_data_bits']}",
            f"CosDeltaBits={b['cos_delta_bits']}", f"CosFracBits={b['cos_frac_bits']}", f"NumBanks={nb}",
            f"BankMaxN={N_BITS * nb}'h{packed:x}", f"CoefRomFile={coef}", f"CosRomFile={cos}"]


def generate(root, romgen, dest):
    """Write every configuration's ROM files under dest (laid out as roms/budget/) and the
    manifest; returns the manifest."""
    manifest = {"about": "Generated by scripts/budget_roms.py from " + SEARCH + "; do not edit. The device's "
                         "configuration per error budget (docs/device.md#configurations-per-budget): the n ranges it "
                         "was found for, its ROM bits and the scripts/fpga.py --param list (fpga.py --label LABEL "
                         "makes its docs/fpga_figures.json entries' \"config\").",
                "configurations": []}
    written = {}
    for c in configurations(root):
        sub = os.path.relpath(c["dir"], OUT)
        if c["dir"] not in written:
            out_dir = os.path.join(dest, sub)
            os.makedirs(out_dir, exist_ok=True)
            before = set(os.listdir(out_dir))
            p = subprocess.run([romgen, "--out-dir", out_dir, "--quiet"] + romgen_args(c),
                               capture_output=True, text=True)
            if p.returncode != 0:
                raise RuntimeError(f"romgen for {c['label']} failed (exit {p.returncode}): {p.stderr.strip()}")
            written[c["dir"]] = sorted(set(os.listdir(out_dir)) - before)
        files = [f"{c['dir']}/{n}" for n in written[c["dir"]]]
        manifest["configurations"].append({
            "label": c["label"], "budget": c["budget"], "n_max": c["n_max"], "policy": c["policy"],
            "rom_bits": c["best"]["rom_bits"], "dir": c["dir"], "fpga_params": fpga_params(c, files)})
    with open(os.path.join(root, SEARCH)) as f:
        runs = json.load(f)["runs"]
    for c in blend_configurations(root, runs):
        manifest["configurations"].append({
            "label": c["label"], "budget": c["budget"], "n_max": c["n_max"], "policy": c["policy"],
            "rom_bits": c["rom_bits"], "dir": c["dir"], "build": c["build"], "fpga_params": c["params"]})
    with open(os.path.join(dest, MANIFEST), "w") as f:
        json.dump(manifest, f, indent=1)
        f.write("\n")
    return manifest


def tree(d):
    out = set()
    for base, _, names in os.walk(d):
        out |= {os.path.relpath(os.path.join(base, n), d) for n in names}
    return out


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--romgen", help="the romgen binary (build/bin/romgen)")
    ap.add_argument("--check", action="store_true", help="compare roms/budget/ with a fresh generation")
    ap.add_argument("--list", action="store_true", help="print the configurations")
    ap.add_argument("--fpga-args", metavar="LABEL", help="print fpga.py's --param ... --label LABEL")
    ap.add_argument("--root", default=ROOT)
    args = ap.parse_args(argv)
    root = args.root
    if args.list or args.fpga_args:
        with open(os.path.join(root, OUT, MANIFEST)) as f:
            m = json.load(f)["configurations"]
        if args.list:
            for c in m:
                print(f"{c['label']}: budget {c['budget']}, n <= {', '.join(map(str, c['n_max']))}; "
                      f"{c['rom_bits']} ROM bits; {c['dir']}/")
            return 0
        c = next((c for c in m if c["label"] == args.fpga_args), None)
        if c is None:
            print(f"budget_roms.py: --fpga-args must be one of {', '.join(c['label'] for c in m)} "
                  f"(got '{args.fpga_args}')", file=sys.stderr)
            return 2
        for p in c["fpga_params"]:
            print(f"--param\n{p}")
        print(f"--label\n{c['label']}")
        return 0
    if not args.romgen:
        print("budget_roms.py: --romgen BIN is needed to write or check the ROM files", file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory() as tmp:
        try:
            generate(root, args.romgen, tmp)
        except (RuntimeError, OSError, KeyError, ValueError) as e:
            print(f"budget_roms.py: {e}", file=sys.stderr)
            return 1
        dest = os.path.join(root, OUT)
        if args.check:
            want, have = tree(tmp), tree(dest) if os.path.isdir(dest) else set()
            stale = sorted(f for f in want & have if not filecmp.cmp(os.path.join(tmp, f), os.path.join(dest, f),
                                                                     shallow=False))
            missing, extra = sorted(want - have), sorted(have - want)
            for what, fs in (("differs from the generated file", stale), ("is missing", missing),
                             ("is not generated from " + SEARCH, extra)):
                for f in fs:
                    print(f"budget_roms.py: {OUT}/{f} {what}")
            if stale or missing or extra:
                print(f"budget_roms.py: {OUT}/ is out of date; run `make roms` and commit", file=sys.stderr)
                return 1
            print(f"budget_roms.py: {OUT}/ is up to date ({len(want)} files)")
            return 0
        shutil.rmtree(dest, ignore_errors=True)
        shutil.copytree(tmp, dest)
        print(f"budget_roms.py: wrote {OUT}/ ({len(tree(dest))} files)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
