#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# Lints an IP with FuseSoC from its .core file (rtl/README.md#filelists): installs the pinned
# FuseSoC first (scripts/tools_venv.py install fusesoc: the build's virtual environment), then runs
#   fusesoc --cores-root rtl run --build-root BUILD_ROOT --target TARGET VLNV
# from the repository root: FuseSoC copies the files of the core and of the cores it depends on
# into BUILD_ROOT/<vlnv>/<target>/src and runs `verilator --lint-only -Wall` there, so a file
# missing from a .core fails. The ctests fusesoc_lint_* (tests/rtl/filelists.cmake) run it.
#
#   scripts/fusesoc_lint.sh [--build-root DIR] VLNV [TARGET]
#       TARGET defaults to lint; DIR to build/fusesoc
#   scripts/fusesoc_lint.sh [--build-root DIR] --mutant
#       the check that the lint can fail: a copy of rtl/ whose core of the core IP
#       (rtl/core/core.core) lacks specular_control.sv must fail to lint, naming that module
#
# Exit status: 0 lint clean (--mutant: the mutant failed as it must), 1 a lint message, a
# failed install or a mutant that passed, 2 on a bad argument.
set -uo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
me=scripts/fusesoc_lint.sh
build_root=$root/build/fusesoc
mutant=0
args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --build-root) [ $# -ge 2 ] || { echo "$me: --build-root needs a directory" >&2; exit 2; }
                  build_root=$2; shift ;;
    --mutant) mutant=1 ;;
    -*) echo "$me: unknown option '$1' (allowed: --build-root DIR, --mutant)" >&2; exit 2 ;;
    *) args+=("$1") ;;
  esac
  shift
done
if { [ "$mutant" = 1 ] && [ ${#args[@]} -ne 0 ]; } || { [ "$mutant" = 0 ] && [ ${#args[@]} -lt 1 ]; } ||
   [ ${#args[@]} -gt 2 ]; then
  echo "usage: $me [--build-root DIR] VLNV [TARGET] | $me [--build-root DIR] --mutant" >&2
  exit 2
fi

bin=$(/usr/bin/python3 "$root/scripts/tools_venv.py" install fusesoc --print-bin) || exit 1
mkdir -p "$build_root"
build_root=$(cd "$build_root" && pwd)
# FuseSoC's own configuration: its caches under the build root, no user or system file read.
# Written aside and moved: the ctests run this script in parallel.
conf=$build_root/fusesoc.conf
printf '[main]\ncache_root = %s/cache\nlibrary_root = %s/library\n' "$build_root" "$build_root" > "$conf.$$"
mv -f "$conf.$$" "$conf"

# lint CORES_ROOT VLNV TARGET WORK_ROOT: prints FuseSoC's and Verilator's output; its status.
lint() {
  rm -rf "$4"
  (cd "$(dirname "$1")" &&
    "$bin/fusesoc" --config "$conf" --monochrome --cores-root "$(basename "$1")" \
      run --work-root "$4" --target "$3" "$2") 2>&1
}

if [ "$mutant" = 0 ]; then
  vlnv=${args[0]}
  target=${args[1]:-lint}
  work=$build_root/$(echo "$vlnv" | tr ':' '_')/$target
  out=$(lint "$root/rtl" "$vlnv" "$target" "$work")
  rc=$?
  echo "$out"
  # Verilator's messages fail the lint even where its exit status would not (-Wno-fatal).
  if [ $rc -ne 0 ] || grep -q '%Warning\|%Error' <<< "$out"; then
    echo "$me: FAIL: fusesoc lint of $vlnv (target $target, work directory $work)" >&2
    exit 1
  fi
  echo "$me: OK: $vlnv target $target lints clean (verilator --lint-only -Wall, work directory $work)"
  exit 0
fi

# The mutant: the core IP's .core without one of its sources.
copy=$build_root/mutant
rm -rf "$copy"
mkdir -p "$copy"
cp -r "$root/rtl" "$copy/rtl"
core=$copy/rtl/core/core.core
before=$(wc -l < "$core")
sed -i '/"specular_control.sv"$/d' "$core"
if [ "$(wc -l < "$core")" -ne $((before - 1)) ]; then
  echo "$me: FAIL: rtl/core/core.core names no \"specular_control.sv\" line to remove (the mutant needs updating)" >&2
  exit 1
fi
vlnv=$(sed -n 's/^name: "\(.*\)"$/\1/p' "$core")
out=$(lint "$copy/rtl" "$vlnv" lint "$copy/work")
rc=$?
echo "$out"
if [ $rc -eq 0 ]; then
  echo "$me: FAIL: the lint of $vlnv passed without specular_control.sv in its .core: it cannot catch a missing file" >&2
  exit 1
fi
if ! grep -q "specular_control" <<< "$out"; then
  echo "$me: FAIL: the lint of the mutant failed, but not on the missing module specular_control" >&2
  exit 1
fi
echo "$me: OK: the lint of $vlnv without specular_control.sv fails, naming the module"
