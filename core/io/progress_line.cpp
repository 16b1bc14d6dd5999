#include "core/io/progress_line.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace collide {

namespace {
constexpr double terminal_redraw_seconds = 0.2;

bool is_terminal(std::FILE* stream) { return ::isatty(::fileno(stream)) == 1; }
}  // namespace

ProgressLine::ProgressLine(std::FILE* stream, double log_interval_seconds)
    : ProgressLine(stream, Style{is_terminal(stream), log_interval_seconds, false}) {}

ProgressLine::ProgressLine(std::FILE* stream, Style style) : stream_(stream), style_(style) {}

ProgressLine::~ProgressLine() { finish(); }

double ProgressLine::seconds_since(Clock::time_point t) const {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

std::string ProgressLine::format_duration(double seconds) {
    const long s = std::lround(std::max(0.0, seconds));
    char buf[32];
    if (s >= 3600) std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
    else std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
    return buf;
}

std::string ProgressLine::compose(double fraction, const std::string& what, double elapsed_seconds) {
    fraction = std::clamp(fraction, 0.0, 1.0);
    std::string line = what + " (" + std::to_string(int(std::floor(100 * fraction))) + "%), " +
                       format_duration(elapsed_seconds) + " elapsed";
    if (fraction > 0 && fraction < 1)
        line += ", about " + format_duration(elapsed_seconds * (1 - fraction) / fraction) + " left";
    return line;
}

void ProgressLine::update(double fraction, const std::string& what, bool force) {
    const double interval = style_.terminal ? terminal_redraw_seconds : style_.log_interval_seconds;
    if (!force && seconds_since(last_print_) < interval) return;
    last_print_ = Clock::now();
    const std::string line = compose(fraction, what, seconds_since(start_));
    if (style_.terminal) {
        std::fprintf(stream_, "\r%s\033[K", line.c_str());  // rewrite in place, erase the old tail
        line_shown_ = true;
    } else {
        std::fprintf(stream_, "%s\n", line.c_str());
    }
    std::fflush(stream_);
}

void ProgressLine::update_time(double time, double duration) {
    char what[96];
    std::snprintf(what, sizeof what, "t = %g of %g", time, duration);
    update(duration > 0 ? time / duration : 1.0, what);
}

void ProgressLine::finish() {
    if (!line_shown_) return;
    std::fputs(style_.keep_last_line ? "\n" : "\r\033[K", stream_);
    std::fflush(stream_);
    line_shown_ = false;
}

}  // namespace collide
