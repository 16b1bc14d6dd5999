#include "validation/judge/tunnelling.h"

#include <cmath>
#include <sstream>

namespace collide::validation {
namespace {

struct Pair {
    double s, perpendicular;  // separation along and across the initial direction u
};

Pair project(const Snapshot& state, std::size_t i, std::size_t j, double ux, double uy) {
    const double dx = state.x[j] - state.x[i], dy = state.y[j] - state.y[i];
    return {dx * ux + dy * uy, -dx * uy + dy * ux};
}

}  // namespace

TunnellingCount count_tunnelling(const CaseResult& backend, const CaseResult& reference, bool periodic) {
    TunnellingCount out;
    const auto& a = backend.trajectory;
    const auto& b = reference.trajectory;
    if (periodic) out.not_evaluated = "periodic box (a wrapped disk is no crossing)";
    else if (a.empty() || b.empty()) out.not_evaluated = "no recorded trajectory (too many disks, or the run failed)";
    else if (a.size() != b.size() || a.front().x.size() != b.front().x.size())
        out.not_evaluated = "the run and its reference recorded different output times or disks";
    if (!out.not_evaluated.empty()) return out;
    for (std::size_t k = 0; k < a.size(); ++k)
        if (std::fabs(backend.trajectory_time[k] - reference.trajectory_time[k]) > 1e-9) {
            out.not_evaluated = "the run and its reference recorded different output times";
            return out;
        }
    out.evaluated = true;
    const Snapshot& start = a.front();
    const std::size_t n = start.x.size();
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) {
            const double dx = start.x[j] - start.x[i], dy = start.y[j] - start.y[i];
            const double d = std::hypot(dx, dy);
            if (!(d > 0)) continue;
            const double ux = dx / d, uy = dy / d, contact = start.radius[i] + start.radius[j];
            for (std::size_t k = 1; k < a.size(); ++k) {
                const Pair before = project(a[k - 1], i, j, ux, uy), now = project(a[k], i, j, ux, uy);
                if (!(before.s > 0 && now.s <= 0)) continue;
                const double w = before.s / (before.s - now.s);  // where s = 0 between the outputs
                const double across = before.perpendicular + w * (now.perpendicular - before.perpendicular);
                if (!(std::fabs(across) < contact)) continue;
                if (!(project(b[k], i, j, ux, uy).s > 0)) continue;
                if (out.pairs++ == 0) {
                    std::ostringstream s;
                    s << "disks " << i << " and " << j << " at t = " << backend.trajectory_time[k];
                    out.first = s.str();
                }
                break;
            }
        }
    return out;
}

}  // namespace collide::validation
