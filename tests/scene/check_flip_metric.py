#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""ctest scene_flip_metric: scripts/flip_metric.py (the mean FLIP of two PNGs, through the pinned
flip-evaluator it installs into the build's virtual environment) on small images whose FLIP is
known without FLIP's code:

  * identical images (a gradient, so that FLIP's edge and point detectors see structure): exactly 0;
  * uniform images: FLIP's edge and point detectors respond to nothing in a uniform image, so the
    feature term is 0 and the per-pixel error is the colour term alone (Andersson et al., "FLIP: A
    Difference Evaluator for Alternating Images", HPG 2020, section 4): the two colours decoded
    from sRGB, in CIE L*a*b* (D65, the white of linear RGB (1, 1, 1)), a* and b* scaled by 0.01 L*
    (the Hunt effect), their HyAB distance |dL| + sqrt(da^2 + db^2) raised to q_c = 0.7, and mapped
    by the paper's compression: e / (p_c c_max) p_t below p_c c_max, p_t + (e - p_c c_max) /
    (c_max - p_c c_max) (1 - p_t) above, with p_c = 0.4, p_t = 0.95 and c_max the same distance
    between pure green and pure blue. The spatial filters keep a uniform image as it is. So black
    against white is 0.9674 (past the knee: near 1), grey code 128 against 129 is 0.0299 (one code,
    30 times smaller), and a chromatic pair is checked too; FLIP computes in single precision, so
    the match is to 0.1 %;
  * bad input: a missing file, a file that is not a whole PNG, two sizes: exit 2 naming the file.

Usage: check_flip_metric.py (SPECULAR_VENV names the environment; default build/venv).
Exit 0 when every check passes, 1 otherwise.
"""
import json
import math
import os
import struct
import subprocess
import sys
import tempfile
import zlib

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, "scripts", "flip_metric.py")
ME = "tests/scene/check_flip_metric.py"


def write_png(path, w, h, pixel):
    """An 8-bit RGB PNG of pixel(x, y) -> (r, g, b), filter 0 on every row."""
    rows = b"".join(b"\x00" + b"".join(bytes(pixel(x, y)) for x in range(w)) for y in range(h))

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


# ---- FLIP of two uniform images from the paper's colour pipeline -------------------------------
def srgb_decode(e):
    return e / 12.92 if e <= 0.04045 else ((e + 0.055) / 1.055) ** 2.4


# Linear sRGB to CIE XYZ (IEC 61966-2-1, D65).
RGB_TO_XYZ = [[0.4124564, 0.3575761, 0.1804375], [0.2126729, 0.7151522, 0.0721750], [0.0193339, 0.1191920, 0.9503041]]


def xyz(rgb):
    return [sum(RGB_TO_XYZ[i][j] * rgb[j] for j in range(3)) for i in range(3)]


def hunt_lab(linear_rgb):
    """CIE L*a*b* relative to the white of linear RGB (1, 1, 1), a* and b* times 0.01 L*."""
    white = xyz([1.0, 1.0, 1.0])
    d = 6.0 / 29.0

    def f(t):
        return t ** (1.0 / 3.0) if t > d ** 3 else t / (3 * d * d) + 4.0 / 29.0

    fx, fy, fz = (f(v / w) for v, w in zip(xyz(linear_rgb), white))
    L, a, b = 116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)
    return L, 0.01 * L * a, 0.01 * L * b


def hyab(p, q):
    return abs(p[0] - q[0]) + math.hypot(p[1] - q[1], p[2] - q[2])


def flip_uniform(code1, code2):
    qc, pc, pt = 0.7, 0.4, 0.95
    cmax = hyab(hunt_lab([0.0, 1.0, 0.0]), hunt_lab([0.0, 0.0, 1.0])) ** qc
    e = hyab(hunt_lab([srgb_decode(c / 255) for c in code1]), hunt_lab([srgb_decode(c / 255) for c in code2])) ** qc
    return pt * e / (pc * cmax) if e < pc * cmax else pt + (e - pc * cmax) / (cmax - pc * cmax) * (1 - pt)


# ---- the checks ---------------------------------------------------------------------------------
def run(*args):
    p = subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def main():
    failures = []

    def check(ok, what):
        print(f"{ME}: {'ok  ' if ok else 'FAIL'} {what}")
        if not ok:
            failures.append(what)

    with tempfile.TemporaryDirectory(prefix="flip_metric_") as d:
        def img(name, pixel, w=32, h=32):
            path = os.path.join(d, name + ".png")
            write_png(path, w, h, pixel)
            return path

        gradient = img("gradient", lambda x, y: (8 * x, 8 * y, 255 - 4 * (x + y)))
        gradient2 = img("gradient2", lambda x, y: (8 * x, 8 * y, 255 - 4 * (x + y)))
        uniform = {c: img("u%d_%d_%d" % c, lambda x, y, c=c: c) for c in
                   [(0, 0, 0), (255, 255, 255), (128, 128, 128), (129, 129, 129), (200, 30, 40), (190, 60, 40)]}

        code, out, err = run(gradient, gradient2)
        check(code == 0, f"identical images: exit 0 (got {code}; {err.strip()})")
        if code != 0:
            return 1  # the install or the tool failed: nothing below can pass
        r = json.loads(out)
        check(r["mean_flip"] == 0.0, f"identical images: mean FLIP exactly 0 (got {r['mean_flip']})")
        check((r["width"], r["height"]) == (32, 32), "the JSON gives the image size")

        means = {}
        for a, b in [((0, 0, 0), (255, 255, 255)), ((128, 128, 128), (129, 129, 129)), ((200, 30, 40), (190, 60, 40))]:
            code, out, err = run(uniform[a], uniform[b])
            got = json.loads(out)["mean_flip"] if code == 0 else float("nan")
            want = flip_uniform(a, b)
            means[(a, b)] = got
            check(abs(got - want) <= 1e-3 * want,
                  f"uniform {a} against {b}: mean FLIP {got:.6f}, closed form {want:.6f} (within 0.1 %)")
        bw, one = means[((0, 0, 0), (255, 255, 255))], means[((128, 128, 128), (129, 129, 129))]
        check(bw > 0.95 and one < bw / 20,
              f"black against white {bw:.4f} is past the knee (> 0.95) and 20 times a one-code difference ({one:.4f})")

        missing = os.path.join(d, "missing.png")
        code, _, err = run(missing, gradient)
        check(code == 2 and missing in err and "no such file" in err, f"a missing file: exit 2 naming it ({code}: {err.strip()})")
        cut = os.path.join(d, "cut.png")
        with open(gradient, "rb") as f, open(cut, "wb") as g:
            g.write(f.read()[:60])
        code, _, err = run(gradient, cut)
        check(code == 2 and cut in err and "whole PNG" in err, f"a cut PNG: exit 2 naming it ({code}: {err.strip()})")
        small = img("small", lambda x, y: (0, 0, 0), 16, 32)
        code, _, err = run(gradient, small)
        check(code == 2 and small in err and "32 x 32" in err, f"two sizes: exit 2 naming them ({code}: {err.strip()})")

    if failures:
        print(f"{ME}: FAILED: {len(failures)} check(s)")
        return 1
    print(f"{ME}: PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
