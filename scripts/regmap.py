#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The register map of specular_axil, written once in rtl/axi/data/specular_axil.rdl
(SystemRDL), and the copies generated from it:

  rtl/axi/specular_axil_reg_pkg.sv   the RTL's constants: byte offsets, field positions,
                                     reset values, which words answer OKAY, a function per
                                     register of several fields (this script, through
                                     systemrdl-compiler; Yosys 0.23 and Icarus 11 read it)
  rtl/axi/data/specular_axil_regs.h  C header of the tests and host code (peakrdl-cheader)
  docs/interfaces.md                 the register-map table, between the lines
                                     <!-- BEGIN generated: axil-regmap (scripts/regmap.py) -->
                                     and <!-- END generated: axil-regmap --> (this script)

The PeakRDL tools (scripts/regmap-requirements.txt, pinned) are installed on first use into
the project's virtual environment (scripts/tools_venv.py install regmap: build/venv, or
SPECULAR_VENV); the generation runs in that environment's Python.

  scripts/regmap.py --write            rewrite the committed copies (make regmap)
  scripts/regmap.py --check DIR        generate into DIR and compare with the committed copies
                                       (ctest regmap_up_to_date); exit 1 naming a stale one
  scripts/regmap.py --selftest DIR     show on copies in DIR that --check catches a hand
                                       edit of each copy (ctest regmap_stale_caught)
  scripts/regmap.py --install          only install the tools

Exit status: 0 done, 1 stale copies or a failed install (the message says which and what
to do), 2 bad arguments. Run from anywhere: paths are relative to the repository root.
"""

import argparse
import difflib
import os
import shutil
import subprocess
import sys

import tools_venv  # scripts/tools_venv.py, beside this file

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ME = "scripts/regmap.py"
RDL = "rtl/axi/data/specular_axil.rdl"
SV_PKG = "rtl/axi/specular_axil_reg_pkg.sv"
C_HEADER = "rtl/axi/data/specular_axil_regs.h"
DOC = "docs/interfaces.md"
DOC_FRAGMENT = "axil-regmap.md"  # the table's name in a generated directory
# The region's lines, in the form of the project's other generated regions (scripts/results_page.py).
BEGIN = "<!-- BEGIN generated: axil-regmap (scripts/regmap.py) -->"
END = "<!-- END generated: axil-regmap -->"
PKG_NAME = "specular_axil_reg_pkg"


def die(msg, status=1):
    print(f"{ME}: {msg}", file=sys.stderr)
    sys.exit(status)


# ---------------------------------------------------------------------------------------
# The tools: a virtual environment under build/ with the pinned requirements
# ---------------------------------------------------------------------------------------
def install():
    """The project's virtual environment with the pinned PeakRDL tools (scripts/tools_venv.py): its bin/."""
    try:
        return tools_venv.bin_dir("regmap")
    except tools_venv.VenvError as e:
        die(str(e))


# ---------------------------------------------------------------------------------------
# Generation (runs inside the virtual environment: needs systemrdl-compiler)
# ---------------------------------------------------------------------------------------
def camel(name):
    """SPAN_PSI0 -> SpanPsi0, BAD_N -> BadN (lowRISC style for constants)."""
    return "".join(p[:1].upper() + p[1:].lower() for p in name.split("_"))


def hex32(v):
    return f"{v >> 16:04X}_{v & 0xFFFF:04X}"


