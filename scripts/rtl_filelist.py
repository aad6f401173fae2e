#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The one reader and writer of the RTL filelists (rtl/README.md#filelists).

Each IP has one source, its manifest (rtl/core/core.manifest, ...): its own files and the IPs it
needs, one entry a line,
  description: TEXT          one line, for the generated files
  needs: rtl/prim/prim.manifest
                             an IP it needs (its files come first, each manifest read once)
  top: MODULE [NAME=VALUE]   a top module, with the parameters its lint needs (VALUE an
                             integer or a "string")
  +incdir+DIR                an include directory (the IP's own folder, for its .svh files)
  path/to/file.sv            a source, relative to the repository root, in compile order
  // comment, or a blank line
From the manifests `--generate` writes, beside each, the files tools read as they are:
  X.f     flat: every include directory and source of the IP and of what it needs, each once,
          in compile order, paths relative to the repository root (`verilator -f X.f`,
          `iverilog -g2012 -c X.f`, run from the root)
  X.core  a FuseSoC CAPI2 core: the IP's own files, a dependency on the core of each IP it
          needs, a Verilator lint target per top
Those files are committed; `--check DIR` regenerates them into DIR and fails naming each
committed one that differs (the ctest filelists_up_to_date).

Reading (the builds, scripts and tests): FILELIST is a manifest or a filelist (`.f`: sources,
`+incdir+DIR`, `-f FILE` read in place, `//` comments). Several are merged, each file once: a
source or include directory named twice within one of them is an error, one named by two of
them is taken once (rtl/specular.f and rtl/competitors/phong/phong.f share the core).

  scripts/rtl_filelist.py rtl/system/system.f             # sources, one per line
  scripts/rtl_filelist.py --incdirs rtl/system/system.f   # include directories
  scripts/rtl_filelist.py --includes rtl/system/system.f  # the include files they read
  scripts/rtl_filelist.py --flat a.f b.f > merged.f       # one flat list of several
  scripts/rtl_filelist.py --generate                      # rewrite every .f and .core
  scripts/rtl_filelist.py --check build/filelists         # are they up to date?
  scripts/rtl_filelist.py --ips                           # the table for CMake (below)

Used by rtl/specular_filelist.cmake (CMake), scripts/rtl_filelist.sh (the shell scripts),
scripts/make_report.py, scripts/fpga.py and tests/rtl/check_filelist.py (as a module),
tests/rtl/filelists.cmake (--ips, --check) and `make filelists` (--generate).

Exit status 0; 1 for --check with a stale file; 2 with a message naming the file, the line and
what is wrong.
"""
import argparse
import difflib
import json
import os
import re
import sys
import textwrap

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MANIFEST_EXT = ".manifest"
VENDOR = "specular"
CMAKE_VERSION_RE = re.compile(r"project\s*\(\s*specular_device\s+VERSION\s+([0-9][0-9.]*)", re.S)
INCLUDE_RE = re.compile(r'^\s*`include\s+"([^"]+)"', re.M)
PARAM_RE = re.compile(r'^([A-Za-z_][A-Za-z0-9_]*)=(-?[0-9]+|"[^"|,\s]*")$')


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


class Manifest:
    """One IP's manifest: its name (the file's stem), description, the manifests it needs, its
    tops [(module, [(param, value)])], its include directories and sources."""

    def __init__(self, path):
        self.path = path
        self.name = os.path.basename(path)[:-len(MANIFEST_EXT)]
        self.folder = os.path.dirname(path)
        self.description = ""
        self.needs = []
        self.tops = []
        self.incdirs = []
        self.sources = []

    @property
    def flat_path(self):
        return os.path.join(self.folder, self.name + ".f")

    @property
    def core_path(self):
        return os.path.join(self.folder, self.name + ".core")


def read_manifest(f, root=ROOT, check_exists=True):
    """Parses one manifest (root-relative path) without following its needs."""
    path = os.path.join(root, f)
    if not os.path.isfile(path):
        raise FilelistError(f"manifest {f} not found (paths are relative to the repository root {root})")
    m = Manifest(f)
    with open(path, encoding="utf-8") as fh:
        for lineno, raw in enumerate(fh, 1):
            line = raw.strip()
            loc = f"{f}:{lineno}"
            if not line or line.startswith("//"):
                continue
            key, sep, value = line.partition(":")
            if sep and key in ("description", "needs", "top"):
                value = value.strip()
                if not value:
                    raise FilelistError(f"{loc}: '{key}:' needs a value")
                if key == "description":
                    if m.description:
                        raise FilelistError(f"{loc}: a second description")
                    m.description = value
                elif key == "needs":
                    if not value.endswith(MANIFEST_EXT) or " " in value:
                        raise FilelistError(f"{loc}: 'needs: {value}' names no manifest (rtl/IP/IP{MANIFEST_EXT})")
                    m.needs.append(os.path.normpath(value))
                else:
                    module, *params = value.split()
                    pairs = []
                    for p in params:
                        match = PARAM_RE.match(p)
                        if not match:
                            raise FilelistError(f"{loc}: '{p}' is no NAME=VALUE (VALUE an integer or a \"string\")")
                        pairs.append((match.group(1), match.group(2)))
                    if module in (t for t, _ in m.tops):
                        raise FilelistError(f"{loc}: top {module} is named twice")
                    m.tops.append((module, pairs))
            elif line.startswith("+incdir+"):
                d = os.path.normpath(line[len("+incdir+"):])
                if check_exists and not os.path.isdir(os.path.join(root, d)):
                    raise FilelistError(f"{loc}: include directory {d} does not exist")
                if d in m.incdirs:
                    raise FilelistError(f"{loc}: include directory {d} is named twice")
                m.incdirs.append(d)
            elif " " in line or line.startswith(("-", "+")) or sep:
                raise FilelistError(f"{loc}: '{line}' is neither a source, +incdir+DIR, description:, needs: nor top:")
            else:
                s = os.path.normpath(line)
                if not s.endswith(".sv"):
                    raise FilelistError(f"{loc}: '{s}' is not an .sv file")
                if check_exists and not os.path.isfile(os.path.join(root, s)):
                    raise FilelistError(f"{loc}: '{s}' does not exist (paths are relative to the repository root)")
                if s in m.sources:
                    raise FilelistError(f"{loc}: '{s}' is named twice")
                m.sources.append(s)
    if not m.description:
        raise FilelistError(f"{f}: no 'description:' line")
    return m


def expand(filelists, root=ROOT, check_exists=True):
    """Reads the filelists or manifests (paths relative to root) and returns their Expansion:
    each one expanded alone (a repeat within it is an error), then merged, each file once."""
    total = Expansion()
    for f in filelists:
        one = Expansion()
        _read(os.path.normpath(f), root, one, [], check_exists)
        for x in one.filelists:
            if x not in total.filelists:
                total.filelists.append(x)
        for s in one.sources:
            if s not in total.owner:
                total.owner[s] = one.owner[s]
                total.sources.append(s)
        for d in one.incdirs:
            if d not in total.incdir_owner:
                total.incdir_owner[d] = one.incdir_owner[d]
                total.incdirs.append(d)
    return total


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


def _add_source(exp, s, f, loc):
    if s in exp.owner:
        raise FilelistError(f"{loc}: '{s}' is already named by {exp.owner[s]}")
    exp.owner[s] = f
    exp.sources.append(s)


def _add_incdir(exp, d, f, loc):
    if d in exp.incdir_owner:
        raise FilelistError(f"{loc}: include directory {d} is already named by {exp.incdir_owner[d]}")
    exp.incdir_owner[d] = f
    exp.incdirs.append(d)


def _read(f, root, exp, stack, check_exists):
    if f in stack:
        raise FilelistError(f"{stack[-1]}: names {f}, which names it again (a cycle)")
    if f in exp.filelists:
        return
    if not os.path.isfile(os.path.join(root, f)):
        where = f"{stack[-1]}: " if stack else ""
        kind = "manifest" if f.endswith(MANIFEST_EXT) else "filelist"
        raise FilelistError(f"{where}{kind} {f} not found (paths are relative to the repository root {root})")
    if f.endswith(MANIFEST_EXT):
        m = read_manifest(f, root, check_exists)
        exp.filelists.append(f)
        for n in m.needs:
            _read(n, root, exp, stack + [f], check_exists)
        for d in m.incdirs:
            _add_incdir(exp, d, f, f)
        for s in m.sources:
            _add_source(exp, s, f, f)
        return
    exp.filelists.append(f)
    with open(os.path.join(root, f), encoding="utf-8") as fh:
        for lineno, raw in enumerate(fh, 1):
            line = raw.strip()
            loc = f"{f}:{lineno}"
            if not line or line.startswith("//"):
                continue
            if line.startswith("+incdir+"):
                d = os.path.normpath(line[len("+incdir+"):])
                if check_exists and not os.path.isdir(os.path.join(root, d)):
                    raise FilelistError(f"{loc}: include directory {d} does not exist")
                _add_incdir(exp, d, f, loc)
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
                _add_source(exp, s, f, loc)


# ---------------------------------------------------------------------------------------
# Generation: the flat filelists and the FuseSoC cores (rtl/README.md#filelists)
# ---------------------------------------------------------------------------------------
def find_manifests(root=ROOT):
    """Every manifest under root/rtl, root-relative, sorted."""
    found = []
    for dirpath, dirnames, filenames in os.walk(os.path.join(root, "rtl")):
        dirnames.sort()
        found += [os.path.relpath(os.path.join(dirpath, n), root) for n in filenames if n.endswith(MANIFEST_EXT)]
    return sorted(found)


def project_version(root=ROOT):
    """The project's version, from the project() call of the top CMakeLists.txt."""
    path = os.path.join(root, "CMakeLists.txt")
    try:
        with open(path, encoding="utf-8") as fh:
            match = CMAKE_VERSION_RE.search(fh.read())
    except OSError:
        match = None
    if not match:
        raise FilelistError(f"{path}: no 'project(specular_device VERSION x.y.z' to take the cores' version from")
    return match.group(1)


