#include "progress.h"

#include <cmath>

namespace collide::validation {

Progress::Progress(std::size_t total, std::FILE* stream, bool terminal, double plain_interval)
    : total_(total), stream_(stream), terminal_(terminal), plain_interval_(plain_interval),
      start_(std::chrono::steady_clock::now()), last_plain_(start_) {}

std::string Progress::format_duration(double seconds) {
    const long s = std::lround(std::max(0.0, seconds));
    char buf[32];
    if (s >= 3600) std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
    else std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
    return buf;
}

void Progress::update(std::size_t done, std::size_t failed, const std::string& last_case) {
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    // ETA from the mean time per finished case; cases differ in cost, so it is a rough guide.
    const std::string eta = done ? format_duration(elapsed / double(done) * double(total_ - done)) : "?";
    // The rate is what a run on more ranks or jobs should raise; it is read against the ETA.
    const double per_minute = elapsed > 0 ? 60.0 * double(done) / elapsed : 0.0;
    char buf[512];
    std::snprintf(buf, sizeof buf, "[%zu/%zu] elapsed %s, ETA %s, %.1f cases/min, %zu failed  %s", done, total_,
                  format_duration(elapsed).c_str(), eta.c_str(), per_minute, failed, last_case.c_str());
    last_line_ = buf;
    if (terminal_) {
        std::fprintf(stream_, "\r\033[K%s", buf);  // \033[K clears the rest of the old line
        std::fflush(stream_);
    } else if (std::chrono::duration<double>(now - last_plain_).count() >= plain_interval_ || done == total_) {
        std::fprintf(stream_, "%s\n", buf);
        last_plain_ = now;
    }
}

void Progress::finish() {
    if (terminal_ && !last_line_.empty()) std::fprintf(stream_, "\n");
    std::fflush(stream_);
}

}  // namespace collide::validation
