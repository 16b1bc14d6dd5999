// ProgressLine: the one progress display of every long command (run, render, explain, bench,
// validate; the report's Python twin is validation/report/progress.py). It tells someone
// waiting how far the work has got and about how long is left, on a stream that is not
// stdout (stdout stays free for results and pipes).
//
// On a terminal one line is rewritten in place (at most a few redraws a second). Elsewhere
// (a log file, CI) it stays silent for the first `log_interval_seconds` and then prints a plain
// line every `log_interval_seconds`, so logs show progress on long work without filling up.
//
// The time left assumes the rest goes as fast as the part done so far: elapsed·(1 − f)/f for a
// fraction f done. Work whose items differ in cost (suite cases, bench sizes) makes it a rough
// guide; the line says "about".
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace collide {

class ProgressLine {
public:
    struct Style {
        bool terminal;                     // rewrite one line in place; else plain lines
        double log_interval_seconds = 10;  // plain lines: at most one per interval
        bool keep_last_line = false;       // on a terminal, leave the final line on screen
    };
    // Detects a terminal on `stream` (isatty).
    explicit ProgressLine(std::FILE* stream = stderr, double log_interval_seconds = 10);
    ProgressLine(std::FILE* stream, Style style);
    ~ProgressLine();  // finish()
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    // `fraction` in [0, 1] of the work is done; `what` says what (e.g. "t = 1.2 of 10").
    // `force` prints even inside the redraw/log interval (a suite's last case).
    void update(double fraction, const std::string& what, bool force = false);
    // Simulation time `time` of `duration` reached: "t = 1.2 of 10 (12.0%)".
    void update_time(double time, double duration);
    // Clears the terminal line (or ends it, with keep_last_line). Called by the destructor too.
    void finish();

    // "0:05", "1:05", "1:02:03".
    static std::string format_duration(double seconds);
    // The line `update` prints (without the terminal control characters), for tests.
    static std::string compose(double fraction, const std::string& what, double elapsed_seconds);

private:
    using Clock = std::chrono::steady_clock;
    double seconds_since(Clock::time_point t) const;

    std::FILE* stream_;
    Style style_;
    Clock::time_point start_ = Clock::now();
    Clock::time_point last_print_ = start_;
    bool line_shown_ = false;
};

}  // namespace collide