def vlnv(m, version):
    library = "competitors" if m.path.startswith("rtl/competitors/") else "ip"
    return f"{VENDOR}:{library}:{m.name}:{version}"


def _comment(prefix, text, width=96):
    return [prefix + line if line else prefix.rstrip() for line in
            sum((textwrap.wrap(p, width - len(prefix)) or [""] for p in text.split("\n")), [])]


def _q(s):
    """A YAML double-quoted scalar (JSON's string syntax is YAML's)."""
    return json.dumps(s)


def _flat_text(m, exp):
    lines = ["// SPDX-License-Identifier: Apache-2.0", "//"]
    lines += _comment("// ", f"{m.flat_path}: {m.description}.")
    lines += ["//"]
    lines += _comment("// ", f"Generated from {m.path} by `make filelists` (scripts/rtl_filelist.py): edit "
                      "the manifest, not this file. Flat: each include directory and source once, in "
                      "compile order, paths relative to the repository root; run the tools from the root "
                      "(rtl/README.md#filelists):")
    top = m.tops[0][0] if m.tops else "TOP"
    lines += [f"//   verilator --lint-only -Wall -f {m.flat_path} --top-module {top}",
              f"//   iverilog -g2012 -c {m.flat_path} -s TOP   (which IPs Icarus 11 elaborates: rtl/README.md#filelists)", ""]
    lines += [f"+incdir+{d}" for d in exp.incdirs]
    last = None
    for s in exp.sources:
        if exp.owner[s] != last:
            last = exp.owner[s]
            lines += [f"// {last}"]
        lines.append(s)
    return "\n".join(lines) + "\n"


