// The progress line of `collide validate`: cases done of the total, failures, the rate and
// the last case, shown through the one progress display of every command
// (core/io/progress_line.h: in place on a terminal, a plain line every `plain_interval` seconds
// otherwise, and always the final count).
#pragma once

#include <cstdio>
#include <string>

#include "core/io/progress_line.h"

namespace collide::validation {

class Progress {
public:
    Progress(std::size_t total, std::FILE* stream, bool terminal, double plain_interval = 10.0);
    void update(std::size_t done, std::size_t failed, const std::string& last_case);
    void finish() { line_.finish(); }

private:
    std::size_t total_;
    ProgressLine line_;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace collide::validation
