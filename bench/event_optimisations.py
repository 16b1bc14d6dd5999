"""What each speed idea of the tuned `event` buys, against `event-plain` (the same method
written plainly): collisions per second of processor time, one core, a periodic gas at area
fraction 0.3, best of three runs of 1.5 s after one time unit of settling. The tuned solver's
options switch its speed layer off one piece at a time ([backend.event] prefetch,
renumber_interval: reference/event/prefetch_pipeline.h, cell_order_renumbering.h). Results
are the same bits either way (tests).

usage: python3 bench/event_optimisations.py [N]   (from the repository root, after a build;
                                                   N = 100000 by default)
"""
import math
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build", "release", "python"))
import collide  # noqa: E402

N = int(sys.argv[1]) if len(sys.argv) > 1 else 100000
eta, r = 0.3, 0.5
L = math.sqrt(N * math.pi * r * r / eta)
SCENE = f"""description = "periodic gas for the event optimisation bench"
seed = 3
[world]
box = [0.0, 0.0, {L!r}, {L!r}]
boundary = "periodic"
[run]
duration = 1000.0
output_interval = 1.0
dt = 1e-3
[[particles]]
kind = "gas"
count = {N}
radius = 0.5
mass = 1.0
velocity = {{ maxwell = 1.0 }}
"""
VARIANTS = [
    ("event (every optimisation)", "event", {}),
    ("event, prefetch off", "event", {"prefetch": "off"}),
    ("event, never renumbered", "event", {"renumber_interval": "1000000000000"}),
    ("event, prefetch off, never renumbered", "event", {"prefetch": "off", "renumber_interval": "1000000000000"}),
    ("event-plain", "event-plain", {}),
]


def collisions_per_second(scene, backend, options, seconds=1.5, repeats=3):
    """Best of `repeats`: collisions per second of processor time after one time unit."""
    best = 0.0
    for _ in range(repeats):
        sim = collide.Simulation(scene, backend, **options)
        sim.advance_to(1.0)
        start_collisions, start = sim.stats()["contacts"], time.process_time()
        t = 1.0
        while time.process_time() - start < seconds:
            t += 1.0
            sim.advance_to(t)
        best = max(best, (sim.stats()["contacts"] - start_collisions) / (time.process_time() - start))
    return best


def main():
    scene = collide.Scene.from_toml(SCENE)
    rows = [(label, collisions_per_second(scene, backend, options)) for label, backend, options in VARIANTS]
    plain = rows[-1][1]
    print(f"N = {N}, area fraction {eta}, periodic, one core")
    for label, rate in rows:
        print(f"{label:40s} {rate:10.3g} collisions/s  {rate / plain:5.2f} x event-plain")


if __name__ == "__main__":
    main()
