#include "progress_line.h"

#include <unistd.h>

namespace collide::cli {

namespace {
constexpr double terminal_redraw_seconds = 0.2;
}

ProgressLine::ProgressLine(std::FILE* stream, double log_interval_seconds)
    : stream_(stream), terminal_(::isatty(::fileno(stream)) == 1), log_interval_seconds_(log_interval_seconds) {}

ProgressLine::~ProgressLine() { finish(); }

double ProgressLine::seconds_since(Clock::time_point t) const {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

void ProgressLine::update(double time, double duration) {
    const double interval = terminal_ ? terminal_redraw_seconds : log_interval_seconds_;
    if (seconds_since(last_print_) < interval) return;
    last_print_ = Clock::now();
    if (terminal_) {
        print(time, duration, "\r", "\033[K");  // rewrite the line in place, erase what is left of it
        line_shown_ = true;
    } else {
        print(time, duration, "", "\n");
    }
}

void ProgressLine::finish() {
    if (!line_shown_) return;
    std::fputs("\r\033[K", stream_);
    std::fflush(stream_);
    line_shown_ = false;
}

// "t = 1.2 of 10 (12.0%), 3 s elapsed, about 22 s left": the remaining time assumes the
// rest of the run goes as fast as the part so far.
void ProgressLine::print(double time, double duration, const char* prefix, const char* suffix) {
    const double fraction = duration > 0 ? time / duration : 1;
    const double elapsed = seconds_since(start_);
    std::fprintf(stream_, "%st = %g of %g (%.1f%%), %.0f s elapsed", prefix, time, duration, 100 * fraction, elapsed);
    if (fraction > 0 && fraction < 1) std::fprintf(stream_, ", about %.0f s left", elapsed * (1 - fraction) / fraction);
    std::fputs(suffix, stream_);
    std::fflush(stream_);
}

}  // namespace collide::cli
