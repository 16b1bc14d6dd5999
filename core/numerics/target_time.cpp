#include "core/numerics/target_time.h"

#include <cmath>
#include <stdexcept>

#include "core/scene/toml_fields.h"

namespace collide {
namespace {

// Numbers as a scene file writes them, so the words match the scene reader's.
std::string text(double v) { return toml_value_text(toml::value(v)); }

}  // namespace

std::string steps_cap_problem(double t, double dt) {
    const double n = std::round(t / dt);
    if (!(n > max_steps)) return "";
    return "at most " + text(max_steps) + " steps of dt = " + text(dt) + " (this is " + text(n) + " steps)";
}

std::string target_time_problem(double t, double now, double dt, bool whole_steps) {
    // NaN would pass every comparison below (each is false) and become the time of every disk;
    // infinity would never be reached (an endless run).
    if (!std::isfinite(t)) return "target time t = " + text(t) + " is not a finite number";
    if (const std::string cap = steps_cap_problem(t, dt); !cap.empty())
        return "target time t = " + text(t) + ": expected " + cap;
    // Past in steps for the stepped backends: their time is k dt, and k dt for the same k a
    // caller computed may differ from its t by one rounding.
    const bool past = whole_steps ? std::llround(t / dt) < std::llround(now / dt) : t < now;
    if (past) return "target time t = " + text(t) + " is in the past: the simulation is at t = " + text(now) +
                     " and never goes backwards";
    return "";
}

void check_target_time(const std::string& backend, double t, double now, double dt, bool whole_steps) {
    const std::string problem = target_time_problem(t, now, dt, whole_steps);
    if (!problem.empty()) throw std::invalid_argument(backend + ": " + problem);
}

}  // namespace collide
