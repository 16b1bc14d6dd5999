"""A protocol-2 solver that writes no `contacts` line (and no `seconds`): disks fly straight and
reflect off the walls. tests/engines/test_engines.py runs it to see collision_rate left out."""
import sys

import numpy as np

directory = sys.argv[1]
request = {}
for line in open(f"{directory}/request.txt"):
    words = line.split()
    if words:
        request[words[0]] = words[1:]
state = np.load(f"{directory}/initial.npy")
x, v, r = state[:, 0:2].copy(), state[:, 2:4].copy(), state[:, 4:5]
low = np.array([float(request["xmin"][0]), float(request["ymin"][0])])
high = np.array([float(request["xmax"][0]), float(request["ymax"][0])])
t, times, out = float(request["start_time"][0]), [float(w) for w in request["output_times"]], []
dt = float(request["dt"][0])
for target in times:
    while t < target - 1e-12:
        x += dt * v
        hit = (x - r < low) | (x + r > high)
        v[hit] *= -1
        t += dt
    out.append(np.hstack([x, v]))
np.save(f"{directory}/states.npy", np.array(out))
with open(f"{directory}/result.txt", "w") as f:
    f.write("times " + " ".join(request["output_times"]) + "\n")
