#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""ctest rtl_filelist: the IP manifests and filelists (rtl/README.md#filelists) against the tree.

Each IP is given by its filelist rtl/X/X.f (or its manifest rtl/X/X.manifest); the manifest
beside the filelist is the IP's source. Fails when
  - a manifest does not expand (a missing file, a bad line, a source named twice, a cycle);
  - an IP's manifest names a source or an include directory outside its own folder (its
    dependencies come in by `needs:`, never by naming their files);
  - an IP's filelist is not what tools read as it is: it names another filelist (`-f`), or its
    include directories and sources are not those of its manifest, in the same order (a stale
    or hand-edited list: edit the manifest, run `make filelists`);
  - a .sv or .svh file under rtl/ belongs to no IP: a .sv file not named by the manifest of
    its folder, a .svh file whose folder is no include directory of it (formal harnesses in a
    formal/ folder and the harnesses of rtl/fpga/ are not synthesizable sources);
  - the product (rtl/specular.manifest, and its list rtl/specular.f) reaches a file of
    rtl/competitors/.
This is the one place that walks rtl/, on purpose: every build reads a filelist instead.
(That every generated file is byte for byte what its manifest generates is the ctest
filelists_up_to_date; the self-test covers its check too.)

  check_filelist.py ROOT IP_FILELIST...
  check_filelist.py --self-test
"""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import rtl_filelist  # noqa: E402

PRODUCT = "rtl/specular.manifest"
COMPETITORS = "rtl/competitors/"
HARNESS_DIRS = ("formal", "fpga")


def manifest_of(f):
    """The manifest of an IP named by its filelist or its manifest."""
    if f.endswith(rtl_filelist.MANIFEST_EXT):
        return f
    if f.endswith(".f"):
        return f[:-len(".f")] + rtl_filelist.MANIFEST_EXT
    return None


def check_flat(root, flat, manifest_exp, errors):
    """The filelist `flat` is what tools read as it is: no -f, the manifest's expansion."""
    try:
        exp = rtl_filelist.expand([flat], root)
    except rtl_filelist.FilelistError as e:
        errors.append(str(e))
        return None
    if exp.filelists != [flat]:
        errors.append(f"{flat}: names {', '.join(exp.filelists[1:])} with -f: a tool reads a nested list "
                      "against another folder (Icarus) or reads a shared one twice; run `make filelists`")
    elif (exp.incdirs, exp.sources) != (manifest_exp.incdirs, manifest_exp.sources):
        missing = [x for x in manifest_exp.incdirs + manifest_exp.sources if x not in exp.incdirs + exp.sources]
        extra = [x for x in exp.incdirs + exp.sources if x not in manifest_exp.incdirs + manifest_exp.sources]
        what = (f"lacks {', '.join(missing)}" if missing else "") + ("; " if missing and extra else "") + \
               (f"names {', '.join(extra)}, which its manifest does not" if extra else "")
        errors.append(f"{flat} is not what its manifest expands to ({what or 'another order'}): edit the "
                      "manifest, not the list, and run `make filelists`")
    return exp


def check(root, ip_filelists):
    errors = []
    owned_sv, owned_inc = set(), set()
    for f in ip_filelists:
        m = manifest_of(f)
        if m is None or not os.path.isfile(os.path.join(root, m)):
            errors.append(f"{f}: no manifest {m} beside it (the IP's source: rtl/README.md#filelists)")
            continue
        try:
            exp = rtl_filelist.expand([m], root)
        except rtl_filelist.FilelistError as e:
            errors.append(str(e))
            continue
        if f != m:
            check_flat(root, f, exp, errors)
        folder = os.path.dirname(m)
        for s, owner in exp.owner.items():
            if owner == m:
                if os.path.dirname(s) != folder:
                    errors.append(f"{m}: names {s}, outside its folder {folder}/ (name that IP's manifest with needs:)")
                owned_sv.add(s)
        for d, owner in exp.incdir_owner.items():
            if owner == m:
                if d != folder:
                    errors.append(f"{m}: +incdir+{d} is outside its folder {folder}/")
                owned_inc.add(d)
    try:
        product = rtl_filelist.expand([PRODUCT], root)
        for s in product.sources:
            if s.startswith(COMPETITORS):
                errors.append(f"{PRODUCT} reaches {s} (through {product.owner[s]}): the competitors are not the product")
        flat = rtl_filelist.Manifest(PRODUCT).flat_path
        product_flat = check_flat(root, flat, product, errors)
        for s in (product_flat.sources if product_flat else []):
            if s.startswith(COMPETITORS) and s not in product.sources:
                errors.append(f"{flat} names {s}: the competitors are not the product")
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
                    errors.append(f"{path} is in no IP's manifest (add it to the .manifest of {rel}/, in compile "
                                  "order, and run `make filelists`)")
            elif name.endswith(".svh") and rel not in owned_inc:
                errors.append(f"{path}: {rel} is the +incdir+ of no IP's manifest")
    return list(dict.fromkeys(errors)), checked  # a broken manifest once, not once per IP needing it