class Reg:
    """One register (or register array) of the map, as the generators need it."""

    def __init__(self, node):
        self.name = node.inst_name
        self.offset = node.raw_address_offset
        self.count = node.array_dimensions[0] if node.is_array else 1
        self.stride = node.array_stride if node.is_array else 0
        self.desc = node.get_property("desc") or ""
        self.fields = []
        for f in node.fields():
            self.fields.append({
                "name": f.inst_name,
                "lsb": f.lsb,
                "msb": f.msb,
                "width": f.width,
                "reset": f.get_property("reset"),
                "reset_text": f.get_property("reset_text"),
                "width_param": f.get_property("width_param"),
                "readable": f.is_sw_readable,
                "writable": f.is_sw_writable,
                "w1c": f.get_property("onwrite") is not None and f.get_property("onwrite").name == "woclr",
                "constant": (not f.is_sw_writable) and (not f.implements_storage) and not f.is_hw_writable,
                "desc": f.get_property("desc") or "",
            })
        self.fields.sort(key=lambda f: f["lsb"])

    @property
    def access(self):
        fs = self.fields
        if all(f["w1c"] for f in fs):
            return "W1C"
        if all(f["writable"] and not f["readable"] for f in fs):
            return "WO"
        if all(f["writable"] and f["readable"] and not f["w1c"] for f in fs):
            return "RW"
        if all(f["readable"] and not f["writable"] for f in fs):
            return "RO"
        die(f"{RDL}: register {self.name} mixes access types, which the RTL and the docs table "
            "do not describe")

    @property
    def reset(self):
        """The register's reset value, or None when a field has none."""
        if any(f["reset"] is None for f in self.fields):
            return None
        return sum(f["reset"] << f["lsb"] for f in self.fields)

    def words(self):
        return [(self.offset + i * self.stride) // 4 for i in range(self.count)]


def load_map(tree):
    from systemrdl import RDLCompileError, RDLCompiler  # the venv's systemrdl-compiler
    rdlc = RDLCompiler()
    try:
        rdlc.compile_file(os.path.join(tree, RDL))
        top = rdlc.elaborate().top
    except RDLCompileError:
        die(f"{RDL} does not compile (messages above)")
    regs = [Reg(r) for r in top.registers()]
    for r in regs:
        if r.offset % 4 or (r.count > 1 and r.stride != 4):
            die(f"{RDL}: {r.name} is not on word boundaries of 4 bytes")
    block_aw = max(2, (top.size - 1).bit_length())
    return regs, block_aw


def sv_package(regs, block_aw):
    words = 1 << (block_aw - 2)
    readable = sum(1 << w for r in regs for w in r.words())
    writable = sum(1 << w for r in regs if r.access != "RO" for w in r.words())
    digits = words // 4

    def bitmap(v):
        s = f"{v:0{digits}X}"
        return f"{words}'h" + "_".join(s[i:i + 4] for i in range(0, digits, 4))

    out = [
        "// SPDX-License-Identifier: Apache-2.0",
        "//",
        f"// Generated by {ME} from {RDL}: do not edit. `make regmap`",
        "// rewrites it; the ctest regmap_up_to_date fails when it is stale.",
        "//",
        f"// {PKG_NAME}: the register map of specular_axil (rtl/axi/specular_axil.sv,",
        "// docs/interfaces.md#register-map) as constants of the default build: per register its",
        "// byte offset (<Reg>Offset), its reset value where every field has one (<Reg>Reset) and",
        "// the position of each field (<Reg><Field>Lsb, <Reg><Field>Width); per word of the",
        "// window, whether a read or a write of it answers OKAY (ReadableWords, WritableWords).",
        "",
        f"package {PKG_NAME};",
        "",
        "  // Not every constant has a user in every design that imports the package.",
        "  /* verilator lint_off UNUSEDPARAM */",
        "",
        f"  // The window of the map: byte addresses 0 .. 2^BlockAw - 1, {words} words of 32 bits.",
        f"  localparam int BlockAw = {block_aw};",
        "",
        "  // Bit w: the word at byte offset 4 w answers a read with OKAY (a mapped register) or a",
        "  // write with OKAY (a register with a writable field); the other words answer SLVERR.",
        f"  localparam logic [{words - 1}:0] ReadableWords = {bitmap(readable)};",
        f"  localparam logic [{words - 1}:0] WritableWords = {bitmap(writable)};",
    ]
    for r in regs:
        c = camel(r.name)
        where = f"0x{r.offset:02X}" + (f" + {r.stride} j, j = 0 .. {r.count - 1}" if r.count > 1 else "")
        out += ["", f"  // {r.name}{'[j]' if r.count > 1 else ''} ({where}, {r.access})"]
        out.append(f"  localparam logic [BlockAw-1:0] {c}Offset = {block_aw}'h{r.offset:02X};")
        if r.count > 1:
            out.append(f"  localparam int {c}Count = {r.count};")
        if r.reset is not None and r.count == 1:
            out.append(f"  localparam logic [31:0] {c}Reset = 32'h{hex32(r.reset)};")
        for f in r.fields:
            fc = c + camel(f["name"])
            out.append(f"  localparam int {fc}Lsb = {f['lsb']};")
            out.append(f"  localparam int {fc}Width = {f['width']};")
    out += ["", "  /* verilator lint_on UNUSEDPARAM */"]
    # A register of several fields: its value from theirs, each argument as wide as its
    # field (a caller's value of another width is a lint warning, not a silent shift).
    for r in regs:
        if len(r.fields) < 2 or r.count > 1:
            continue
        fn = r.name.lower() + "_value"
        head = f"  function automatic logic [31:0] {fn}("
        args = ["input logic " + ("" if f["width"] == 1 else f"[{f['width'] - 1}:0] ") + f["name"].lower()
                for f in r.fields]
        out += ["", f"  // {r.name}: the register's value from its fields."]
        line = head
        for i, a in enumerate(args):
            piece = a + (");" if i == len(args) - 1 else ", ")
            if len(line) + len(piece.rstrip()) > 100:
                out.append(line.rstrip())
                line = " " * len(head)
            line += piece
        out.append(line)
        out.append(f"    {fn} = '0;")
        for f in r.fields:
            sel = f"[{f['lsb']}]" if f["width"] == 1 else f"[{f['msb']}:{f['lsb']}]"
            out.append(f"    {fn}{sel} = {f['name'].lower()};")
        out.append("  endfunction")
    out += ["", f"endpackage : {PKG_NAME}", ""]
    return "\n".join(out)


def doc_table(regs):
    def bits(f):
        if f["width"] == 1:
            return f"`[{f['lsb']}]`"
        b = f"`[{f['msb']}:{f['lsb']}]`"
        if f["width_param"]:
            assert f["lsb"] == 0, f["name"]
            return f"`[{f['width_param']}-1:0]` ({b})"
        return b

    def fields(r):
        parts = []
        for f in r.fields:
            # A register of one field: the field is the register (its name is the macro's).
            if len(r.fields) == 1:
                full = f["width"] == 32 and not f["width_param"]
                parts.append(f["desc"] if full else f"{bits(f)} {f['desc']}")
                continue
            text = f"{bits(f)} {f['name']}: {f['desc']}"
            if f["constant"] and len(r.fields) > 1:
                text += f" = {f['reset']}"
            parts.append(text)
        body = "; ".join(parts)
        if not r.desc:
            return body
        return f"{r.desc}{': ' if len(r.fields) > 1 else '; '}{body}"

    def reset(r):
        if r.reset is None:
            texts = {f["reset_text"] for f in r.fields if f["reset_text"]}
            return ", ".join(f"`{t}`" for t in sorted(texts)) if texts else "-"
        return "0" if r.reset == 0 else f"`0x{hex32(r.reset)}`"

    rows = [BEGIN,
            "| offset | name | access | reset | fields |",
            "|---|---|---|---|---|"]
    for r in regs:
        if r.count > 1:
            off, name = f"0x{r.offset:02X} + {r.stride} j", f"`{r.name}[j]`, j = 0..{r.count - 1}"
        else:
            off, name = f"0x{r.offset:02X}", f"`{r.name}`"
        rows.append(f"| {off} | {name} | {r.access} | {reset(r)} | {fields(r)} |")
    rows.append(END)
    return "\n".join(rows) + "\n"


def generate(tree, out_dir):
    """Writes the three generated files of tree's map into out_dir (inside the virtual
    environment)."""
    regs, block_aw = load_map(tree)
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, os.path.basename(SV_PKG)), "w") as f:
        f.write(sv_package(regs, block_aw))
    with open(os.path.join(out_dir, DOC_FRAGMENT), "w") as f:
        f.write(doc_table(regs))
    peakrdl = os.path.join(os.path.dirname(sys.executable), "peakrdl")
    header = os.path.join(out_dir, os.path.basename(C_HEADER))
    if subprocess.run([peakrdl, "c-header", os.path.join(tree, RDL), "-o", header]).returncode != 0:
        die(f"peakrdl c-header failed on {RDL}")


