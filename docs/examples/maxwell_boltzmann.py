"""Maxwell-Boltzmann from collisions alone (docs/python.md, example 1).

1000 hard disks start with the same speed in random directions: as far from equilibrium as
a gas of that energy can be. Elastic collisions (the exact `event` solver) relax the speeds to
the 2D Maxwell-Boltzmann distribution

    f(v) = (m v / kT) exp(-m v^2 / (2 kT)),    kT = K / N   (two degrees of freedom per disk),

with no thermostat and nothing random after the initial directions. The script samples the
speeds after relaxation, compares their histogram with f(v), prints chi^2 per bin, exits
non-zero if the two disagree, and writes maxwell_boltzmann.png.

    PYTHONPATH=build/release/python python3 docs/examples/maxwell_boltzmann.py [--out DIR]
"""
import argparse
import os
import sys

import numpy as np

import collide

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--out", default=".", help="directory for maxwell_boltzmann.png")
args = parser.parse_args()

N, radius, phi = 1000, 0.5, 0.2
side = float(np.sqrt(N * np.pi * radius**2 / phi))
scene = collide.Scene.from_dict({
    "description": "1000 disks, all at speed 1 in random directions, periodic box, area fraction 0.2",
    "seed": 3,
    "world": {"box": [0.0, 0.0, side, side], "boundary": "periodic"},
    "run": {"duration": 40.0, "output_interval": 1.0},
    "particles": [{"kind": "gas", "count": N, "radius": radius, "mass": 1.0, "velocity": {"speed": 1.0}}],
}, "maxwell_boltzmann")

sim = collide.Simulation(scene, backend="event")
initial_speeds = np.hypot(*sim.velocities.T)
sim.advance_to(10.0)  # relaxation: each disk has collided several times by now
speeds = []
for t in np.arange(12.0, 40.0 + 1e-9, 2.0):  # snapshots 2 time units apart (many collisions between)
    sim.advance_to(float(t))
    speeds.append(np.hypot(*sim.velocities.T))
speeds = np.concatenate(speeds)
collisions_per_disk = 2 * sim.stats()["contacts"] / N

m = 1.0
kT = sim.metrics()["kinetic_energy"] / N  # conserved exactly by elastic collisions: 0.5 here
edges = np.linspace(0.0, 3.5, 36)
counts, _ = np.histogram(speeds, bins=edges)
centres = 0.5 * (edges[1:] + edges[:-1])
width = edges[1] - edges[0]
cdf = 1 - np.exp(-m * edges**2 / (2 * kT))  # exact probability per bin from the CDF of f
expected = len(speeds) * np.diff(cdf)
used = expected > 5
chi2_per_bin = float(np.sum((counts[used] - expected[used]) ** 2 / expected[used]) / used.sum())
print("kT = %.6f, %d speeds from %d snapshots, %.1f collisions per disk" % (
    kT, len(speeds), len(speeds) // N, collisions_per_disk))
print("chi^2 per bin against the 2D Maxwell-Boltzmann curve: %.2f (%d bins)" % (chi2_per_bin, used.sum()))

import matplotlib  # noqa: E402  (after the computation: the plot is optional decoration)
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

v = np.linspace(0, 3.5, 400)
fig, ax = plt.subplots(figsize=(6.4, 4.2))
ax.bar(centres, counts / (len(speeds) * width), width=width * 0.95, color="#8fb8de",
       label="event solver, t = 12..40")
ax.plot(v, m * v / kT * np.exp(-m * v**2 / (2 * kT)), "k-", lw=2,
        label=r"$f(v) = (mv/kT)\,e^{-mv^2/2kT}$, kT = K/N")
ax.axvline(initial_speeds[0], color="#d62728", ls="--", label="every speed at t = 0")
ax.set_xlabel("speed v")
ax.set_ylabel("probability density")
ax.set_title("1000 hard disks relax to Maxwell-Boltzmann (area fraction 0.2)")
ax.legend()
fig.tight_layout()
png = os.path.join(args.out, "maxwell_boltzmann.png")
fig.savefig(png, dpi=110)
print("wrote", png)

# Snapshots 2 time units apart are nearly independent, so chi^2 per bin is about 1; a histogram
# still remembering the initial delta peak would give hundreds.
sys.exit(0 if chi2_per_bin < 3.0 else 1)
