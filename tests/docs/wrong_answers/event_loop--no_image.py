# In a periodic box each pair is tried only as the two disks lie in the box, not through the
# images: two disks on either side of an edge pass through each other. Only the suite's periodic
# scene shows it; the probes have walls.
# hint: two disks overlap in the periodic box
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
from worked_solution import worked_solution  # noqa: E402  (the chapter's EventLoop)

Right = worked_solution("event_loop.py").EventLoop


class EventLoop(Right):
    def next_pair_event(self):
        best = (float("inf"), None, None, None)
        for i in range(len(self.x)):
            for j in range(i + 1, len(self.x)):
                dt = self.pair_time(i, j, (0.0, 0.0))          # the slip: no shifted images
                if dt < best[0]:
                    best = (dt, i, j, (0.0, 0.0))
        return best
