# SPDX-License-Identifier: Apache-2.0
#
# Sourced by the scripts that read the RTL (synth.sh, fpga.sh, the formal*.sh scripts,
# coverage.sh): rtl_filelist [FILE] reads the filelist (default rtl/specular.f, run from the
# repository root; format in rtl/README.md) into two arrays:
#   RTL_SOURCES  the source files in compile order, paths relative to the root
#   RTL_INCDIRS  the include directories of its `+incdir+DIR` lines
# `//` comment lines and blank lines are skipped. Returns 1 (with a message) when the file
# is missing or names no source.
rtl_filelist() {
  local f=${1:-rtl/specular.f} line
  RTL_SOURCES=()
  RTL_INCDIRS=()
  if [ ! -f "$f" ]; then
    echo "rtl_filelist: $f not found (run from the repository root)" >&2
    return 1
  fi
  while IFS= read -r line || [ -n "$line" ]; do
    line=${line#"${line%%[![:space:]]*}"}
    line=${line%"${line##*[![:space:]]}"}
    case "$line" in
      ''|//*) ;;
      +incdir+*) RTL_INCDIRS+=("${line#+incdir+}") ;;
      *) RTL_SOURCES+=("$line") ;;
    esac
  done < "$f"
  if [ ${#RTL_SOURCES[@]} -eq 0 ]; then
    echo "rtl_filelist: $f lists no source" >&2
    return 1
  fi
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
