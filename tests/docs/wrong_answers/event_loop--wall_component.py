# Every wall reverses vx, whichever wall it is: at the top wall the disk keeps flying out.
# hint: only the velocity component normal to that wall is reversed
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
from worked_solution import worked_solution  # noqa: E402  (the chapter's EventLoop)

Right = worked_solution("event_loop.py").EventLoop


class EventLoop(Right):
    def wall_collision(self, i, k):
        self.v[i][0] = -self.v[i][0]                           # the slip: k ignored