def self_test():
    """A copy of a small tree, broken in each way the checks must catch."""
    def tree(files):
        d = tempfile.mkdtemp()
        for p, text in files.items():
            os.makedirs(os.path.join(d, os.path.dirname(p)), exist_ok=True)
            with open(os.path.join(d, p), "w") as fh:
                fh.write(text)
        return d
    head = "description: x\ntop: t\n"
    good = {
        "CMakeLists.txt": "project(specular_device VERSION 1.2.3)\n",
        "rtl/prim/prim.manifest": head + "+incdir+rtl/prim\nrtl/prim/a.sv\n", "rtl/prim/a.sv": "",
        "rtl/prim/m.svh": "",
        "rtl/core/core.manifest": head + "needs: rtl/prim/prim.manifest\nrtl/core/b.sv\n", "rtl/core/b.sv": "",
        "rtl/core/formal/b_fv.sv": "",
        "rtl/competitors/x/x.manifest": head + "needs: rtl/core/core.manifest\nrtl/competitors/x/x.sv\n",
        "rtl/competitors/x/x.sv": "",
        "rtl/specular.manifest": head + "needs: rtl/core/core.manifest\n",
    }
    ips = ["rtl/prim/prim.f", "rtl/core/core.f", "rtl/competitors/x/x.f"]
    cases = [
        ("good", {}, None),
        ("unlisted source", {"rtl/core/c.sv": ""}, "rtl/core/c.sv is in no IP's manifest"),
        ("missing source", {"rtl/core/core.manifest": head + "needs: rtl/prim/prim.manifest\nrtl/core/b.sv\n"
                            "rtl/core/gone.sv\n"}, "does not exist"),
        ("foreign source", {"rtl/core/core.manifest": head + "rtl/prim/a.sv\nrtl/core/b.sv\n",
                            "rtl/prim/prim.manifest": head + "+incdir+rtl/prim\n"}, "outside its folder"),
        ("competitor in product", {"rtl/specular.manifest": head + "needs: rtl/competitors/x/x.manifest\n"},
         "the competitors are not the product"),
        ("competitor in the product's list", {"rtl/specular.f": "+incdir+rtl/prim\nrtl/prim/a.sv\nrtl/core/b.sv\n"
                                              "rtl/competitors/x/x.sv\n"}, "the competitors are not the product"),
        ("stray header", {"rtl/core/n.svh": ""}, "rtl/core is the +incdir+ of no IP's manifest"),
        ("cycle", {"rtl/prim/prim.manifest": head + "needs: rtl/core/core.manifest\n+incdir+rtl/prim\nrtl/prim/a.sv\n"},
         "a cycle"),
        ("twice", {"rtl/core/core.manifest": head + "needs: rtl/prim/prim.manifest\nrtl/core/b.sv\nrtl/core/b.sv\n"},
         "named twice"),
        ("stale list", {"rtl/core/core.f": "+incdir+rtl/prim\nrtl/prim/a.sv\n"}, "lacks rtl/core/b.sv"),
        ("list not flat", {"rtl/core/core.f": "-f rtl/prim/prim.f\nrtl/core/b.sv\n"}, "with -f"),
        ("repeat in a list", {"rtl/core/core.f": "+incdir+rtl/prim\nrtl/prim/a.sv\nrtl/core/b.sv\nrtl/prim/a.sv\n"},
         "already named by rtl/core/core.f"),
        ("no manifest", {"rtl/core/core.manifest": None}, "no manifest rtl/core/core.manifest"),
    ]
    failed = 0
    for name, change, expect in cases:
        d = tree(good)
        try:
            rtl_filelist.write_generated(rtl_filelist.generate(d), d)
            for p, text in change.items():
                if text is None:
                    os.remove(os.path.join(d, p))
                else:
                    with open(os.path.join(d, p), "w") as fh:
                        fh.write(text)
            errors, _ = check(d, ips)
        finally:
            shutil.rmtree(d)
        ok = (not errors) if expect is None else any(expect in e for e in errors)
        print(f"self-test {name}: {'ok' if ok else 'FAILED'}" + ("" if ok else f" ({errors})"))
        failed += not ok

    # The up-to-date check (scripts/rtl_filelist.py --check): a manifest changed without
    # regenerating leaves its list and core stale, and a hand-edited core is stale too.
    for name, path, text, expect in [
            ("stale after a manifest edit", "rtl/core/core.manifest",
             head + "top: u\nneeds: rtl/prim/prim.manifest\nrtl/core/b.sv\n", {"rtl/core/core.core"}),
            ("stale after a new source", "rtl/core/core.manifest",
             head + "needs: rtl/prim/prim.manifest\nrtl/core/b.sv\nrtl/core/c.sv\n",
             {"rtl/core/core.f", "rtl/core/core.core", "rtl/specular.f", "rtl/competitors/x/x.f"}),
            ("hand-edited core", "rtl/prim/prim.core", "CAPI=2:\nname: x\n", {"rtl/prim/prim.core"}),
            ("core of no manifest", "rtl/old/old.core", "CAPI=2:\nname: x\n", {"rtl/old/old.core"})]:
        d = tree({**good, "rtl/core/c.sv": ""})
        try:
            rtl_filelist.write_generated(rtl_filelist.generate(d), d)
            os.makedirs(os.path.dirname(os.path.join(d, path)), exist_ok=True)
            with open(os.path.join(d, path), "w") as fh:
                fh.write(text)
            stale = {rel for rel, _ in rtl_filelist.stale(rtl_filelist.generate(d), d)}
            if path.endswith(".core"):
                fresh = set()
            else:
                rtl_filelist.write_generated(rtl_filelist.generate(d), d)
                fresh = {rel for rel, _ in rtl_filelist.stale(rtl_filelist.generate(d), d)}
        finally:
            shutil.rmtree(d)
        ok = stale == expect and not fresh
        print(f"self-test {name}: {'ok' if ok else 'FAILED'}" + ("" if ok else f" (stale {stale}, after regenerating {fresh})"))
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
    print(f"rtl_filelist: OK: {len(ips)} IP filelists, each its manifest's expansion; {checked} synthesizable "
          ".sv files under rtl/, each in its IP's manifest; the product reaches no competitor")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
