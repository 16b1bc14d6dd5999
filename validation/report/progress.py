"""The report's progress line: the Python twin of core/io/progress_line.h (the one progress display
of every long command), with the same wording. On a terminal one line on stderr is rewritten in
place; elsewhere (a log, CI) nothing is printed for the first `log_interval` seconds and then a
plain line at most every `log_interval` seconds. The time left is elapsed·(1 − f)/f for a
fraction f done: a rough guide when the items differ in cost."""
import math
import sys
import time


def format_duration(seconds):
    """0:05, 1:05, 1:02:03 (as ProgressLine::format_duration)."""
    s = int(math.floor(max(0.0, seconds) + 0.5))
    return f"{s // 3600}:{s // 60 % 60:02d}:{s % 60:02d}" if s >= 3600 else f"{s // 60}:{s % 60:02d}"  # layout: h:mm:ss


def compose(fraction, what, elapsed):
    """The line ProgressLine::compose prints for the same arguments."""
    fraction = min(1.0, max(0.0, fraction))
    line = f"{what} ({int(math.floor(100 * fraction))}%), {format_duration(elapsed)} elapsed"
    if 0 < fraction < 1:
        line += f", about {format_duration(elapsed * (1 - fraction) / fraction)} left"
    return line


class ProgressLine:
    def __init__(self, stream=None, terminal=None, log_interval=10.0):
        self.stream = stream or sys.stderr
        self.terminal = self.stream.isatty() if terminal is None else terminal
        self.log_interval = log_interval
        self.start = self.last = time.monotonic()
        self.shown = False

    def update(self, fraction, what):
        now = time.monotonic()
        if now - self.last < (0.2 if self.terminal else self.log_interval):
            return
        self.last = now
        line = compose(fraction, what, now - self.start)
        if self.terminal:
            self.stream.write("\r" + line + "\033[K")
            self.shown = True
        else:
            self.stream.write(line + "\n")
        self.stream.flush()

    def finish(self):
        if self.shown:
            self.stream.write("\r\033[K")
            self.stream.flush()
            self.shown = False
