"""A long-lived outside solver for test_long_lived_suite.py (docs/your-solver.md, "A solver that
serves many calls"): started as `long_lived_solver.py LOG --serve`, it answers request directory
after request directory read from stdin, letting every disk fly straight (a trivial answer of the
right shape and times), and appends "start PID" and "exit PID" to LOG, so the test can count its
starts and see that it read end of file. It misbehaves by the case's seed: 3 kills itself
(SIGSEGV), 5 hangs; every other seed is answered."""
import os
import signal
import sys
import time

import numpy as np


def log(path, word):
    with open(path, "a") as f:
        f.write(f"{word} {os.getpid()}\n")


def answer(directory):
    request = {}
    for line in open(os.path.join(directory, "request.txt")):
        key, _, rest = line.strip().partition(" ")
        request[key] = rest
    seed = int(request["seed"])
    print(f"request seed {seed}", file=sys.stderr, flush=True)
    if seed == 3:
        # Dies by signal 11 whatever handler the process was given (a sanitized build's tests
        # preload AddressSanitizer into every process they start, and it catches SIGSEGV).
        signal.signal(signal.SIGSEGV, signal.SIG_DFL)
        os.kill(os.getpid(), signal.SIGSEGV)
    if seed == 5:
        time.sleep(600)
    initial = np.load(os.path.join(directory, "initial.npy"))
    start = float(request["start_time"])
    times = [float(t) for t in request["output_times"].split()]
    states = np.array([np.column_stack([initial[:, 0:2] + initial[:, 2:4] * (t - start), initial[:, 2:4]]) for t in times])
    np.save(os.path.join(directory, "states.npy"), states)
    with open(os.path.join(directory, "result.txt"), "w") as f:
        f.write("times " + " ".join(request["output_times"].split()) + "\nseconds 0.001\n")


def main():
    log_path, mode = sys.argv[1], sys.argv[2]
    if mode != "--serve":
        answer(mode)
        return
    log(log_path, "start")
    for line in sys.stdin:
        answer(line.rstrip("\n"))
        print("done", flush=True)
    log(log_path, "exit")


main()
