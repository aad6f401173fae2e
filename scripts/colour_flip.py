#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The mean FLIP of every colour image of a sim_regression run (docs/colour.md#flip).

    scripts/colour_flip.py --sim-json docs/measured/sim.json --json docs/measured/colour_flip.json

Reads the run's "colour" section (sim/colour_stage.hpp: per scene the RTL's image and the
reference, written under the run's images folder), runs scripts/flip_metric.py on each pair
(reference first) and writes {"provenance": ..., "scenes": {name: {"mean_flip", "ppd", "width",
"height"}}}, the file written whole or not at all. Exit 0 done; 2 bad input (a missing section or
image, named); 1 a metric run failed.
"""
import argparse
import datetime
import json
import os
import platform
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ME = "scripts/colour_flip.py"


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sim-json", required=True, help="sim_regression --json output with a colour section")
    ap.add_argument("--json", required=True, help="the file to write")
    a = ap.parse_args(argv)
    try:
        with open(a.sim_json) as f:
            colour = json.load(f).get("colour")
    except (OSError, ValueError) as e:
        print(f"{ME}: --sim-json {a.sim_json}: cannot read it as JSON ({e})", file=sys.stderr)
        return 2
    if not colour:
        print(f"{ME}: --sim-json {a.sim_json}: no \"colour\" section (run sim_regression with scenes and "
              f"--images-dir)", file=sys.stderr)
        return 2
    out = {}
    for name, c in sorted(colour.items()):
        imgs = c.get("images") or []
        rtl = next((p for p in imgs if p.endswith("_colour_rtl.png")), None)
        ref = next((p for p in imgs if p.endswith("_colour_reference.png")), None)
        if not rtl or not ref:
            print(f"{ME}: scene {name}: the run wrote no colour images (give sim_regression --images-dir)",
                  file=sys.stderr)
            return 2
        p = subprocess.run([sys.executable, os.path.join(HERE, "flip_metric.py"), ref, rtl], capture_output=True,
                           text=True)
        if p.returncode != 0:
            sys.stderr.write(p.stderr)
            return p.returncode
        r = json.loads(p.stdout)
        out[name] = {"mean_flip": r["mean_flip"], "ppd": r["ppd"], "width": r["width"], "height": r["height"]}
        print(f"{name}: mean FLIP {r['mean_flip']:.5f}")
    head = subprocess.run(["git", "-C", os.path.dirname(HERE), "rev-parse", "--short", "HEAD"], capture_output=True,
                          text=True).stdout.strip()
    doc = {"provenance": {"commit": head or "unknown", "date": datetime.date.today().isoformat(),
                          "machine": f"{platform.machine()}, {os.cpu_count()} CPUs",
                          "command": f"{ME} --sim-json {a.sim_json} --json {a.json} (flip-evaluator "
                                     f"{r.get('flip_evaluator')}; reference first, the RTL's image second)"},
           "scenes": out}
    tmp = a.json + ".tmp"
    with open(tmp, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")
    os.replace(tmp, a.json)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
