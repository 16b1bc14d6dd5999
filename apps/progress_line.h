// ProgressLine: tells someone waiting for a long run how far it has got, on stderr (stdout
// stays free for the summary and for pipes).
//
// On a terminal it keeps one line up to date in place (at most a few redraws a second) and
// clears it at the end. Otherwise (a log file, CI) it stays silent for short runs and prints
// a plain line every `log_interval_seconds` for long ones, so logs show progress without
// filling up.
#pragma once

#include <chrono>
#include <cstdio>

namespace collide::cli {

class ProgressLine {
public:
    explicit ProgressLine(std::FILE* stream = stderr, double log_interval_seconds = 10);
    ~ProgressLine();  // finish()
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    // Simulation time `time` of `duration` has been reached.
    void update(double time, double duration);
    // Clears the terminal line, if one is shown. Called by the destructor too.
    void finish();

private:
    using Clock = std::chrono::steady_clock;
    double seconds_since(Clock::time_point t) const;
    void print(double time, double duration, const char* prefix, const char* suffix);

    std::FILE* stream_;
    bool terminal_;
    double log_interval_seconds_;
    Clock::time_point start_ = Clock::now();
    Clock::time_point last_print_ = start_;
    bool line_shown_ = false;
};

}  // namespace collide::cli
