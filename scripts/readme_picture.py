#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""The README's picture: one scene rendered in colour through the RTL beside its reference.

Runs `sim_regression` on one scene only, the default build (its scene and colour stages,
sim/README.md and docs/colour.md: spans of the rasterized scene through the batched setup into
`specular_stream` under Verilator, every pixel checked against the golden model; the colour
image composed around the RTL's intensities) and puts three of the images it writes side by side,
pixel for pixel:

  <scene>_colour_rtl.png          the RTL's intensities composed in colour (every light)
  <scene>_colour_registers.png    the same composition around C cos^n(psi) of the RTL's own
                                  registers in double (what the device's budget bounds)
  <scene>_colour_device_diff.png  their difference in 8-bit sRGB codes, amplified, with its range
(the composition around the material's BRDF, which adds the setup's error, is
<scene>_colour_reference.png; the caption gives both differences)

--grey draws the grey images instead (<scene>_rtl, _float, _device_error). Run from the repository
root, so that the RTL's ROM paths resolve (rtl/README.md, "ROM files"):

usage: scripts/readme_picture.py --sim build/bin/sim_regression [--scene scenes/duck_colour.json]
                                 [--grey] [--out docs/img/readme_scene.png]
`make readme-picture` runs it.
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

PANELS = {
    "colour": [("colour_rtl", "RTL: specular_stream (Verilator), composed"),
               ("colour_registers", "C cos^n(psi) of its registers, double"),
               ("colour_device_diff", "RTL - C cos^n(psi), sRGB codes")],
    "grey": [("rtl", "RTL: specular_stream (Verilator)"),
             ("float", "reference: C cos^n(psi), double"),
             ("device_error", "RTL - C cos^n(psi) of its registers")],
}
GAP = 8      # pixels between the panels
TITLE = 22   # pixels of the title band above them
BG = "#1c1f2b"


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sim", required=True, help="the sim_regression binary")
    ap.add_argument("--scene", default="scenes/duck_colour.json", help="the scene (JSON, scenes/README.md)")
    ap.add_argument("--grey", action="store_true", help="the grey images: RTL, C cos^n(psi), the device error")
    ap.add_argument("--out", default="docs/img/readme_scene.png", help="the PNG to write")
    a = ap.parse_args(argv)

    name = os.path.splitext(os.path.basename(a.scene))[0]
    panels = PANELS["grey" if a.grey else "colour"]
    with tempfile.TemporaryDirectory() as tmp:
        scenes = os.path.join(tmp, "scenes")
        images = os.path.join(tmp, "images")
        os.makedirs(scenes)
        shutil.copy(a.scene, scenes)  # the scene alone (a model file path would need the original folder)
        # The smallest run that renders the scene: the default build only, no random lines,
        # no stream or system stage (the colour stage runs with the scenes).
        cmd = [a.sim, "--config", "default", "--random", "0", "--stream-spans", "0", "--system-spans", "0",
               "--scenes-dir", scenes, "--images-dir", images]
        run = subprocess.run(cmd, capture_output=True, text=True)
        if run.returncode != 0:
            sys.stderr.write(run.stdout[-3000:] + run.stderr[-3000:])
            print(f"readme_picture: {' '.join(cmd)} failed ({run.returncode})", file=sys.stderr)
            return 1
        imgs = [mpimg.imread(os.path.join(images, f"{name}_{kind}.png")) for kind, _ in panels]

    width = sum(im.shape[1] for im in imgs) + GAP * (len(imgs) + 1)
    height = max(im.shape[0] for im in imgs) + TITLE + GAP
    dpi = 100
    fig = plt.figure(figsize=(width / dpi, height / dpi), dpi=dpi, facecolor=BG)
    x = GAP
    for im, (_, title) in zip(imgs, panels):
        h, w = im.shape[:2]
        # axes in figure fractions, placed on whole pixels: one image pixel per PNG pixel
        ax = fig.add_axes([x / width, (height - TITLE - h) / height, w / width, h / height])
        ax.imshow(im, interpolation="nearest")
        ax.set_axis_off()
        fig.text((x + w / 2) / width, (height - TITLE / 2) / height, title, color="white",
                 ha="center", va="center", fontsize=9, family="DejaVu Sans")
        x += w + GAP
    os.makedirs(os.path.dirname(a.out) or ".", exist_ok=True)
    fig.savefig(a.out, dpi=dpi, facecolor=BG, metadata={"Software": None})
    print(f"readme_picture: {a.out} ({name}, {width} x {height}, {os.path.getsize(a.out)} bytes)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
