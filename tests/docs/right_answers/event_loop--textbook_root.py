# The textbook root (-b - sqrt(D)) / (u.u), which exercise 2.5 rejects, in the event loop: its
# error is relative to a small time, eps |d| / |u| in absolute terms, no more than the rounding of
# a position, so the loop still passes every check of exact dynamics (exercise 2.7's solution).
import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
from worked_solution import worked_solution  # noqa: E402  (the chapter's EventLoop)

Right = worked_solution("event_loop.py").EventLoop


class EventLoop(Right):
    def pair_time(self, i, j, shift):
        dx = self.x[j][0] + shift[0] - self.x[i][0]
        dy = self.x[j][1] + shift[1] - self.x[i][1]
        ux, uy = self.v[j][0] - self.v[i][0], self.v[j][1] - self.v[i][1]
        b = dx * ux + dy * uy
        if b >= 0:
            return math.inf
        sigma = self.r[i] + self.r[j]
        c = dx * dx + dy * dy - sigma * sigma
        uu = ux * ux + uy * uy
        disc = b * b - uu * c
        if disc <= 0:
            return math.inf
        return max((-b - math.sqrt(disc)) / uu, 0.0)
