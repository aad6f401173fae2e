#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# Licence header check (ctest docs_spdx): every tracked source file carries the line
# `SPDX-License-Identifier: Apache-2.0` (in any comment syntax) within its first 5 lines.
# The licence text is LICENSE at the repository root.
#
#   tests/docs/check_spdx.sh [ROOT]      check ROOT (default: the repository of this script)
#   tests/docs/check_spdx.sh --self-test  the checker on a scratch tree: one good file, one
#                                         without the line, one with it on line 6
#
# Source files: *.sv, *.svh, *.cpp, *.hpp, *.inl, *.py, *.sh, *.cmake, *.f (filelists),
# .ci/run, CMakeLists.txt and Makefile, taken from `git ls-files` (tracked files only; build trees and untracked scratch
# files are not looked at), or from `find` when ROOT is not a git work tree.
# Exit status: 0 when every file has the line, 1 otherwise (each offending file listed),
# 2 on a usage error.
set -euo pipefail

readonly spdx='SPDX-License-Identifier: Apache-2.0'
readonly head_lines=5
readonly name_re='(\.(sv|svh|cpp|hpp|inl|py|sh|cmake|f)$|(^|/)(CMakeLists\.txt|Makefile)$|^\.ci/run$)'

list_sources() {
  local root=$1
  if git -C "$root" rev-parse --is-inside-work-tree > /dev/null 2>&1; then
    git -C "$root" ls-files -z | tr '\0' '\n' | grep -E "$name_re" || true
  else
    (cd "$root" && find . -path ./build -prune -o -type f -print | sed 's|^\./||' |
      grep -E "$name_re" | sort) || true
  fi
}

# Prints each file under ROOT that lacks the line; returns 1 if there is one.
check_tree() {
  local root=$1 f missing=0 total=0
  while IFS= read -r f; do
    [ -n "$f" ] || continue
    # A tracked file deleted in the work tree is not a source any more.
    [ -f "$root/$f" ] || continue
    total=$((total + 1))
    if ! head -n "$head_lines" "$root/$f" | grep -qF "$spdx"; then
      echo "  $f"
      missing=$((missing + 1))
    fi
  done < <(list_sources "$root")
  if [ "$missing" -ne 0 ]; then
    echo "check_spdx: $missing of $total source files lack '$spdx' in their first $head_lines lines (listed above)"
    return 1
  fi
  echo "check_spdx: all $total source files carry '$spdx'"
}

self_test() {
  local tmp
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' RETURN
  mkdir -p "$tmp/rtl"
  printf '// %s\nmodule good; endmodule\n' "$spdx" > "$tmp/rtl/good.sv"
  printf '#!/bin/sh\n# %s\n' "$spdx" > "$tmp/good.sh"
  printf 'module bare; endmodule\n' > "$tmp/rtl/bare.sv"
  printf '1\n2\n3\n4\n5\n# %s\n' "$spdx" > "$tmp/CMakeLists.txt"
  printf 'not a source\n' > "$tmp/notes.txt"
  local out rc=0
  out=$(check_tree "$tmp") || rc=$?
  if [ "$rc" -ne 1 ] || ! grep -qx '  rtl/bare.sv' <<< "$out" \
     || ! grep -qx '  CMakeLists.txt' <<< "$out" || grep -q 'good\|notes' <<< "$out"; then
    echo "check_spdx --self-test: FAIL: expected exactly rtl/bare.sv and CMakeLists.txt, got:"
    echo "$out"
    return 1
  fi
  rm "$tmp/rtl/bare.sv"
  printf '# %s\n' "$spdx" > "$tmp/CMakeLists.txt"
  if ! check_tree "$tmp" > /dev/null; then
    echo "check_spdx --self-test: FAIL: a clean tree is reported"
    return 1
  fi
  echo "check_spdx --self-test: PASS (missing line and line 6 caught, clean tree passes)"
}

case "${1:-}" in
  --self-test) self_test ;;
  -h|--help) sed -n '3,16p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
  -*) echo "check_spdx: unknown option '$1'" >&2; exit 2 ;;
  *) root=${1:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
     [ -d "$root" ] || { echo "check_spdx: no directory '$root'" >&2; exit 2; }
     check_tree "$root" ;;
esac