# ---------------------------------------------------------------------------------------
# The committed copies: write and check
# ---------------------------------------------------------------------------------------
def doc_section(text):
    """The generated section of docs/interfaces.md: (start, end) character offsets, markers
    included."""
    b = text.find(BEGIN)
    e = text.find(END, b + 1) if b >= 0 else -1
    if b < 0 or e < 0 or text.find(BEGIN, b + 1) >= 0:
        die(f"{DOC} needs exactly one '{BEGIN}' followed by '{END}' (the register-map table)")
    return b, e + len(END) + 1


def run_generation(tree, out_dir):
    bins = install()
    cmd = [os.path.join(bins, "python"), os.path.join(ROOT, "scripts", "regmap.py"), "--generate", out_dir,
           "--root", tree]
    if subprocess.run(cmd).returncode != 0:
        die("the generation failed (messages above)")


def write(tree, tmp):
    run_generation(tree, tmp)
    for path in (SV_PKG, C_HEADER):
        shutil.copyfile(os.path.join(tmp, os.path.basename(path)), os.path.join(tree, path))
        print(f"{ME}: wrote {path}")
    doc = os.path.join(tree, DOC)
    with open(doc) as f:
        text = f.read()
    b, e = doc_section(text)
    with open(os.path.join(tmp, DOC_FRAGMENT)) as f:
        table = f.read()
    with open(doc, "w") as f:
        f.write(text[:b] + table + text[e:])
    print(f"{ME}: wrote {DOC} (the register-map table)")


