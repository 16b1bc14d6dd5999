"""The collide-first stepping rule (docs/stepping-rules.md, section 5) in vectorised NumPy: an
outside solver for `collide validate` (docs/your-solver.md). Per step of dt: every overlapping
pair's contact share from one snapshot (position split by inverse mass, the restitution
impulse on approaching pairs, Coulomb friction), summed and applied; then x += v dt,
v += (g - gamma v) dt; then the walls. Stones (mass given, "stone" set) never move.

    collide validate numpy_stepper.toml --out results     (the suite beside this file)
"""

import numpy as np


class NumPyStepper:
    version = "numpy-stepper 1"
    rule = "collide-first"            # judged as the built-in stepped backends are

    def refuses(self, scene):
        if scene["order"] != "collide-first":
            return "only the collide-first order (the scene asks for %s)" % scene["order"]
        return None

    def load(self, scene, initial):
        self.s = scene
        self.x, self.v = initial["positions"].copy(), initial["velocities"].copy()
        self.r, self.stone = initial["radius"], initial["stone"]
        self.w = np.where(self.stone, 0.0, 1.0 / initial["mass"])   # inverse masses, 0 for stones
        self.lo = np.array([scene["xmin"], scene["ymin"]])
        self.size = np.array([scene["xmax"], scene["ymax"]]) - self.lo
        self.cells = np.maximum((self.size // (2 * self.r.max())).astype(int), 1)  # cell edge >= 2 r_max
        self.step_count = round(scene["start_time"] / scene["dt"])
        self.steps = self.contacts = 0

    def advance_to(self, t):
        while self.step_count < round(t / self.s["dt"]):
            self.step()
            self.step_count += 1

    def candidate_pairs(self):
        """Every (i, j), i != j, whose cells are neighbours (periodic cells wrap)."""
        c = np.clip(((self.x - self.lo) / self.size * self.cells).astype(int), 0, self.cells - 1)
        cell = c[:, 0] * self.cells[1] + c[:, 1]
        order = np.argsort(cell, kind="stable")
        starts = np.searchsorted(cell[order], np.arange(self.cells.prod() + 1))
        i_all, j_all = [], []
        for ox in (-1, 0, 1):
            for oy in (-1, 0, 1):
                n = c + (ox, oy)
                if self.s["boundary"] == "periodic":
                    n %= self.cells
                inside = np.all((n >= 0) & (n < self.cells), axis=1)
                i, nc = np.nonzero(inside)[0], n[inside, 0] * self.cells[1] + n[inside, 1]
                count = starts[nc + 1] - starts[nc]
                first = np.repeat(starts[nc] - np.cumsum(count) + count, count)
                i_all.append(np.repeat(i, count))
                j_all.append(order[first + np.arange(count.sum())])
        i, j = np.concatenate(i_all), np.concatenate(j_all)
        keep = (i != j) & ~self.stone[i]          # a stone's own share is always zero
        # Sorted by (i, j) and each pair once (a grid under 3 cells wide sees a cell twice): the
        # sums below then add each disk's contacts in the order of c_stepper.c's loop.
        key = np.unique(i[keep] * len(self.x) + j[keep])
        return key // len(self.x), key % len(self.x)

    def step(self):
        s, x, v, w = self.s, self.x, self.v, self.w
        i, j = self.candidate_pairs()
        d = x[i] - x[j]
        if s["boundary"] == "periodic":           # minimum image
            d -= self.size * np.rint(d / self.size)
        dist2 = np.einsum("ij,ij->i", d, d)
        reach = self.r[i] + self.r[j]
        wsum = w[i] + w[j]
        hit = (dist2 < reach * reach) & (dist2 > 0) & (wsum > 0)
        i, j, d, reach, wsum = i[hit], j[hit], d[hit], reach[hit], wsum[hit]
        dist = np.sqrt(dist2[hit])
        nrm = d / dist[:, None]
        dx = (w[i] / wsum * (reach - dist))[:, None] * nrm      # the inverse-mass share of the overlap
        u = v[i] - v[j]
        un = np.einsum("ij,ij->i", u, nrm)
        jn = self.impulse(un, wsum)
        dv = (w[i] * jn)[:, None] * nrm
        if s["friction"] > 0:
            ut = u - un[:, None] * nrm
            speed = np.sqrt(np.einsum("ij,ij->i", ut, ut))
            jt = np.minimum(s["friction"] * jn, speed / wsum)
            dv -= (w[i] * np.where(speed > 0, jt / np.where(speed > 0, speed, 1), 0))[:, None] * ut
        for k in (0, 1):
            x[:, k] += np.bincount(i, dx[:, k], len(x))
            v[:, k] += np.bincount(i, dv[:, k], len(x))
        self.contacts += int(np.count_nonzero((i < j) | self.stone[j]))
        move = ~self.stone
        x[move] += v[move] * s["dt"]
        g = np.array([s["gravity_x"], s["gravity_y"]])
        v[move] += (g - s["damping"] * v[move]) * s["dt"]
        self.walls(move)
        self.steps += 1

    def impulse(self, un, wsum):
        """J = -(1 + e) u_n / (w_i + w_j), approaching pairs only (docs/stepping-rules.md, (3))."""
        return np.where(un < 0, -(1 + self.s["restitution"]) * un / wsum, 0.0)

    def walls(self, move):
        x, v = self.x, self.v
        if self.s["boundary"] == "periodic":
            rel = x[move] - self.lo
            rel -= self.size * np.floor(rel / self.size)
            rel = np.where(rel >= self.size, rel - self.size, rel)
            x[move] = self.lo + rel
            return
        e, r = self.s["wall_restitution"], self.r[:, None]
        low, high = move[:, None] & (x - r < self.lo), move[:, None] & (x + r > self.lo + self.size)
        high &= ~low
        x[:] = np.where(low, self.lo + r, np.where(high, self.lo + self.size - r, x))
        v[:] = np.where((low & (v < 0)) | (high & (v > 0)), -e * v, v)

    @property
    def positions(self):
        return self.x

    @property
    def velocities(self):
        return self.v

    def stats(self):
        return {"steps": self.steps, "contacts": self.contacts}
