#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""The pages of docs/ are design documents: what, why, the contracts, the error analyses and the
alternatives rejected (docs/README.md). The figures a run measured, with the commit, date and
machine of the run, are on one page, docs/results.md, generated from the JSON of the runs
(scripts/results_page.py), and history is in git. This check fails when a page of docs/ other
than docs/results.md reads like a run diary or a history: it names the machine or its load, CPU
or wall-clock seconds of a build or a test, before/after or trial rows, the session a figure was
measured in, a commit of the history (but the one line citing a superseded design,
"superseded: commit HASH"), or what the design no longer is.

    check_design_only.py ROOT [--exclude PAGE ...]   (PAGE relative to ROOT)
    check_design_only.py --self-test
"""
import argparse
import glob
import os
import re
import shutil
import sys
import tempfile

GENERATED = "docs/results.md"  # the results page: runs, machines and dates belong there

# (regular expression, what it means); case-insensitive, matched across line breaks.
PHRASES = [
    (r"\bthis machine\b", "names the machine"),
    (r"\bthe same (?:two-core )?machine\b", "names the machine"),
    (r"\bmachine (?:shared|otherwise|was|ran|loaded)\b", "the machine's load"),
    (r"\bquiet machine\b", "the machine's load"),
    (r"\bshared with\b", "the machine's load ('shared with')"),
    (r"\bshared (?:its|the) (?:two )?(?:cores|machine)\b", "the machine's load"),
    (r"\bnothing else running\b", "the machine's load"),
    (r"\bload about \d", "the machine's load"),
    (r"\bnice -n\b", "how a run was scheduled"),
    (r"\bCPU s\b", "CPU seconds of a run"),
    (r"\bCPU seconds\b", "CPU seconds of a run"),
    (r"\bwall[- ](?:clock|time)s?\b", "wall-clock time of a run"),
    (r"\bseconds on two cores\b", "run time of a run"),
    (r"\b\d+ min \d+ s\b", "run time of a run"),
    (r"\bfresh clone\b", "a timed run of the build"),
    (r"\btrials?\b", "a trial row"),
    (r"\bbefore:", "a before/after row"),
    (r"\"before\"", "a before/after row"),
    (r"\bbefore/after\b", "a before/after row"),
    (r"\(before\)", "a before/after column"),
    (r"\bin one session\b|\bthe session's\b", "the session of a run"),
    (r"\btoday(?:'s)?\b", "the date of a run"),
    # History belongs to git: a page describes what is built, not what it was before.
    (r"(?<!superseded: )\bcommits? `?[0-9a-f]{7,40}\b", "a commit of the history (the one citing line of a "
                                                         "superseded design reads 'superseded: commit HASH')"),
    (r"\bno longer\b|\bused to be\b|\bpreviously\b|\bformerly\b|\bat the time\b", "history"),
    (r"\b(?:was|were) (?:then )?(?:replaced|taken out|reverted)\b", "history"),
]


def pages(root, exclude):
    out = []
    for p in sorted(glob.glob(os.path.join(root, "docs", "**", "*.md"), recursive=True)):
        rel = os.path.relpath(p, root).replace(os.sep, "/")
        if rel != GENERATED and rel not in exclude:
            out.append(rel)
    return out


def check(root, exclude):
    errors = []
    for rel in pages(root, exclude):
        with open(os.path.join(root, rel), encoding="utf-8") as f:
            text = f.read()
        for pat, why in PHRASES:
            for m in re.finditer(pat, text, re.IGNORECASE):
                line = text.count("\n", 0, m.start()) + 1
                errors.append(f"{rel}:{line}: '{m.group(0)}' ({why}): a design page states no run; "
                              f"measured figures go to {GENERATED} (scripts/results_page.py), history to git")
    return errors


def self_test():
    """A clean page passes; each phrase planted in a page fails, naming the page; the generated page
    and an excluded page are not read."""
    failures = []
    tmp = tempfile.mkdtemp(prefix="design_only_")
    try:
        os.makedirs(os.path.join(tmp, "docs", "measured"))
        clean = ("# A design page\n\nThe table of 9 address bits errs 0.3 % ([results](results.md#x)); the "
                 "shared ROM serves both banks. Registers are written while idle. Rejected: the old design (the "
                 "Q44 setup, superseded: commit b49e795).\n")

        def write(rel, text):
            with open(os.path.join(tmp, rel), "w") as f:
                f.write(text)

        write("docs/README.md", clean)
        write("docs/measured/README.md", clean)
        write(GENERATED, "Run: commit `abc1234`, this machine, 14 min 3 s, shared with another job.\n")
        write("docs/formal.md", "Measured on this machine.\n")
        if check(tmp, {"docs/formal.md"}):
            failures.append(f"a clean tree fails: {check(tmp, {'docs/formal.md'})}")
        if not check(tmp, set()):
            failures.append("a phrase in a page not excluded is not caught (docs/formal.md)")
        planted = ["measured on this machine", "the machine shared with another job", "56.4 CPU s",
                   "the wall time of a run", "48 seconds on two cores", "| `Q36` trial | 5,873 |",
                   "Before: 51.1", "| value (before) |", "14 min 18 s", "a fresh clone took", "measured the same way today",
                   "built in commit `ac63d59`", "the span slice is no longer needed", "the loop was replaced by a tree",
                   "the counter previously took a stage"]
        for phrase in planted:
            write("docs/measured/README.md", clean + "\n" + phrase + "\n")
            errs = check(tmp, {"docs/formal.md"})
            if not any(e.startswith("docs/measured/README.md:") for e in errs):
                failures.append(f"the planted phrase '{phrase}' is not caught")
        write("docs/measured/README.md", clean)
    finally:
        shutil.rmtree(tmp)
    for f in failures:
        print(f"check_design_only self-test: FAIL: {f}", file=sys.stderr)
    if not failures:
        print("check_design_only self-test: OK (a clean tree passes, every planted phrase is caught)")
    return 1 if failures else 0


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("root", nargs="?", help="repository root")
    ap.add_argument("--exclude", action="append", default=[], metavar="PAGE",
                    help="a page not to check (repeatable)")
    ap.add_argument("--self-test", action="store_true")
    a = ap.parse_args(argv)
    if a.self_test:
        return self_test()
    if not a.root:
        ap.error("ROOT is required")
    for rel in a.exclude:
        if not os.path.isfile(os.path.join(a.root, rel)):
            print(f"check_design_only: excluded page {rel} does not exist", file=sys.stderr)
            return 2
    errors = check(a.root, set(a.exclude))
    for e in errors:
        print(e, file=sys.stderr)
    n = len(pages(a.root, set(a.exclude)))
    if errors:
        print(f"check_design_only: FAIL ({len(errors)} run or machine phrases in {n} pages)", file=sys.stderr)
        return 1
    print(f"check_design_only: OK ({n} pages, no run or machine phrase)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
