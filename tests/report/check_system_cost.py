#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""The report's comparison of the device system per SetupII with the Phong cores (section 4b,
scripts/hw_plane.py: ecp5_runs, setup_ii_sim, write_system_cost).

1. On synthetic inputs whose ratios are worked out by hand below: the keys of the synthesis
   entries, the table cells and the conclusion (which scene, which SetupII, cheaper or not).
2. On the committed docs/fpga_figures.json and docs/measured/sim_setup_ii.json: every SetupII
   the JSON has a system count for is read, and every ratio in the table equals
   system LUT4 / pixels per clock / phong n1000's LUT4, recomputed here from the JSON.
Exit 0 when all agree, 1 otherwise.
"""
import json
import os
import re
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import hw_plane  # noqa: E402


def entry(core, lut4, mult, **kw):
    e = {"core": core, "part": "ECP5", "rtl": "0000000", "lut4": lut4, "ccu2c": 1, "ffs": 1, "mult18x18d": mult,
         "dp16kd": 0}
    e.update(kw)
    return e


def render(runs, ii_sim):
    out = []
    hw_plane.write_system_cost(out.append, runs, ii_sim)
    return "\n".join(out)


def synthetic(fail):
    # System 1000 LUT4 at SetupII 1, 400 at SetupII 4; Phong n1000 200 LUT4.
    runs_json = {"synthesis_runs": [
        entry("specular_system", 1000, 50),
        entry("specular_system", 400, 20, setup_ii=4),
        entry("phong_stream", 200, 0, config="n1000"),
        entry("phong_stream", 150, 0, config="n64"),
        entry("specular_setup", 900, 50),                                 # not a system: ignored
        dict(entry("specular_system", 1, 1, setup_ii=2), part="UP5K"),  # not ECP5: ignored
    ]}
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "f.json")
        with open(path, "w") as f:
            json.dump(runs_json, f)
        runs = hw_plane.ecp5_runs(path)
    want_keys = {"specular_system", "specular_system SetupII=4", "phong n1000", "phong n64"}
    if set(runs) != want_keys:
        fail(f"ecp5_runs keys {sorted(runs)}, expected {sorted(want_keys)}")
    # Scene a: 1 px/clock at SetupII 1, 0.25 at 4 -> 1000/1/200 = 5.00, 400/0.25/200 = 8.00.
    # Scene b: 1 and 1 -> 5.00 and 2.00.
    ii_sim = {1: {"a": {"px_per_clock_steady": 1.0}, "b": {"px_per_clock_steady": 1.0}, "l0": {}},
              4: {"a": {"px_per_clock_steady": 0.25}, "b": {"px_per_clock_steady": 1.0}}}
    text = render(runs, ii_sim)
    for row in ("| a | 1.0000 | 0.2500 | 5.00 | 8.00 |", "| b | 1.0000 | 1.0000 | 5.00 | 2.00 |"):
        if row not in text:
            fail(f"synthetic: row {row!r} missing:\n{text}")
    if "| l0 |" in text:
        fail("synthetic: the one-pixel-span run l0 is not a scene and must not be a row")
    if "costs 2.00 x (b, SetupII=4) to 5.00 x (a, SetupII=1)" not in text or "cheaper per pixel on every scene" not in text:
        fail(f"synthetic: conclusion wrong:\n{text.splitlines()[-1]}")
    # A cheaper system (100 LUT4 at SetupII 4): scene b wins at 100/1/200 = 0.50.
    runs["specular_system SetupII=4"] = entry("specular_system", 100, 20, setup_ii=4)
    text = render(runs, ii_sim)
    if "cheaper per pixel on b only" not in text or "0.50 x (b, SetupII=4)" not in text:
        fail(f"synthetic, a winning scene: conclusion wrong:\n{text.splitlines()[-1]}")
    # Without the system stage per SetupII: the LUT4 ratio at SetupII 1 only (1000 / 200).
    if "at least 5.0 x the LUT4" not in render(runs, {}):
        fail("synthetic, no sim: missing the SetupII 1 LUT4 ratio")


def committed(fail):
    runs, ii_sim = hw_plane.ecp5_runs(), hw_plane.setup_ii_sim()
    systems = {hw_plane.setup_ii_of(k): v for k, v in runs.items() if k.startswith("specular_system")}
    if 1 not in systems or not ii_sim:
        fail("docs/fpga_figures.json or docs/measured/sim_setup_ii.json lacks the system's figures")
        return
    text = render(runs, ii_sim)
    ks = sorted(systems)
    ref = runs["phong n1000"]["lut4"]
    rows = 0
    for line in text.splitlines():
        m = re.match(r"\| (\w+) \| (.*) \|$", line)
        if not m or m.group(1) not in ii_sim.get(1, {}):
            continue
        cells = m.group(2).split(" | ")
        ratios = cells[len(ks):]
        for k, r in zip(ks, ratios):
            ppc = float(ii_sim[k][m.group(1)]["px_per_clock_steady"])
            want = f"{systems[k]['lut4'] / ppc / ref:.2f}"
            if r != want:
                fail(f"committed: {m.group(1)} SetupII={k}: {r}, recomputed {want}")
        rows += 1
    if rows == 0:
        fail(f"committed: no scene rows in:\n{text}")
    print(f"check_system_cost: {rows} scenes x {len(ks)} SetupII checked against the committed JSON")


def main():
    errors = []
    synthetic(errors.append)
    committed(errors.append)
    for e in errors:
        print("FAIL " + e)
    print("check_system_cost: " + ("FAIL" if errors else "OK"))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
