#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The mean FLIP error between two PNG images, as JSON: NVIDIA's perceptual image metric
(LDR-FLIP, Andersson et al., "FLIP: A Difference Evaluator for Alternating Images", 2020)
through the Python package flip-evaluator. Made for the colour images of `render --colour`
(model/scene/compose.hpp): the device's image against the reference.

    scripts/flip_metric.py REFERENCE.png TEST.png

Prints one JSON object on stdout:
    {"reference": PATH, "test": PATH, "width": W, "height": H, "mean_flip": M,
     "ppd": P, "flip_evaluator": VERSION}
M is the mean of the per-pixel FLIP error over the whole image, in [0, 1] (0: identical).
Both images are taken as 8-bit sRGB, as LDR-FLIP assumes of a PNG; the viewing condition is
FLIP's default, P = 67 pixels per degree (0.7 m from a 0.7 m wide display of 3840 pixels).

The pinned flip-evaluator (scripts/flip-requirements.txt) is installed on first use into the
project's virtual environment (scripts/tools_venv.py install flip: build/venv, or SPECULAR_VENV);
the metric runs in that environment's Python. The inputs are checked before, in any Python 3:
each must be a readable, whole PNG file (signature, chunk checksums, a header, image data that
decompresses, an end), and the two of the same size.

Exit status: 0 done; 2 bad input (the message names the file or the argument and what was
expected); 1 the install failed (the message says how to install by hand).
"""

import argparse
import json
import os
import struct
import subprocess
import sys
import zlib

ME = "scripts/flip_metric.py"
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
# Bit depths the PNG specification allows per colour type, and the samples per pixel.
PNG_DEPTHS = {0: (1, 2, 4, 8, 16), 2: (8, 16), 3: (1, 2, 4, 8), 4: (8, 16), 6: (8, 16)}
PNG_SAMPLES = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}


class InputError(Exception):
    """A bad input image: the message names it and what was expected."""


def png_size(path):
    """(width, height) of a whole PNG file; InputError naming the file otherwise."""
    what = f"{path}: expected a whole PNG image"
    if not os.path.exists(path):
        raise InputError(f"{path}: no such file (expected a PNG image)")
    if not os.path.isfile(path):
        raise InputError(f"{path}: not a regular file (expected a PNG image)")
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise InputError(f"{path}: cannot read it ({e.strerror}; expected a readable PNG image)")
    if not data.startswith(PNG_SIGNATURE):
        raise InputError(f"{what}, but it does not start with the PNG signature")
    pos, header, idat, ended = len(PNG_SIGNATURE), None, [], False
    while pos < len(data) and not ended:
        if pos + 12 > len(data):
            raise InputError(f"{what}, but it is cut inside a chunk at byte {pos}")
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        if pos + 12 + length > len(data):
            raise InputError(f"{what}, but its chunk {kind!r} at byte {pos} runs past the end of the file")
        (crc,) = struct.unpack(">I", data[pos + 8 + length:pos + 12 + length])
        if zlib.crc32(kind + body) & 0xFFFFFFFF != crc:
            raise InputError(f"{what}, but the checksum of its chunk {kind!r} at byte {pos} is wrong")
        if header is None and kind != b"IHDR":
            raise InputError(f"{what}, but its first chunk is {kind!r}, not the header IHDR")
        if kind == b"IHDR":
            if length != 13:
                raise InputError(f"{what}, but its header IHDR has {length} bytes, not 13")
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            ended = True
        pos += 12 + length
    if header is None or not ended:
        raise InputError(f"{what}, but it has no {'header IHDR' if header is None else 'end chunk IEND'}")
    w, h, depth, colour, compression, filtering, interlace = header
    if not (w > 0 and h > 0 and colour in PNG_DEPTHS and depth in PNG_DEPTHS[colour] and compression == 0
            and filtering == 0 and interlace in (0, 1)):
        raise InputError(f"{what}, but its header IHDR is not valid ({w} x {h}, colour type {colour}, "
                         f"bit depth {depth}, compression {compression}, filter {filtering}, interlace {interlace})")
    try:
        raw = zlib.decompress(b"".join(idat))
    except zlib.error as e:
        raise InputError(f"{what}, but its image data does not decompress ({e})")
    if interlace == 0:
        row = 1 + (w * PNG_SAMPLES[colour] * depth + 7) // 8
        if len(raw) != h * row:
            raise InputError(f"{what}, but its image data has {len(raw)} bytes where {w} x {h} needs {h * row}")
    return w, h


def evaluate(reference, test):
    """Runs inside the virtual environment: the mean FLIP of the two checked images."""
    from importlib import metadata

    import flip_evaluator as flip

    _, mean, parameters = flip.evaluate(reference, test, "LDR")
    return float(mean), float(parameters["ppd"]), metadata.version("flip-evaluator")


def main():
    ap = argparse.ArgumentParser(prog=ME, description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("reference", help="the reference image (PNG)")
    ap.add_argument("test", help="the image compared with it (PNG), of the same size")
    ap.add_argument("--evaluate", action="store_true", help=argparse.SUPPRESS)  # inside the venv
    a = ap.parse_args()
    try:
        size_ref = png_size(a.reference)
        size_test = png_size(a.test)
    except InputError as e:
        print(f"{ME}: {e}", file=sys.stderr)
        return 2
    if size_ref != size_test:
        print(f"{ME}: {a.test}: expected an image of the reference's size {size_ref[0]} x {size_ref[1]} "
              f"({a.reference}), got {size_test[0]} x {size_test[1]}", file=sys.stderr)
        return 2
    if a.evaluate:
        mean, ppd, version = evaluate(a.reference, a.test)
        print(json.dumps({"reference": a.reference, "test": a.test, "width": size_ref[0], "height": size_ref[1],
                          "mean_flip": mean, "ppd": ppd, "flip_evaluator": version}))
        return 0
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import tools_venv  # scripts/tools_venv.py, beside this file

    try:
        bins = tools_venv.bin_dir("flip")
    except tools_venv.VenvError as e:
        print(f"{ME}: {e}", file=sys.stderr)
        return 1
    return subprocess.run([os.path.join(bins, "python"), os.path.abspath(__file__), "--evaluate",
                           a.reference, a.test]).returncode


if __name__ == "__main__":
    sys.exit(main())
