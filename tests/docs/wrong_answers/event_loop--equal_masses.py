# The equal-mass rule (exchange the normal components) used whatever the masses.
# hint: the collision rule weighs the masses
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
from worked_solution import worked_solution  # noqa: E402  (the chapter's EventLoop)

Right = worked_solution("event_loop.py").EventLoop


class EventLoop(Right):
    def pair_collision(self, i, j, shift):
        dx = self.x[j][0] + shift[0] - self.x[i][0]
        dy = self.x[j][1] + shift[1] - self.x[i][1]
        ux, uy = self.v[j][0] - self.v[i][0], self.v[j][1] - self.v[i][1]
        along = (dx * ux + dy * uy) / (dx * dx + dy * dy)
        for k, d in ((0, dx), (1, dy)):
            self.v[i][k] += along * d                          # the slip: no 2 m_j / (m_i + m_j)
            self.v[j][k] -= along * d
