# After each pair collision the two disks are pushed 1e-9 apart along the line of centres, so the
# pair is sure not to be found touching again: a habit of stepped codes. The probes see it; in
# the suite, declared as nothing (positions to 0.5 r_min), it passes every scene but the periodic
# one, where chaos grows the offset to 9.9 r_min before that looser horizon; declared exact, it
# fails all six, 1e-9 against limits of 1e-11.
# hint: disks pushed apart after a contact
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
from worked_solution import worked_solution  # noqa: E402  (the chapter's EventLoop)

Right = worked_solution("event_loop.py").EventLoop


class EventLoop(Right):
    def pair_collision(self, i, j, shift):
        super().pair_collision(i, j, shift)
        dx = self.x[j][0] + shift[0] - self.x[i][0]
        dy = self.x[j][1] + shift[1] - self.x[i][1]
        gap = 1e-9 / (dx * dx + dy * dy) ** 0.5                # the slip: a push of 1e-9
        for k, d in ((0, dx), (1, dy)):
            self.x[i][k] -= 0.5 * gap * d
            self.x[j][k] += 0.5 * gap * d
