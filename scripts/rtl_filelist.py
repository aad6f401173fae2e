#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The one reader of the RTL filelists (rtl/README.md#filelists).

A filelist (`.f`) holds, one per line:
  path/to/file.sv    a source, relative to the repository root
  +incdir+DIR        an include directory, relative to the root
  -f path/to/ip.f    another filelist, read in place (its sources come first)
  // comment, or a blank line
Every filelist is read once however often it is named (IPs share their dependencies: the
system names the core and the setup, both of which name the primitives), so the expansion is
each source once, in compile order: dependencies before their users.

Used by rtl/specular_filelist.cmake (CMake), scripts/rtl_filelist.sh (the shell scripts),
scripts/make_report.py and tests/rtl/check_filelist.py (as a module), and by users:

  scripts/rtl_filelist.py rtl/system/system.f            # sources, one per line
  scripts/rtl_filelist.py --incdirs rtl/system/system.f  # include directories
  scripts/rtl_filelist.py --includes rtl/system/system.f # the include files they read
  scripts/rtl_filelist.py --flat rtl/system/system.f > system_flat.f
      # one flat filelist for a tool that reads nested ones but not the same file twice
      # (Verilator and Icarus report a module declared twice)

Exit status 0, or 2 with a message naming the filelist, the line and what is wrong.
"""
import argparse
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


class FilelistError(Exception):
    pass


class Expansion:
    """Sources and include directories in order, the filelists read, and which filelist names
    each source and include directory (paths relative to the root)."""

    def __init__(self):
        self.sources = []
        self.incdirs = []
        self.filelists = []
        self.owner = {}         # source -> the filelist that names it
        self.incdir_owner = {}  # include directory -> the filelist that names it


def expand(filelists, root=ROOT, check_exists=True):
    """Reads the filelists (paths relative to root) and returns their Expansion."""
    exp = Expansion()
    for f in filelists:
        _read(os.path.normpath(f), root, exp, [], check_exists)
    return exp


INCLUDE_RE = re.compile(r'^\s*`include\s+"([^"]+)"', re.M)


def includes(exp, root=ROOT):
    """The include files the sources read (`include "name"`, found in the include directories
    in order, and the files those include), root-relative: what a build depends on besides the
    sources. Raises FilelistError for an include found in no include directory."""
    found, todo = [], list(exp.sources)
    while todo:
        src = todo.pop(0)
        with open(os.path.join(root, src), encoding="utf-8") as fh:
            names = INCLUDE_RE.findall(fh.read())
        for name in names:
            hits = [os.path.join(d, name) for d in exp.incdirs if os.path.isfile(os.path.join(root, d, name))]
            if not hits:
                raise FilelistError(f"{src}: `include \"{name}\" is in no include directory ({', '.join(exp.incdirs) or 'none'})")
            if hits[0] not in found:
                found.append(hits[0])
                todo.append(hits[0])
    return found


def _read(f, root, exp, stack, check_exists):
    if f in stack:
        raise FilelistError(f"{stack[-1]}: names {f}, which names it again (a cycle)")
    if f in exp.filelists:
        return
    path = os.path.join(root, f)
    if not os.path.isfile(path):
        where = f"{stack[-1]}: " if stack else ""
        raise FilelistError(f"{where}filelist {f} not found (paths are relative to the repository root {root})")
    exp.filelists.append(f)
    with open(path, encoding="utf-8") as fh:
        for lineno, raw in enumerate(fh, 1):
            line = raw.strip()
            loc = f"{f}:{lineno}"
            if not line or line.startswith("//"):
                continue
            if line.startswith("+incdir+"):
                d = os.path.normpath(line[len("+incdir+"):])
                if check_exists and not os.path.isdir(os.path.join(root, d)):
                    raise FilelistError(f"{loc}: include directory {d} does not exist")
                if d in exp.incdir_owner:
                    if exp.incdir_owner[d] != f:
                        raise FilelistError(f"{loc}: include directory {d} is already named by {exp.incdir_owner[d]}")
                    continue
                exp.incdir_owner[d] = f
                exp.incdirs.append(d)
            elif line.startswith("-f ") or line.startswith("-F "):
                _read(os.path.normpath(line[3:].strip()), root, exp, stack + [f], check_exists)
            elif " " in line or line.startswith(("-", "+")):
                raise FilelistError(f"{loc}: '{line}' is neither a source, +incdir+DIR nor -f FILE")
            else:
                s = os.path.normpath(line)
                if not s.endswith(".sv"):
                    raise FilelistError(f"{loc}: '{s}' is not an .sv file")
                if check_exists and not os.path.isfile(os.path.join(root, s)):
                    raise FilelistError(f"{loc}: '{s}' does not exist (paths are relative to the repository root)")
                if s in exp.owner:
                    raise FilelistError(f"{loc}: '{s}' is already named by {exp.owner[s]}")
                exp.owner[s] = f
                exp.sources.append(s)


def main(argv=None):
    ap = argparse.ArgumentParser(description="Expand RTL filelists (rtl/README.md#filelists).")
    what = ap.add_mutually_exclusive_group()
    what.add_argument("--sources", action="store_true", help="the sources in compile order (default)")
    what.add_argument("--incdirs", action="store_true", help="the include directories")
    what.add_argument("--filelists", action="store_true", help="every filelist read")
    what.add_argument("--includes", action="store_true", help="the include files the sources read")
    what.add_argument("--flat", action="store_true", help="one flat filelist: +incdir+ lines, then the sources")
    ap.add_argument("--absolute", action="store_true", help="absolute paths instead of root-relative ones")
    ap.add_argument("--root", default=ROOT, help="the repository root (default: the one holding this script)")
    ap.add_argument("filelist", nargs="+", help="filelists, relative to the root (rtl/specular.f, rtl/core/core.f, ...)")
    args = ap.parse_args(argv)
    try:
        exp = expand(args.filelist, args.root)
        incs = includes(exp, args.root) if args.includes else []
    except FilelistError as e:
        print(f"rtl_filelist: {e}", file=sys.stderr)
        return 2
    if not exp.sources:
        print(f"rtl_filelist: {' '.join(args.filelist)} names no source", file=sys.stderr)
        return 2
    fix = (lambda p: os.path.join(os.path.abspath(args.root), p)) if args.absolute else (lambda p: p)
    if args.incdirs:
        out = [fix(d) for d in exp.incdirs]
    elif args.filelists:
        out = [fix(f) for f in exp.filelists]
    elif args.includes:
        out = [fix(i) for i in incs]
    elif args.flat:
        out = [f"// flattened from {' '.join(args.filelist)} by scripts/rtl_filelist.py"]
        out += [f"+incdir+{fix(d)}" for d in exp.incdirs] + [fix(s) for s in exp.sources]
    else:
        out = [fix(s) for s in exp.sources]
    sys.stdout.write("".join(line + "\n" for line in out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
