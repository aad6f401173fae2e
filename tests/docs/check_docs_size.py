#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""The size cap of the design documents: every page of docs/ (docs/*.md) but the generated
docs/results.md, and every README.md of the tree, at most PAGE_CAP bytes, the top-level README.md
(a newcomer's first page) at most README_CAP; the pages of docs/
together, docs/results.md included, at most TOTAL_CAP bytes. A design page states what, why, the
contract, the error analysis and the decision; history is in git and measured figures are on
docs/results.md, so a page over the cap holds something that belongs elsewhere.

usage: check_docs_size.py ROOT          exit 1 naming every page over its cap, with its size
       check_docs_size.py --self-test   pages over each cap must fail, a tree within them pass
"""
import os
import sys
import tempfile

PAGE_CAP = 30 * 1024    # bytes, a page of docs/ or a README.md
README_CAP = 8 * 1024   # bytes, the top-level README.md: results and design belong in docs/
TOTAL_CAP = 150 * 1024  # bytes, docs/*.md together
GENERATED = "docs/results.md"


def readmes(root):
    """Every README.md of the tree; hidden folders and build folders (a CMakeCache.txt) aside."""
    out = []
    for d, dirs, files in os.walk(root):
        dirs[:] = sorted(x for x in dirs if not x.startswith(".")
                         and not os.path.exists(os.path.join(d, x, "CMakeCache.txt")))
        if "README.md" in files:
            out.append(os.path.relpath(os.path.join(d, "README.md"), root))
    return out


def check(root):
    """Messages, one per page over its cap (empty: within every cap)."""
    docs = os.path.join(root, "docs")
    if not os.path.isdir(docs):
        return [f"{root}: no docs/ folder"]
    pages = sorted(f"docs/{f}" for f in os.listdir(docs) if f.endswith(".md"))
    size = {p: os.path.getsize(os.path.join(root, p)) for p in set(pages) | set(readmes(root))}
    errors = []
    for p in sorted(size):
        if p != GENERATED and size[p] > PAGE_CAP:
            errors.append(f"{p}: {size[p]:,} bytes, over the cap of {PAGE_CAP:,} bytes (30 KB) a page; "
                          f"move history to git and measured figures to docs/results.md")
    if size.get("README.md", 0) > README_CAP:
        errors.append(f"README.md: {size['README.md']:,} bytes, over the cap of {README_CAP:,} bytes (8 KB) of the "
                      f"top-level README; move results to docs/results.md and design to docs/")
    total = sum(size[p] for p in pages)
    if total > TOTAL_CAP:
        errors.append(f"docs/*.md: {total:,} bytes together ({len(pages)} pages, {GENERATED} included), over the "
                      f"cap of {TOTAL_CAP:,} bytes (150 KB); the largest: "
                      + ", ".join(f"{p} {size[p]:,}" for p in sorted(pages, key=lambda p: -size[p])[:3]))
    return errors


def self_test():
    failures = []

    def tree(tmp, files):
        for rel, n in files.items():
            os.makedirs(os.path.dirname(os.path.join(tmp, rel)), exist_ok=True)
            with open(os.path.join(tmp, rel), "w") as f:
                f.write("x" * n)

    # The paths are joined from their parts so that the link check does not take them for references.
    page, readme, sim_readme = os.path.join("docs", "a.md"), "README.md", os.path.join("sim", "README.md")
    big = {os.path.join("docs", f"p{i}.md"): 30000 for i in range(6)}
    cases = [
        # (what, files and sizes, text every failure message must contain; None: must pass)
        ("a tree within the caps", {page: PAGE_CAP, readme: README_CAP, GENERATED: 40000,
                                    os.path.join("build", "x", "README.md"): PAGE_CAP + 1,
                                    os.path.join("build", "CMakeCache.txt"): 1}, None),
        ("a docs page over the cap", {page: PAGE_CAP + 1, readme: 100}, f"{page}: {PAGE_CAP + 1:,} bytes"),
        ("a folder README over the cap", {page: 10, sim_readme: 40000}, f"{sim_readme}: 40,000 bytes"),
        ("the top-level README over its cap", {page: 10, readme: README_CAP + 1},
         f"README.md: {README_CAP + 1:,} bytes, over the cap of {README_CAP:,}"),
        ("docs/ over the total", big, "docs/*.md: 180,000 bytes together"),
        ("the generated page counts in the total", dict(list(big.items())[:4], **{GENERATED: 40000}),
         "docs/*.md: 160,000 bytes together"),
    ]
    for what, files, must in cases:
        with tempfile.TemporaryDirectory() as tmp:
            tree(tmp, files)
            errs = check(tmp)
        if must is None:
            if errs:
                failures.append(f"{what}: fails: {errs}")
            else:
                print(f"self-test: {what}: passes")
        elif len(errs) != 1 or must not in errs[0]:
            failures.append(f"{what}: expected one message naming '{must}', got {errs}")
        else:
            print(f"self-test: {what}: fails as it must: {errs[0]}")
    return failures


def main(argv):
    if argv == ["--self-test"]:
        failures = self_test()
        for f in failures:
            print(f"check_docs_size self-test: {f}", file=sys.stderr)
        print("check_docs_size self-test: " + ("FAIL" if failures else "PASS"))
        return 1 if failures else 0
    if len(argv) != 1:
        print(__doc__, file=sys.stderr)
        return 2
    errors = check(argv[0])
    for e in errors:
        print(e, file=sys.stderr)
    print(f"check_docs_size: {'FAIL' if errors else 'PASS'} ({len(errors)} problems)")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
