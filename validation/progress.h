// The progress line of `collide validate`: count, elapsed time and an estimate of the time
// left. On a terminal one line is rewritten in place (carriage return); otherwise (CI logs,
// pipes) a plain line is printed every `plain_interval` seconds and at the end.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace collide::validation {

class Progress {
public:
    Progress(std::size_t total, std::FILE* stream, bool terminal, double plain_interval = 10.0);
    void update(std::size_t done, std::size_t failed, const std::string& last_case);
    void finish();

    static std::string format_duration(double seconds);  // "1:05", "1:02:03"

private:
    std::size_t total_;
    std::FILE* stream_;
    bool terminal_;
    double plain_interval_;
    std::chrono::steady_clock::time_point start_, last_plain_;
    std::string last_line_;
};

}  // namespace collide::validation
