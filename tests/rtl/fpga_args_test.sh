#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# ctest fpga_args: scripts/fpga.sh rejects bad arguments with exit 2 and a message naming
# the argument and its allowed values, before running any tool (no place and route here).
set -u
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
fail=0
expect() {  # expect REGEX ARGS...: exit 2 and stderr matching REGEX
  local re=$1; shift
  local err rc
  err=$(bash "$root/scripts/fpga.sh" "$@" 2>&1 > /dev/null); rc=$?
  if [ "$rc" != 2 ] || ! grep -Eq -- "$re" <<< "$err"; then
    echo "FAIL: fpga.sh $* -> exit $rc (want 2), stderr: $err"; fail=1
  else
    echo "ok: fpga.sh $* -> exit 2: $(head -n 1 <<< "$err")"
  fi
}
expect "--device must be one of hx8k, up5k, ecp5, ecp5-25, ecp5-45, ecp5-85, all, or a comma-separated list of them \(got 'virtex7'\)" --device virtex7
expect "--top must be one of unit, stream, axil, phong, setup, setup_lean, system, mul, all \(got 'core'\)" --top core
expect "--device must be one of hx8k, up5k, ecp5, ecp5-25, ecp5-45, ecp5-85, all, or a comma-separated list of them \(got 'hx8k,ecp6'\)" --top setup --device hx8k,ecp6
expect "--device must be one of .* \(got 'ecp5-12'\)" --device ecp5-12
expect "--seed must be a non-negative integer \(got 'abc'\)" --top phong --phong-config all --seed abc
expect "--phong-config must be all or one of n1000,n128,.* \(got 'n7'\)" --top phong --phong-config n7
expect "--phong-config needs --top phong \(got --top setup\)" --top setup --phong-config n64
expect "--param must be NAME=VALUE" --param CosAddrBits
expect "--param name must be a Verilog identifier" --param 9x=1
expect "string value must not contain quotes" --param 'CosRomFile=a"b'
expect "--seed must be a non-negative integer" --seed abc
expect "--yosys-timeout must be a whole number of seconds, 0 for no limit \(got '1h'\)" --top setup --yosys-timeout 1h
expect "must be a positive number of MHz" --freq-hx8k 0
expect "must be a positive number of MHz \(got 'fast'\)" --freq-ecp5 fast
expect "--out needs a value" --out
expect "--setup-ii must be a positive whole number \(got 'x'" --top setup --setup-ii x
expect "--setup-ii needs --top setup, setup_lean or system \(got --top stream\)" --top stream --setup-ii 2
expect "--label must be letters, digits and _ \(got 'b1 n64'\)" --top stream --label 'b1 n64'
expect "--label must not be 'default'" --top stream --label default
expect "--label and --phong-config both name the configuration: give one \(got --label x --phong-config n64\)" --top phong --phong-config n64 --label x
expect "--label needs a value" --top stream --label
expect "--record with --param CosAddrBits needs --label NAME" --top stream --param CosAddrBits=7 --record
expect "--record with --param CoefBits needs --label NAME" --top stream --record --param MulTileBits=0 --param CoefBits=20
expect "unknown argument '--bogus' \(allowed: .*--flatten, --no-flatten" --bogus
expect "unknown argument .*--setup-ii, --label, --record, --help\)" --bogus
exit $fail
