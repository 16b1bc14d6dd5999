#!/usr/bin/env python3
"""`collide render` writes an animated GIF with the frame count and size asked for, read back
by Pillow (an independent decoder). Usage: check_render_gif.py COLLIDE SCENE.toml"""
import os
import subprocess
import sys
import tempfile

from PIL import Image


def main():
    collide, scene = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as tmp:
        run = os.path.join(tmp, "run.h5")
        gif = os.path.join(tmp, "run.gif")
        subprocess.run([collide, "run", scene, "--backend", "step", "--frames", "--out", run], check=True,
                       stdout=subprocess.DEVNULL)
        subprocess.run([collide, "render", run, "--out", gif, "--frames", "7", "--size", "200x120"], check=True)
        with Image.open(gif) as image:
            frames, size = image.n_frames, image.size
            # The frames must differ (the disks move), or the animation shows nothing.
            image.seek(0)
            first = image.convert("RGB").tobytes()
            image.seek(frames - 1)
            last = image.convert("RGB").tobytes()
    errors = []
    if frames != 7:
        errors.append(f"expected 7 frames, Pillow reads {frames}")
    if size != (200, 120):
        errors.append(f"expected 200x120 pixels, Pillow reads {size[0]}x{size[1]}")
    if first == last:
        errors.append("the first and last frames are identical")
    for e in errors:
        print("check_render_gif:", e, file=sys.stderr)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
