"""A small exact (event-driven) solver for few disks in a reflecting box, for
test_declared_claims.py: O(N^2) prediction of the next pair or wall collision, straight flights
between them. `Exact` declares itself exact; `LossyExact` is the same with a restitution of
0.995 at every pair collision (1 % of a head-on pair's energy lost), also declared exact;
`LossyUndeclared` is that one declaring nothing."""
import math

import numpy as np


class Exact:
    exact = True                 # event-driven: judged at rounding level (docs/your-solver.md)
    restitution = 1.0

    def load(self, scene, initial):
        self.box = (scene["xmin"], scene["ymin"], scene["xmax"], scene["ymax"])
        self.x = initial["positions"].copy()
        self.v = initial["velocities"].copy()
        self.r = initial["radius"].copy()
        self.m = initial["mass"].copy()
        self.t = scene["start_time"]
        self.contacts = 0

    def _pair_time(self, i, j):
        d, u = self.x[i] - self.x[j], self.v[i] - self.v[j]
        b, s = d @ u, self.r[i] + self.r[j]
        if b >= 0:
            return math.inf
        a, c = u @ u, d @ d - s * s
        disc = b * b - a * c
        return math.inf if disc < 0 else max(c / (-b + math.sqrt(disc)), 0.0)

    def _wall_time(self, i):
        best = (math.inf, None)
        for axis in (0, 1):
            v = self.v[i, axis]
            if v > 0:
                best = min(best, ((self.box[axis + 2] - self.r[i] - self.x[i, axis]) / v, axis))
            elif v < 0:
                best = min(best, ((self.box[axis] + self.r[i] - self.x[i, axis]) / v, axis))
        return best

    def advance_to(self, t):
        n = len(self.r)
        while True:
            dt, event = math.inf, None
            for i in range(n):
                w, axis = self._wall_time(i)
                if w < dt:
                    dt, event = w, ("wall", i, axis)
                for j in range(i + 1, n):
                    p = self._pair_time(i, j)
                    if p < dt:
                        dt, event = p, ("pair", i, j)
            if self.t + dt > t:
                self.x += self.v * (t - self.t)
                self.t = t
                return
            self.x += self.v * dt
            self.t += dt
            if event[0] == "wall":
                self.v[event[1], event[2]] *= -1
            else:
                i, j = event[1], event[2]
                d = self.x[i] - self.x[j]
                g = -(1 + self.restitution) * (d @ (self.v[i] - self.v[j])) / ((d @ d) * (1 / self.m[i] + 1 / self.m[j]))
                self.v[i] += g / self.m[i] * d
                self.v[j] -= g / self.m[j] * d
                self.contacts += 1

    @property
    def positions(self):
        return self.x

    @property
    def velocities(self):
        return self.v

    def stats(self):
        return {"steps": 0, "contacts": self.contacts}


class LossyExact(Exact):
    restitution = 0.995


class LossyUndeclared(LossyExact):
    exact = False                # the same dynamics, claiming nothing
