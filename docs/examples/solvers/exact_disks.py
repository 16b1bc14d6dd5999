"""An exact event-driven solver for elastic hard disks in NumPy, written from the physics alone
(no collide code): an outside solver for `collide validate` (docs/your-solver.md, "An exact
solver").

Between collisions every disk moves on a straight line, so the whole motion is known once the
next event is: the earliest of all pair contacts (a quadratic in time for every pair), wall
contacts (reflecting box) and boundary crossings (periodic box). The solver jumps to it,
applies the elastic collision rule to the one or two disks involved, predicts again the times
of the events those disks take part in, and repeats: O(N) predictions per event and an O(N^2)
search of the table of times, which is all a few-body scene needs (Alder & Wainwright,
J. Chem. Phys. 31, 459 (1959); Rapaport, "The Art of Molecular Dynamics Simulation", ch. 14).

Each disk keeps its own clock (position x0 at time t0): its position at time t is
x0 + v (t - t0), evaluated only when the disk takes part in an event or is read out, so a disk
that flies freely is not rounded at every event of the others.

Stones (mass given, "stone" set) have inverse mass 0 and never move. Scenes with gravity,
damping, friction or restitution below 1 are refused: the motion between events is then no
longer a straight line, or inelastic collapse needs a model of its own.

    collide validate tests/external/exact_solvers.toml --out results/exact --jobs 2

runs it, and four known-wrong copies of it (tests/external/faulty_exact.py), against `event`.
"""

import numpy as np

NEVER = np.inf


