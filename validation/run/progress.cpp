#include "validation/run/progress.h"

#include "core/text/printable.h"

namespace collide::validation {

Progress::Progress(std::size_t total, std::FILE* stream, bool terminal, double plain_interval)
    : total_(total), line_(stream, ProgressLine::Style{terminal, plain_interval, true}) {}

// "[12/40] 3.2 cases/min, 1 failed  scene__backend__seed1 (30%), 3:45 elapsed, about 8:45 left".
// Cases differ in cost, so the time left is a rough guide; the rate is what more ranks or jobs
// should raise.
void Progress::update(std::size_t done, std::size_t failed, const std::string& last_case) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double per_minute = elapsed > 0 ? 60.0 * double(done) / elapsed : 0.0;
    char head[96];
    std::snprintf(head, sizeof head, "[%zu/%zu] %.1f cases/min, %zu failed  ", done, total_, per_minute, failed);
    line_.update(total_ ? double(done) / double(total_) : 1.0, head + printable(last_case), done == total_);
}

}  // namespace collide::validation
