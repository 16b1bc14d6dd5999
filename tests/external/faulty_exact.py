"""Known-wrong exact solvers: the shipped exact solver (docs/examples/solvers/exact_disks.py)
with one fault each, all of which declare themselves exact. The suite exact_solvers.toml must
fail every one of them in every scene where its fault acts (docs/your-solver.md, "An exact
solver"; test_exact_solvers.py). Each fault acts early, at the first event it can touch, and
says so once on its output ("fault acts: ..."), which collide keeps in the case's log: the test
reads it to know in which scenes the fault acted.

    restitution  every pair collision with restitution 0.995 (the energy drops at each)
    skip         pair collision number 1, 1001, 2001, ... is not performed: the two disks pass
                 through each other until they are apart again
    wall         the first wall contact is missed: that disk flies on through that wall
    late         every pair collision happens 1e-9 after its time (the disks overlap by
                 1e-9 times their approach speed, and everything after is shifted)
"""

import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "docs" / "examples" / "solvers"))

from exact_disks import NEVER, ExactDisks  # noqa: E402

FAULTS = ("restitution", "skip", "wall", "late")
WRONG_RESTITUTION = 0.995
SKIP_EVERY = 1000
LATE_BY = 1e-9


class FaultyExact(ExactDisks):
    fault = None                          # one of FAULTS, set by the classes below

    def load(self, scene, initial):
        self.acted = False
        self.passing = set()              # pairs let through each other ("skip")
        self.missed = set()               # (disk, (axis, side)) walls let through ("wall")
        super().load(scene, initial)

    def acts(self, what):
        """Says once, on the case's log, that the fault changed the run."""
        if not self.acted:
            print("fault acts: %s: %s at t = %r" % (self.fault, what, self.now), flush=True)
            self.acted = True

    def pair_event(self, i, j):
        number = self.pair_collisions + 1
        if self.fault == "skip" and (number - 1) % SKIP_EVERY == 0:
            self.pair_collisions += 1
            self.passing.add((i, j))
            self.acts("pair collision %d (disks %d and %d) skipped" % (number, i, j))
            self.pair_time[i, j] = NEVER      # re-predicted at i's or j's next event
            return
        if self.fault == "late":
            self.acts("pair collision %d (disks %d and %d) %g late" % (number, i, j, LATE_BY))
        super().pair_event(i, j)

    def collide(self, i, j, restitution=1.0):
        if self.fault == "restitution":
            self.acts("pair collision %d (disks %d and %d) with restitution %g" % (self.pair_collisions, i, j, WRONG_RESTITUTION))
            restitution = WRONG_RESTITUTION
        super().collide(i, j, restitution)

    def pair_delay(self, i, j):
        if (i, j) in self.passing:
            d, shifts = self.separation(i, j)
            reach = self.radius[i] + self.radius[j]
            if min((d + s) @ (d + s) for s in shifts) <= reach * reach * (1 + 1e-9):
                return NEVER                  # still inside each other (or just touching)
            self.passing.discard((i, j))
        delay = super().pair_delay(i, j)
        return delay + LATE_BY if self.fault == "late" and delay < NEVER else delay

    def wall_event(self, i):
        if self.fault == "wall" and not self.periodic and not self.missed:
            self.missed.add((i, self.wall[i]))
            self.acts("wall contact of disk %d (axis %d, side %+d) missed" % (i, *self.wall[i]))
            self.predict(i)
            return
        super().wall_event(i)

    def wall_delays(self, i):
        return [(t, w) for t, w in super().wall_delays(i) if (i, w) not in self.missed]


class Restitution(FaultyExact):
    fault = "restitution"
    version = "exact-disks 1, restitution %g" % WRONG_RESTITUTION


class SkipEvery1000(FaultyExact):
    fault = "skip"
    version = "exact-disks 1, pair collision 1 of every %d skipped" % SKIP_EVERY


class MissFirstWall(FaultyExact):
    fault = "wall"
    version = "exact-disks 1, first wall contact missed"


class LateCollisions(FaultyExact):
    fault = "late"
    version = "exact-disks 1, pair collisions %g late" % LATE_BY
