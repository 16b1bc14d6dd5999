# Only the disks in the event are moved to its time: the others stay behind, their clocks wrong.
# hint: every disk flies on to the event's time, not only the disks in the event
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
from worked_solution import worked_solution  # noqa: E402  (the chapter's EventLoop)

Right = worked_solution("event_loop.py").EventLoop


class EventLoop(Right):
    def advance_to(self, t):
        while True:
            wall_dt, i, k = self.next_wall_event()
            pair_dt, p, q, shift = self.next_pair_event()
            if min(wall_dt, pair_dt) > t - self.t:
                break
            moved = [i] if wall_dt < pair_dt else [p, q]
            dt = min(wall_dt, pair_dt)
            for disk in moved:                                 # the slip: the others stay put
                self.x[disk][0] += self.v[disk][0] * dt
                self.x[disk][1] += self.v[disk][1] * dt
            self.t += dt
            if wall_dt < pair_dt:
                self.wall_collision(i, k)
            else:
                self.pair_collision(p, q, shift)
        self.advance(t - self.t)
