#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# Installs FuseSoC (scripts/fusesoc-requirements.txt: fusesoc, edalize and what they pull in,
# pinned) into a Python virtual environment, by default build/fusesoc-venv (FUSESOC_VENV
# overrides it), and checks that it runs. Idempotent: when the environment already holds the
# pinned versions and fusesoc answers, it does nothing. scripts/fusesoc_lint.sh calls it; so
# does the ctest fusesoc_install on first use (rtl/README.md#filelists).
#
#   scripts/install-fusesoc.sh [--print-bin]
#     --print-bin  print the environment's bin/
#
# Exit status: 0 installed (or already there), 1 with a message naming what failed and how to
# install it by hand, 2 on a bad argument.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
venv=${FUSESOC_VENV:-$root/build/fusesoc-venv}
req=$root/scripts/fusesoc-requirements.txt
me=scripts/install-fusesoc.sh
print_bin=0
for arg in "$@"; do
  case "$arg" in
    --print-bin) print_bin=1 ;;
    *) echo "$me: unknown argument '$arg' (allowed: --print-bin)" >&2; exit 2 ;;
  esac
done

# Debian's interpreter: the python3 first on PATH may be another one (pyenv).
python=/usr/bin/python3
[ -x "$python" ] || python=$(command -v python3 || true)
if [ -z "$python" ]; then
  echo "$me: no python3 found (Debian: apt-get install python3 python3-venv)" >&2
  exit 1
fi

want=$(sed -n 's/^fusesoc==//p' "$req")
answers() {
  [ "$("$venv/bin/fusesoc" --version 2> /dev/null)" = "$want" ]
}

stamp=$venv/.requirements
if ! cmp -s "$req" "$stamp" 2> /dev/null || ! answers; then
  echo "$me: installing fusesoc $want and its pinned dependencies ($req) into $venv" >&2
  if [ ! -x "$venv/bin/pip" ]; then
    "$python" -m venv "$venv" ||
      { echo "$me: '$python -m venv $venv' failed (Debian: apt-get install python3-venv)" >&2; exit 1; }
  fi
  if ! "$venv/bin/pip" install -q --disable-pip-version-check --timeout 30 --retries 2 -r "$req"; then
    echo "$me: pip could not install $req into $venv: is the Python package index reachable?" \
      "Install by hand with '$venv/bin/pip install -r $req', then run $me again" >&2
    exit 1
  fi
  if ! answers; then
    echo "$me: $venv/bin/fusesoc does not answer --version with $want; remove $venv and run $me again" >&2
    exit 1
  fi
  cp "$req" "$stamp"
fi
[ "$print_bin" = 0 ] || echo "$venv/bin"
