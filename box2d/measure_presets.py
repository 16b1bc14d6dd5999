#!/usr/bin/env python3
"""The per-setting table of docs/box2d-baseline.md ("Two presets"): the effect of each setting
on which the `tuned` and `shipped` presets differ, measured by switching that one setting from
its tuned value to its shipped one, on three scenes:

  energy   box_gas_1000 (e = 1, 10 s): relative kinetic-energy change K(10)/K(0) - 1
  pile     particle_box (granular disks settling onto stones under gravity, 10 s): kinetic
           energy per disk left at t = 10, disks asleep, largest overlap / contact distance
  speed    100 disks of radius 0.05 in 50 head-on lanes at +-250 per s, dt 1e-3, collision
           phases spread over one step: fraction of pairs that pass through each other, and
           the kinetic energy lost (Box2D's translation cap of 2 m per step)

Usage:  box2d/measure_presets.py [--collide build/release/collide] [--out DIR]
Needs Python 3 with numpy (Debian: python3-numpy) and the `collide` module built beside the
program (build/release/python), whose read_run reads the run files.
"""
import argparse
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.join(HERE, "..", "data", "scenes")
sys.path.insert(0, os.path.join(HERE, "..", "validation", "report"))
from collide_program import collide_module  # noqa: E402


def lanes_scene(lanes=50, radius=0.05, speed=250.0, dt=1e-3):
    """Head-on pairs, one per lane, whose meeting phase within a step runs over one step."""
    disks = []
    for k in range(lanes):
        y = 0.4 * (k + 0.5)
        offset = (k / lanes) * 2 * speed * dt
        disks.append(f"{{ x = 5.0, y = {y:.6f}, vx = {speed}, vy = 0.0, radius = {radius}, mass = 1.0 }}")
        disks.append(f"{{ x = {15.0 + offset:.6f}, y = {y:.6f}, vx = {-speed}, vy = 0.0, radius = {radius}, mass = 1.0 }}")
    return (f'description = "head-on pairs at speed"\nseed = 1\n'
            f'[world]\nbox = [0.0, 0.0, 20.0, {0.4 * lanes}]\nboundary = "reflect"\n'
            f'[run]\nduration = 0.035\noutput_interval = 0.005\ndt = {dt}\n'
            f'[[particles]]\nkind = "list"\ndisks = [ {", ".join(disks)} ]\n')


def run(collide, scene_text, options, path):
    """Runs the scene on box2d with `options` as its [backend.box2d] table; its run file as
    collide.read_run gives it."""
    table = "\n".join(f"{k} = {v}" for k, v in options.items())
    with open(path + ".toml", "w") as f:
        f.write(scene_text + f"\n[backend.box2d]\n{table}\n")
    subprocess.run([collide, "run", path + ".toml", "-b", "box2d", "-o", path + ".h5", "--frames"],
                   check=True, stdout=subprocess.DEVNULL)
    return collide_module(collide).read_run(path + ".h5", frames=True)


def energy_column(f):
    k = f["metrics"]["kinetic_energy"]
    return f"{k[-1] / k[0] - 1:+.2e}"


def pile_column(f):
    k = f["metrics"]["kinetic_energy"]
    moving = np.count_nonzero(f["particles"]["inv_mass"])
    asleep = int(f["stats"]["counters"].get("asleep_bodies", 0))
    return f"{k[-1] / moving:.2e}; {asleep} asleep; overlap {f['metrics']['max_overlap'][-1]:.3f}"


def speed_column(f):
    x = f["positions"][-1, :, 0]
    through = np.mean(x[0::2] > x[1::2])
    k = f["metrics"]["kinetic_energy"]
    return f"{through:.2f} through; K lost {1 - k[-1] / k[0]:.2f}"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--collide", default=os.path.join(HERE, "..", "build", "release", "collide"))
    parser.add_argument("--out", default="box2d-presets")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    scenes = {
        "energy": (open(os.path.join(SCENES, "box_gas_1000.toml")).read(), energy_column),
        "pile": (open(os.path.join(SCENES, "particle_box.toml")).read(), pile_column),
        "speed": (lanes_scene(), speed_column),
    }
    # Switching the threshold alone keeps the tuned scale, so Box2D's 1 m/s is 1/scale in scene
    # units: read the scale each scene gets from a tuned run first.
    rows = [("tuned", {}), ("restitution_threshold", None), ("length_scale", {"length_scale": 1.0}),
            ("sleeping", {"sleeping": "true"}), ("fixed_rotation", {"fixed_rotation": "false"}),
            ("shipped", {"preset": '"shipped"'})]
    print("| switched to shipped | " + " | ".join(scenes) + " |")
    print("|---" * (len(scenes) + 1) + "|")
    scales = {}
    for label, options in rows:
        cells = []
        for name, (text, column) in scenes.items():
            opts = options if options is not None else {"restitution_threshold": 1.0 / scales[name]}
            f = run(args.collide, text, opts, os.path.join(args.out, f"{name}_{label}"))
            if label == "tuned":
                scales[name] = float(f["attributes"]["backend_box2d_length_scale"])
            cells.append(column(f))
        print(f"| {label} | " + " | ".join(cells) + " |", flush=True)


if __name__ == "__main__":
    main()
