#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs the Debian bookworm packages this project builds and tests with.
# Idempotent: does nothing when every package is already installed.
set -euo pipefail

PACKAGES=(
  build-essential cmake
  verilator
  catch2
  libglm-dev
  libcli11-dev
  nlohmann-json3-dev
  libfmt-dev
  libbenchmark-dev
  libstb-dev
  libsleef-dev
  libassimp-dev glmark2-data assimp-testmodels
  iverilog
  yosys
  nextpnr-ice40
  fpga-icestorm
  python3-matplotlib python3-venv
  lcov
  clang-14 libfuzzer-14-dev
  z3 ccache
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  SUDO="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
