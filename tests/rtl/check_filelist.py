#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""ctest rtl_filelist: the IP filelists (rtl/README.md#filelists) against the tree.

Fails when
  - a filelist does not expand (a missing file, a bad line, a source named twice, a cycle);
  - an IP's filelist names a source or an include directory outside its own folder (its
    dependencies come in by `-f`, never by naming their files);
  - a .sv or .svh file under rtl/ belongs to no IP: a .sv file not named by the filelist of
    its folder, a .svh file whose folder is no include directory of it (formal harnesses in a
    formal/ folder and the harnesses of rtl/fpga/ are not synthesizable sources);
  - the product filelist rtl/specular.f reaches a file of rtl/competitors/.
This is the one place that walks rtl/, on purpose: every build reads a filelist instead.

  check_filelist.py ROOT IP_FILELIST...
  check_filelist.py --self-test
"""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import rtl_filelist  # noqa: E402

PRODUCT = "rtl/specular.f"
COMPETITORS = "rtl/competitors/"
HARNESS_DIRS = ("formal", "fpga")


def check(root, ip_filelists):
    errors = []
    owned_sv, owned_inc = set(), set()
    for f in ip_filelists:
        try:
            exp = rtl_filelist.expand([f], root)
        except rtl_filelist.FilelistError as e:
            errors.append(str(e))
            continue
        folder = os.path.dirname(f)
        for s, owner in exp.owner.items():
            if owner == f:
                if os.path.dirname(s) != folder:
                    errors.append(f"{f}: names {s}, outside its folder {folder}/ (name that IP's filelist with -f)")
                owned_sv.add(s)
        for d, owner in exp.incdir_owner.items():
            if owner == f:
                if d != folder:
                    errors.append(f"{f}: +incdir+{d} is outside its folder {folder}/")
                owned_inc.add(d)
    try:
        product = rtl_filelist.expand([PRODUCT], root)
        for s in product.sources:
            if s.startswith(COMPETITORS):
                errors.append(f"{PRODUCT} reaches {s} (through {product.owner[s]}): the competitors are not the product")
    except rtl_filelist.FilelistError as e:
        errors.append(str(e))

    checked = 0
    for dirpath, dirnames, filenames in os.walk(os.path.join(root, "rtl")):
        rel = os.path.relpath(dirpath, root)
        if os.path.basename(rel) in HARNESS_DIRS:
            dirnames[:] = []
            continue
        for name in sorted(filenames):
            path = os.path.join(rel, name)
            if name.endswith(".sv"):
                checked += 1
                if path not in owned_sv:
                    errors.append(f"{path} is in no IP's filelist (add it to the .f of {rel}/, in compile order)")
            elif name.endswith(".svh") and rel not in owned_inc:
                errors.append(f"{path}: {rel} is the +incdir+ of no IP's filelist")
    return errors, checked


def self_test():
    """A copy of a small tree, broken in each way the check must catch."""
    def tree(files):
        d = tempfile.mkdtemp()
        for p, text in files.items():
            os.makedirs(os.path.join(d, os.path.dirname(p)), exist_ok=True)
            with open(os.path.join(d, p), "w") as fh:
                fh.write(text)
        return d
    good = {
        "rtl/prim/prim.f": "+incdir+rtl/prim\nrtl/prim/a.sv\n", "rtl/prim/a.sv": "", "rtl/prim/m.svh": "",
        "rtl/core/core.f": "-f rtl/prim/prim.f\nrtl/core/b.sv\n", "rtl/core/b.sv": "",
        "rtl/core/formal/b_fv.sv": "",
        "rtl/competitors/x/x.f": "-f rtl/core/core.f\nrtl/competitors/x/x.sv\n", "rtl/competitors/x/x.sv": "",
        "rtl/specular.f": "-f rtl/core/core.f\n",
    }
    ips = ["rtl/prim/prim.f", "rtl/core/core.f", "rtl/competitors/x/x.f"]
    cases = [
        ("good", {}, None),
        ("unlisted source", {"rtl/core/c.sv": ""}, "rtl/core/c.sv is in no IP's filelist"),
        ("missing source", {"rtl/core/core.f": "-f rtl/prim/prim.f\nrtl/core/b.sv\nrtl/core/gone.sv\n"}, "does not exist"),
        ("foreign source", {"rtl/core/core.f": "rtl/prim/a.sv\nrtl/core/b.sv\n",
                            "rtl/prim/prim.f": "+incdir+rtl/prim\n"}, "outside its folder"),
        ("competitor in product", {"rtl/specular.f": "-f rtl/competitors/x/x.f\n"}, "the competitors are not the product"),
        ("stray header", {"rtl/core/n.svh": ""}, "rtl/core is the +incdir+ of no IP's filelist"),
        ("cycle", {"rtl/prim/prim.f": "-f rtl/core/core.f\n+incdir+rtl/prim\nrtl/prim/a.sv\n"}, "a cycle"),
        ("twice", {"rtl/core/core.f": "-f rtl/prim/prim.f\nrtl/core/b.sv\nrtl/core/b.sv\n"}, "already named"),
    ]
    failed = 0
    for name, change, expect in cases:
        d = tree({**good, **change})
        try:
            errors, _ = check(d, ips)
        finally:
            shutil.rmtree(d)
        ok = (not errors) if expect is None else any(expect in e for e in errors)
        print(f"self-test {name}: {'ok' if ok else 'FAILED'}" + ("" if ok else f" ({errors})"))
        failed += not ok
    return 1 if failed else 0


def main(argv):
    if argv[1:] == ["--self-test"]:
        return self_test()
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    root, ips = argv[1], argv[2:]
    errors, checked = check(root, ips)
    if errors:
        print("rtl_filelist: FAIL\n  " + "\n  ".join(errors))
        return 1
    print(f"rtl_filelist: OK: {len(ips)} IP filelists, {checked} synthesizable .sv files under rtl/, each in its IP's filelist")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
