#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Include direction of the model's layers (model/CMakeLists.txt): every quoted #include of a
source in model/<layer>/ must name a header of the same layer or of one below it, in the order
reference < setup < device < host < scene < tools, bench. The build already refuses an upward
include (a layer's include path holds only its own folder and those below); this check names
the offending file, line and layers. Exit 1 on a violation.

Usage: check_layers.py ROOT | --self-test
"""
import os
import re
import sys
import tempfile

LAYERS = ["reference", "setup", "device", "host", "scene", "tools", "bench"]
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def header_layers(model):
    """header file name -> layer that holds it."""
    out = {}
    for layer in LAYERS:
        d = os.path.join(model, layer)
        if os.path.isdir(d):
            for name in os.listdir(d):
                out[name] = layer
    return out


def check(root):
    model = os.path.join(root, "model")
    where = header_layers(model)
    bad = []
    for layer in LAYERS:
        d = os.path.join(model, layer)
        if not os.path.isdir(d):
            continue
        for name in sorted(os.listdir(d)):
            path = os.path.join(d, name)
            if not os.path.isfile(path) or not re.search(r"\.(cpp|hpp|inl)$", name):
                continue
            with open(path, encoding="utf-8", errors="replace") as fh:
                for ln, line in enumerate(fh, 1):
                    m = INCLUDE.match(line)
                    if not m:
                        continue
                    target = where.get(os.path.basename(m.group(1)))
                    if target and LAYERS.index(target) > LAYERS.index(layer):
                        bad.append(f"model/{layer}/{name}:{ln}: includes {m.group(1)} of the {target} layer, "
                                   f"above {layer} (order: {' < '.join(LAYERS)})")
    return bad


def self_test():
    with tempfile.TemporaryDirectory() as root:
        for layer, name, text in [("reference", "a.hpp", ""), ("device", "d.hpp", '#include "a.hpp"\n'),
                                  ("reference", "bad.cpp", '#include "d.hpp"\n'),
                                  ("scene", "s.cpp", '#include "d.hpp"\n#include "a.hpp"\n')]:
            os.makedirs(os.path.join(root, "model", layer), exist_ok=True)
            with open(os.path.join(root, "model", layer, name), "w") as fh:
                fh.write(text)
        bad = check(root)
        ok = len(bad) == 1 and bad[0].startswith("model/reference/bad.cpp:1: includes d.hpp of the device layer")
        print("\n".join(bad))
        print("self-test " + ("passed: the one upward include found" if ok else "FAILED"))
        return 0 if ok else 1


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    if sys.argv[1] == "--self-test":
        return self_test()
    bad = check(sys.argv[1])
    for b in bad:
        print(b)
    print(f"check_layers: {len(bad)} upward includes")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