class ExactDisks:
    version = "exact-disks 1"
    exact = True                      # event-driven: no time step, contacts at their times

    def refuses(self, scene):
        for key in ("gravity_x", "gravity_y", "damping", "friction"):
            if scene.get(key, 0.0) != 0.0:
                return "an exact solver for straight-line motion only (the scene has %s = %g)" % (key, scene[key])
        for key in ("restitution", "wall_restitution"):
            if scene.get(key, 1.0) != 1.0:
                return "elastic collisions only (the scene has %s = %g)" % (key, scene[key])
        return None

    # ---- state -------------------------------------------------------------------------------

    def load(self, scene, initial):
        self.x0, self.v = initial["positions"].copy(), initial["velocities"].copy()
        n = len(self.x0)
        self.t0 = np.full(n, scene["start_time"])          # each disk's own clock
        self.now = scene["start_time"]
        self.radius = initial["radius"]
        self.inverse_mass = np.where(initial["stone"], 0.0, 1.0 / initial["mass"])
        self.v[initial["stone"]] = 0.0
        self.lo = np.array([scene["xmin"], scene["ymin"]])
        self.hi = np.array([scene["xmax"], scene["ymax"]])
        self.periodic = scene["boundary"] == "periodic"
        # The times of every predicted event: pair (i < j) contacts, and per disk its next wall
        # contact or boundary crossing (which wall: axis 0/1 and side -1/+1).
        self.pair_time = np.full((n, n), NEVER)
        self.wall_time = np.full(n, NEVER)
        self.wall = [(0, 0)] * n
        self.pair_collisions = self.wall_contacts = 0
        for i in range(n):
            self.predict(i)

    def position(self, i, t):
        return self.x0[i] + self.v[i] * (t - self.t0[i])

    def bring_to(self, i, t):
        """Moves disk i's clock to t (before its velocity changes)."""
        self.x0[i] = self.position(i, t)
        self.t0[i] = t

    @property
    def positions(self):
        return self.x0 + self.v * (self.now - self.t0)[:, None]

    @property
    def velocities(self):
        return self.v

    def stats(self):
        return {"contacts": self.pair_collisions}

    # ---- prediction --------------------------------------------------------------------------

    def separation(self, i, j):
        """x_j - x_i now, and in a periodic box the image shifts to try (the 3 x 3 nearest)."""
        d = self.position(j, self.now) - self.position(i, self.now)
        if not self.periodic:
            return d, [np.zeros(2)]
        size = self.hi - self.lo
        return d, [size * (a, b) for a in (-1, 0, 1) for b in (-1, 0, 1)]

    def contact_delay(self, d, dv, reach):
        """Time until |d + dv t| first equals reach, or NEVER: the smaller root of
        a t^2 + 2 b t + c = 0 (a = dv.dv, b = d.dv, c = d.d - reach^2), written as
        c / (-b + sqrt(b^2 - a c)) so that nothing cancels when the disks are far apart
        (Numerical Recipes 3rd ed., section 5.6). Only approaching pairs (b < 0) meet; a pair
        found overlapping by rounding (c < 0) while approaching meets at once."""
        b = d @ dv
        if b >= 0.0:
            return NEVER
        a, c = dv @ dv, d @ d - reach * reach
        discriminant = b * b - a * c
        if discriminant < 0.0:
            return NEVER
        return max(c / (-b + np.sqrt(discriminant)), 0.0)

    def pair_delay(self, i, j):
        """Time from now until disks i and j touch (the earliest periodic image), or NEVER."""
        if self.inverse_mass[i] + self.inverse_mass[j] == 0.0:
            return NEVER                                     # two stones pass each other by
        d, shifts = self.separation(i, j)
        dv, reach = self.v[j] - self.v[i], self.radius[i] + self.radius[j]
        return min(self.contact_delay(d + s, dv, reach) for s in shifts)

    def wall_delays(self, i):
        """Each wall disk i flies towards, with the time from now until it touches it (reflecting
        box) or its centre crosses that edge (periodic box): [(delay, (axis, side)), ...]."""
        x = self.position(i, self.now)
        inset = 0.0 if self.periodic else self.radius[i]
        out = []
        for axis in (0, 1):
            u = self.v[i, axis]
            if u < 0.0:
                out.append((max((self.lo[axis] + inset - x[axis]) / u, 0.0), (axis, -1)))
            elif u > 0.0:
                out.append((max((self.hi[axis] - inset - x[axis]) / u, 0.0), (axis, +1)))
        return out

    def wall_delay(self, i):
        return min(self.wall_delays(i), default=(NEVER, (0, 0)))

    def predict(self, i):
        """Every event disk i takes part in, from now on."""
        for j in range(len(self.x0)):
            if j != i:
                self.pair_time[min(i, j), max(i, j)] = self.now + self.pair_delay(min(i, j), max(i, j))
        self.pair_time[i, i] = NEVER
        delay, self.wall[i] = self.wall_delay(i)
        self.wall_time[i] = self.now + delay

    # ---- events ------------------------------------------------------------------------------

    def advance_to(self, t):
        while True:
            pair = np.unravel_index(np.argmin(self.pair_time), self.pair_time.shape)
            wall = int(np.argmin(self.wall_time))
            first = min(self.pair_time[pair], self.wall_time[wall])
            if first > t:
                break
            self.now = first
            if self.pair_time[pair] <= self.wall_time[wall]:
                self.pair_event(int(pair[0]), int(pair[1]))
            else:
                self.wall_event(wall)
        self.now = t

    def pair_event(self, i, j):
        self.pair_collisions += 1
        self.bring_to(i, self.now)
        self.bring_to(j, self.now)
        self.collide(i, j)
        self.predict(i)
        self.predict(j)

    def collide(self, i, j, restitution=1.0):
        """The collision rule: an impulse along the line of centres n that reverses the normal
        relative velocity (times the restitution e), shared by inverse mass:
            v_i' = v_i + (1 + e) w_i / (w_i + w_j) ((v_j - v_i).d / d.d) d,   d = x_j - x_i,
        and the opposite for j, with w = 1/m (0 for a stone). Momentum is conserved exactly,
        and at e = 1 so is the kinetic energy."""
        d, shifts = self.separation(i, j)
        d = min((d + s for s in shifts), key=lambda e: e @ e)    # the image that touches
        dv = self.v[j] - self.v[i]
        push = (1.0 + restitution) * (dv @ d) / (d @ d) / (self.inverse_mass[i] + self.inverse_mass[j]) * d
        self.v[i] += self.inverse_mass[i] * push
        self.v[j] -= self.inverse_mass[j] * push

    def wall_event(self, i):
        self.bring_to(i, self.now)
        axis, side = self.wall[i]
        if self.periodic:                                    # re-enter at the opposite edge
            self.x0[i, axis] += (self.lo[axis] - self.hi[axis]) * side
        else:
            self.wall_contacts += 1
            self.reflect(i, axis)
        self.predict(i)

    def reflect(self, i, axis):
        """A reflecting wall reverses the normal velocity (elastic wall)."""
        self.v[i, axis] = -self.v[i, axis]