def stale_copies(tree, out_dir, show_diff=True):
    """The committed copies of tree that differ from what out_dir holds, by name."""
    stale = []

    def compare(name, committed, generated_path):
        with open(generated_path) as f:
            generated = f.read()
        if committed == generated:
            return
        stale.append(name)
        if show_diff:
            diff = difflib.unified_diff(committed.splitlines(), generated.splitlines(),
                                        f"{name} (committed)", generated_path, lineterm="", n=1)
            print("\n".join(list(diff)[:40]), file=sys.stderr)

    for path in (SV_PKG, C_HEADER):
        try:
            with open(os.path.join(tree, path)) as f:
                committed = f.read()
        except FileNotFoundError:
            committed = ""
        compare(path, committed, os.path.join(out_dir, os.path.basename(path)))
    with open(os.path.join(tree, DOC)) as f:
        text = f.read()
    b, e = doc_section(text)
    compare(f"{DOC} (the register-map table)", text[b:e], os.path.join(out_dir, DOC_FRAGMENT))
    return stale


def check(tree, out_dir):
    shutil.rmtree(out_dir, ignore_errors=True)
    run_generation(tree, out_dir)
    stale = stale_copies(tree, out_dir)
    if stale:
        die(f"stale, differs from what {RDL} generates (into {out_dir}): {', '.join(stale)}. "
            "Run `make regmap` and commit.")
    print(f"{ME}: {SV_PKG}, {C_HEADER} and the table of {DOC} match {RDL}")


# Hand edits of each committed copy that --check must catch: (file, text, replacement).
HAND_EDITS = [
    (SV_PKG, "SpanCOffset = 8'h20;", "SpanCOffset = 8'h24;"),
    (C_HEADER, "#define SPECULAR_AXIL__SPAN_C__C_bw 16", "#define SPECULAR_AXIL__SPAN_C__C_bw 17"),
    (DOC, "| 0x20 | `SPAN_C` |", "| 0x24 | `SPAN_C` |"),
]


def selftest(out_dir):
    """--check on copies of the committed files: passes on the copies as they are and on an
    edit of docs/interfaces.md outside the table, fails naming the file on each hand edit."""
    shutil.rmtree(out_dir, ignore_errors=True)
    tree = os.path.join(out_dir, "tree")
    for path in (RDL, SV_PKG, C_HEADER, DOC):
        os.makedirs(os.path.dirname(os.path.join(tree, path)), exist_ok=True)
        shutil.copyfile(os.path.join(ROOT, path), os.path.join(tree, path))
    gen = os.path.join(out_dir, "generated")
    run_generation(tree, gen)
    failures = []
    if stale_copies(tree, gen, show_diff=False):
        die(f"the committed copies are stale already; run {ME} --check first")
    with open(os.path.join(tree, DOC), "a") as f:
        f.write("\nAn edit outside the generated table.\n")
    if stale_copies(tree, gen, show_diff=False):
        failures.append(f"an edit of {DOC} outside the table was taken for a stale table")
    for path, old, new in HAND_EDITS:
        full = os.path.join(tree, path)
        with open(full) as f:
            original = f.read()
        if original.count(old) != 1:
            die(f"self-test: '{old}' is not once in {path}; update HAND_EDITS")
        with open(full, "w") as f:
            f.write(original.replace(old, new))
        stale = stale_copies(tree, gen, show_diff=False)
        named = [n for n in stale if n.startswith(path)]
        print(f"{ME}: self-test: {path} edited ('{old}' -> '{new}'): stale: {', '.join(stale) or 'none'}")
        if len(stale) != 1 or not named:
            failures.append(f"the edit of {path} was not reported as that file's staleness alone")
        with open(full, "w") as f:
            f.write(original)
    if failures:
        die("self-test FAILED: " + "; ".join(failures))
    print(f"{ME}: self-test PASS: every hand edit of a generated copy is caught and named")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    mode = ap.add_mutually_exclusive_group(required=True)
    mode.add_argument("--write", action="store_true", help="rewrite the committed copies")
    mode.add_argument("--check", metavar="DIR", help="generate into DIR, compare with the committed copies")
    mode.add_argument("--selftest", metavar="DIR",
                      help="show, on copies in DIR, that --check catches a hand edit of each copy")
    mode.add_argument("--install", action="store_true", help="only install the tools")
    mode.add_argument("--generate", metavar="DIR", help=argparse.SUPPRESS)  # inside the venv
    ap.add_argument("--root", default=ROOT, help=argparse.SUPPRESS)  # the tree of the map and its copies
    args = ap.parse_args()
    tree = os.path.abspath(args.root)
    if args.generate:
        generate(tree, os.path.abspath(args.generate))
    elif args.install:
        install()
    elif args.check:
        check(tree, os.path.abspath(args.check))
    elif args.selftest:
        selftest(os.path.abspath(args.selftest))
    else:
        tmp = os.path.join(tools_venv.path(), "regmap-last-write")
        shutil.rmtree(tmp, ignore_errors=True)
        write(tree, tmp)


if __name__ == "__main__":
    main()
