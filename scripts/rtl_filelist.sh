# SPDX-License-Identifier: Apache-2.0
#
# Sourced by the scripts that read the RTL (synth.sh, fpga.sh, the formal*.sh scripts,
# coverage.sh): rtl_filelist [FILELIST...] expands filelists (default rtl/specular.f, the
# product; run from the repository root; format in rtl/README.md#filelists) with
# scripts/rtl_filelist.py, the one reader of the format, into two arrays:
#   RTL_SOURCES  the source files in compile order, paths relative to the root
#   RTL_INCDIRS  the include directories of their `+incdir+DIR` lines
#   RTL_FILELISTS  every filelist read
# Returns 1 (with the reader's message) when a filelist is missing or wrong.
rtl_filelist() {
  local out
  [ $# -gt 0 ] || set -- rtl/specular.f
  out=$(python3 scripts/rtl_filelist.py --sources "$@") || return 1
  mapfile -t RTL_SOURCES <<< "$out"
  out=$(python3 scripts/rtl_filelist.py --incdirs "$@") || return 1
  RTL_INCDIRS=()
  [ -z "$out" ] || mapfile -t RTL_INCDIRS <<< "$out"
  out=$(python3 scripts/rtl_filelist.py --filelists "$@") || return 1
  mapfile -t RTL_FILELISTS <<< "$out"
}

# rtl_mutant_copy DIR FILE SED_EXPR [SOURCE...] (after rtl_filelist): copies the sources
# (default: every file of RTL_SOURCES) into DIR under their relative paths, applies the sed
# expression to the copy of FILE (one of them), prints the difference, and sets
# MUTANT_SOURCES to the copies in the same order. The formal scripts' mutant runs read those
# instead of rtl/, which is never edited. Returns 1 (with a message) when the expression
# changes nothing: the RTL changed under the mutation.
rtl_mutant_copy() {
  local dir=$1 file=$2 expr=$3 f
  shift 3
  [ $# -gt 0 ] || set -- "${RTL_SOURCES[@]}"
  rm -rf "$dir"
  MUTANT_SOURCES=()
  for f in "$@"; do
    mkdir -p "$dir/$(dirname "$f")"
    cp "$f" "$dir/$f"
    MUTANT_SOURCES+=("$dir/$f")
  done
  sed -i "$expr" "$dir/$file"
  if cmp -s "$file" "$dir/$file"; then
    echo "rtl_mutant_copy: the mutation did not apply to $file (RTL changed?)" >&2
    return 1
  fi
  diff "$file" "$dir/$file" || true
}