def _core_text(m, root, manifests, version):
    """The FuseSoC CAPI2 core of one IP (its fields: docs of the pinned FuseSoC, see
    scripts/fusesoc-requirements.txt)."""
    name = vlnv(m, version)
    out = ["CAPI=2:", "# SPDX-License-Identifier: Apache-2.0", "#"]
    out += _comment("# ", f"Generated from {m.path} by `make filelists` (scripts/rtl_filelist.py): edit the "
                    "manifest, not this file. The FuseSoC core of the IP: its own files, the cores of "
                    "the IPs it needs, a Verilator lint target per top (rtl/README.md#filelists):")
    out += [f"#   fusesoc --cores-root rtl run --target=lint {name}", ""]
    out += [f"name: {_q(name)}", f"description: {_q(m.description)}", "license: Apache-2.0", "", "filesets:",
            "  rtl:"]
    if m.needs:
        out += ["    depend:"] + [f"      - {_q(vlnv(manifests[n], version))}" for n in m.needs]
    headers = []
    for d in m.incdirs:
        headers += sorted(os.path.join(d, h) for h in os.listdir(os.path.join(root, d)) if h.endswith(".svh"))
    files = [f"      - {_q(os.path.relpath(h, m.folder))}: {{is_include_file: true}}" for h in headers]
    files += [f"      - {_q(os.path.relpath(s, m.folder))}" for s in m.sources]
    if files:
        out += ["    file_type: systemVerilogSource", "    files:"] + files
    params = {}
    for _, pairs in m.tops:
        for k, v in pairs:
            params.setdefault(k, "str" if v.startswith('"') else "int")
    out += ["", "targets:", "  default:", "    filesets: [rtl]"]
    for i, (top, pairs) in enumerate(m.tops):
        target = "lint" if i == 0 else f"lint_{top}"
        out += [f"  {target}:", f"    description: {_q(f'verilator --lint-only -Wall of {top}')}",
                "    filesets: [rtl]", "    flow: lint", "    flow_options:", "      tool: verilator",
                "      verilator_options: [-Wall]"]
        if pairs:
            out += ["    parameters:"] + [f"      - {_q(k + '=' + v.strip(chr(34)))}" for k, v in pairs]
        out += [f"    toplevel: {top}"]
    if params:
        out += ["", "parameters:"]
        for k, datatype in params.items():
            out += [f"  {k}:", f"    datatype: {datatype}", "    paramtype: vlogparam"]
    return "\n".join(out) + "\n"


