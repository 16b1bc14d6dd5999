"""validation/report/progress.py, the report's progress line: the same words as the C++ one
(tests/core/test_progress_line.cpp holds core/io/progress_line.h to the same strings), in place on a
terminal, quiet in a short log. Run by ctest (label unit) with pytest."""
import io
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "validation", "report"))
import progress  # noqa: E402


class Terminal(io.StringIO):
    def isatty(self):
        return True


def test_the_line_reads_as_the_cpp_one():
    assert progress.compose(0.25, "t = 2.5 of 10", 10) == "t = 2.5 of 10 (25%), 0:10 elapsed, about 0:30 left"
    assert progress.compose(0, "x", 3) == "x (0%), 0:03 elapsed"
    assert progress.compose(1, "x", 3725) == "x (100%), 1:02:05 elapsed"
    assert progress.compose(1.5, "x", 1) == "x (100%), 0:01 elapsed"
    assert progress.format_duration(65) == "1:05"
    assert progress.format_duration(-5) == "0:00"


def test_a_short_log_stays_quiet():
    log = io.StringIO()
    line = progress.ProgressLine(log, log_interval=3600)
    line.update(0.5, "half")
    line.finish()
    assert log.getvalue() == ""


def test_a_terminal_line_is_rewritten_and_cleared():
    tty = Terminal()
    line = progress.ProgressLine(tty)
    line.last -= 1  # past the redraw interval
    line.update(0.5, "report: 3 of 6 scenes drawn")
    line.finish()
    text = tty.getvalue()
    assert text.startswith("\rreport: 3 of 6 scenes drawn (50%), 0:0")
    assert text.endswith("\r\033[K")
