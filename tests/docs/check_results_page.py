#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Self-test of scripts/results_page.py (the ctest docs_results_page_selftest): on a copy of the
pages and the JSON it reads, an untouched copy passes --check; a tampered figure in a generated
region, a tampered JSON value, a region without its END line, an unknown region and a missing
region each fail it with a message naming the file and the region; --write puts the copy back as it
was. With --specular BIN, a JSON figure of the `specular` CLI that the CLI does not print fails,
and --write --specular records the CLI's value again.

usage: check_results_page.py ROOT [--specular BIN]
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

SCRIPT = "scripts/results_page.py"
COPIED = ["scripts/verdict.py", "scripts/hw_plane.py", "scripts/fpga_parts.py", "roms/phong/phong_configs.cmake",
          "docs/results.md"]


def main(argv):
    if not argv or argv[0].startswith("-"):
        print(__doc__, file=sys.stderr)
        return 2
    root = os.path.abspath(argv[0])
    specular = argv[argv.index("--specular") + 1] if "--specular" in argv else None
    sys.path.insert(0, os.path.join(root, "scripts"))
    import results_page  # scripts/results_page.py: its SOURCES and REGIONS

    files = sorted(set(COPIED) | set(results_page.SOURCES.values()) | {f for f, _ in results_page.REGIONS.values()})
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        def fresh():
            dst = os.path.join(tmp, "repo")
            shutil.rmtree(dst, ignore_errors=True)
            for rel in files:
                os.makedirs(os.path.dirname(os.path.join(dst, rel)), exist_ok=True)
                shutil.copy(os.path.join(root, rel), os.path.join(dst, rel))
            return dst

        def run(dst, *args):
            r = subprocess.run([sys.executable, os.path.join(root, SCRIPT), "--root", dst, *args],
                               capture_output=True, text=True)
            return r.returncode, r.stdout + r.stderr

        def edit(dst, rel, old, new):
            p = os.path.join(dst, rel)
            with open(p) as f:
                text = f.read()
            if old not in text:
                failures.append(f"'{old}' is not in {rel}: the self-test needs updating")
            with open(p, "w") as f:
                f.write(text.replace(old, new, 1))

        def read(dst, rel):
            with open(os.path.join(dst, rel)) as f:
                return f.read()

        dst = fresh()
        rc, out = run(dst, "--check")
        if rc != 0:
            failures.append(f"the untouched copy fails --check: {out.strip()[:400]}")
        readme = read(dst, "README.md")
        sim = json.loads(read(dst, "docs/measured/sim.json"))
        fmax = f"{results_page.pnr({'fpga': json.loads(read(dst, 'docs/fpga_figures.json'))}, 'specular_stream', 'HX8K')['fmax_mhz']:.2f}"
        begin = "<!-- BEGIN generated: results (scripts/results_page.py) -->"
        cases = [
            # (what, file, old text, new text, what every message must contain)
            ("a figure of the README's region tampered", "README.md", f"{fmax} MHz", "99.99 MHz",
             "README.md:", "'results'"),
            ("a JSON value tampered", "docs/measured/sim.json",
             f'"pixels_per_clock_short_spans_steady": {json.dumps(sim["stream"]["pixels_per_clock_short_spans_steady"])}',
             '"pixels_per_clock_short_spans_steady": 0.5', "'results'", "README.md:"),
            ("a region without its END line", "docs/setup_hw.md", "<!-- END generated: system_cost -->", "",
             "docs/setup_hw.md:", "'system_cost' has no line"),
            ("an unknown region", "docs/device.md", "<!-- BEGIN generated: device_budget (scripts/results_page.py) -->",
             "<!-- BEGIN generated: budgets (scripts/results_page.py) -->\n<!-- END generated: budgets -->\n"
             "<!-- BEGIN generated: device_budget (scripts/results_page.py) -->", "docs/device.md:",
             "no generated region is called 'budgets'"),
            ("a region removed", "README.md", begin, "<!-- the table was here -->", "README.md",
             "'results' is there 0 times"),
        ]
        for what, rel, old, new, *must in cases:
            dst = fresh()
            edit(dst, rel, old, new)
            rc, out = run(dst, "--check")
            if rc == 0:
                failures.append(f"{what}: --check passes")
            elif not all(m in out for m in must):
                failures.append(f"{what}: no message names {must}: {out.strip()[:400]}")
            else:
                print(f"self-test: {what}: fails as it must: {out.strip().splitlines()[0]}")
        # --write restores a tampered region exactly.
        dst = fresh()
        edit(dst, "README.md", f"{fmax} MHz", "99.99 MHz")
        rc, out = run(dst, "--write")
        rc2, out2 = run(dst, "--check")
        if rc != 0 or rc2 != 0 or read(dst, "README.md") != readme:
            failures.append(f"--write does not restore a tampered region: {out.strip()[:200]} {out2.strip()[:200]}")
        else:
            print("self-test: --write restores a tampered region")
        if specular:
            cli = "docs/measured/specular_cli.json"
            dst = fresh()
            d = json.loads(read(dst, cli))
            v = d["runs"][0]["rows"][0]["max_rel_epicenter"]
            d["runs"][0]["rows"][0]["max_rel_epicenter"] = v * 1.001
            with open(os.path.join(dst, cli), "w") as f:
                json.dump(d, f, indent=1)
            rc, out = run(dst, "--check", "--specular", specular)
            if rc == 0 or "max_rel_epicenter" not in out or cli not in out:
                failures.append(f"a CLI figure the CLI does not print: --check --specular gives {rc}: {out.strip()[:400]}")
            else:
                print(f"self-test: a tampered CLI figure fails as it must: {out.strip().splitlines()[0]}")
            rc, out = run(dst, "--write", "--specular", specular)
            got = json.loads(read(dst, cli))["runs"][0]["rows"][0]["max_rel_epicenter"]
            if rc != 0 or abs(got - v) > 1e-9 * abs(v):
                failures.append(f"--write --specular does not record the CLI's figure ({got} against {v}): {out[:200]}")
            else:
                print("self-test: --write --specular records the CLI's figure")
    for f in failures:
        print(f"check_results_page self-test: {f}", file=sys.stderr)
    print("check_results_page self-test: " + ("FAIL" if failures else "PASS"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