def generate(root=ROOT):
    """{root-relative path: text} of every generated file: the flat filelist and the FuseSoC core
    of each manifest under root/rtl."""
    paths = find_manifests(root)
    if not paths:
        raise FilelistError(f"no {MANIFEST_EXT} file under {os.path.join(root, 'rtl')}")
    manifests = {p: read_manifest(p, root) for p in paths}
    for m in manifests.values():
        for n in m.needs:
            if n not in manifests:
                raise FilelistError(f"{m.path}: needs {n}, which is no manifest under rtl/")
        if not m.tops:
            raise FilelistError(f"{m.path}: no 'top:' line (the lint targets need one)")
    names = {}
    for m in manifests.values():
        if m.name in names:
            raise FilelistError(f"{m.path} and {names[m.name]}: one name, one FuseSoC core name (rename one)")
        names[m.name] = m.path
    version = project_version(root)
    out = {}
    for p, m in manifests.items():
        exp = expand([p], root)
        if not exp.sources:
            raise FilelistError(f"{p} names no source, and needs none that does")
        out[m.flat_path] = _flat_text(m, exp)
        out[m.core_path] = _core_text(m, root, manifests, version)
    return out


def write_generated(files, outdir):
    for rel, text in files.items():
        path = os.path.join(outdir, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(text)


def stale(files, root=ROOT):
    """[(path, diff)] of each generated file whose committed text differs, and of each .f or
    .core file under root/rtl that no manifest generates (left behind by a removed one)."""
    found = []
    for dirpath, dirnames, filenames in os.walk(os.path.join(root, "rtl")):
        for n in sorted(filenames):
            rel = os.path.relpath(os.path.join(dirpath, n), root)
            if n.endswith((".f", ".core")) and rel not in files:
                found.append((rel, f"{rel}: no manifest generates it (remove it, or add its .manifest)\n"))
    for rel, text in sorted(files.items()):
        try:
            with open(os.path.join(root, rel), encoding="utf-8") as fh:
                old = fh.read()
        except OSError:
            old = None
        if old != text:
            diff = "".join(difflib.unified_diff((old or "").splitlines(True), text.splitlines(True),
                                                f"{rel} (committed)", f"{rel} (generated)"))
            found.append((rel, diff if old is not None else f"{rel}: missing\n"))
    return found


def ip_table(root=ROOT):
    """One line per top of each manifest: NAME|FLAT_LIST|VLNV|TARGET|TOP|-GNAME=VALUE,...
    (tests/rtl/filelists.cmake registers its tests from it)."""
    version = project_version(root)
    lines = []
    for p in find_manifests(root):
        m = read_manifest(p, root)
        for i, (top, pairs) in enumerate(m.tops):
            target = "lint" if i == 0 else f"lint_{top}"
            args = ",".join(f"-G{k}={v}" for k, v in pairs)
            lines.append(f"{m.name}|{m.flat_path}|{vlnv(m, version)}|{target}|{top}|{args}")
    return lines


def main(argv=None):
    ap = argparse.ArgumentParser(description="Read, generate and check the RTL filelists (rtl/README.md#filelists).")
    what = ap.add_mutually_exclusive_group()
    what.add_argument("--sources", action="store_true", help="the sources in compile order (default)")
    what.add_argument("--incdirs", action="store_true", help="the include directories")
    what.add_argument("--filelists", action="store_true", help="every filelist or manifest read")
    what.add_argument("--includes", action="store_true", help="the include files the sources read")
    what.add_argument("--flat", action="store_true", help="one flat filelist: +incdir+ lines, then the sources")
    what.add_argument("--generate", action="store_true",
                      help="write each manifest's flat filelist and FuseSoC core (into --out, default the tree)")
    what.add_argument("--check", metavar="DIR",
                      help="regenerate into DIR and fail naming each committed file that differs")
    what.add_argument("--ips", action="store_true", help="NAME|LIST|VLNV|TARGET|TOP|-GPARAMS per top of each manifest")
    ap.add_argument("--out", help="with --generate: the directory to write into (default: the root)")
    ap.add_argument("--absolute", action="store_true", help="absolute paths instead of root-relative ones")
    ap.add_argument("--root", default=ROOT, help="the repository root (default: the one holding this script)")
    ap.add_argument("filelist", nargs="*", help="filelists or manifests, relative to the root (rtl/specular.f, ...)")
    args = ap.parse_args(argv)
    generating = args.generate or args.check or args.ips
    if generating and args.filelist:
        ap.error("--generate, --check and --ips take no filelist")
    if not generating and not args.filelist:
        ap.error("name at least one filelist (rtl/specular.f, rtl/core/core.f, ...)")
    try:
        if args.ips:
            sys.stdout.write("".join(line + "\n" for line in ip_table(args.root)))
            return 0
        if generating:
            files = generate(args.root)
            if args.generate:
                write_generated(files, args.out or args.root)
                print(f"rtl_filelist: wrote {len(files)} files: {' '.join(sorted(files))}", file=sys.stderr)
                return 0
            write_generated(files, args.check)
            bad = stale(files, args.root)
            for rel, diff in bad:
                sys.stdout.write(diff)
            if bad:
                print(f"rtl_filelist: STALE (not what their manifests generate, regenerated into {args.check}): "
                      f"{', '.join(rel for rel, _ in bad)}; edit the .manifest, not the generated file, and run "
                      "`make filelists`")
                return 1
            print(f"rtl_filelist: OK: {len(files)} generated files up to date ({', '.join(sorted(files))})")
            return 0
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
