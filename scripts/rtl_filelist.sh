# SPDX-License-Identifier: Apache-2.0
#
# Sourced by the scripts that read the RTL (synth.sh, fpga.sh, formal.sh, formal_axil.sh,
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
