#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Break-even plot of scene_bench (model/bench/scene_bench.cpp, docs/system.md): ns per pixel
against span length for the device method (batched setup included) and per-pixel SLEEF
Phong, on synthetic spans with a constant halfway vector.

usage: scripts/plot_break_even.py SCENE_BENCH.json OUT.png
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def break_even_pixels(data):
    """Pixels per span (l + 1) from which the device is at or below phong_sleef, or None."""
    l = data.get("break_even_l")
    return None if l is None else l + 1


def plot(data, out):
    rows = data.get("break_even", [])
    if not rows:
        raise ValueError("no break_even rows in the scene_bench JSON (run without --no-break-even)")
    px = [r["pixels_per_span"] for r in rows]
    fig, ax = plt.subplots(figsize=(8, 5))
    ax.plot(px, [r["device"] for r in rows], "o-", ms=3, color="tab:blue",
            label="device method (setup_batch automatic + AVX2 shading)")
    ax.plot(px, [r["phong_sleef"] for r in rows], "s-", ms=3, color="tab:orange",
            label="per-pixel Phong, AVX2 + SLEEF powf8 (constant H)")
    # The same at one instruction set, when measured.
    for key, style, color, label in (("device_avx2", "--", "tab:blue", "device, AVX2 throughout"),
                                     ("device_avx512", ":", "tab:blue", "device, AVX-512 throughout"),
                                     ("phong_sleef_avx512", ":", "tab:orange", "Phong, AVX-512 + SLEEF powf16")):
        if key in rows[0]:
            ax.plot(px, [r[key] for r in rows], style, lw=1.2, color=color, label=label)
    be = break_even_pixels(data)
    if be is not None:
        ax.axvline(be, color="grey", ls="--", lw=1)
        ax.text(be, 0.6, f" break-even (solid lines): {be} pixels per span", color="grey", fontsize=9,
                transform=ax.get_xaxis_transform(), va="top")
    for s in data.get("scenes", []):  # where the scenes sit on the length axis (those inside it)
        if s["mean_span"] <= px[-1]:
            ax.axvline(s["mean_span"], color="tab:green", ls=":", lw=0.8)
            ax.text(s["mean_span"], 0.02, " " + s["scene"], rotation=90, fontsize=7, color="tab:green",
                    transform=ax.get_xaxis_transform(), va="bottom")
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xlabel("pixels per span (l + 1), log scale; dotted: mean span of the scenes in this range")
    ax.set_ylabel("ns per pixel (this run)")
    ax.set_title("Device method with its setup against per-pixel Phong")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7.5, loc="upper right")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    try:
        with open(argv[1]) as f:
            data = json.load(f)
        plot(data, argv[2])
    except (OSError, ValueError, KeyError) as e:
        print(f"plot_break_even.py: error: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
