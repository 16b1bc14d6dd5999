#include "validation/compare/predictability_horizon.h"

#include <cmath>
#include <limits>
#include <string>
#include <stdexcept>

namespace collide::validation {

PredictabilityHorizon predictability_horizon(const std::vector<double>& times,
                                             const std::vector<double>& twin_separation, double tolerance,
                                             double margin) {
    if (times.size() != twin_separation.size())
        throw std::invalid_argument("predictability_horizon: " + std::to_string(times.size()) + " output times but " +
                                    std::to_string(twin_separation.size()) + " twin separations");
    PredictabilityHorizon h;
    h.threshold = tolerance / margin;
    while (h.judged < times.size() && twin_separation[h.judged] <= h.threshold) ++h.judged;  // NaN stops it
    h.reached = h.judged < times.size();
    h.time = h.judged > 0 ? times[h.judged - 1] : std::nan("");
    h.first_unjudged = h.reached ? times[h.judged] : std::nan("");
    return h;
}

double trajectory_limit(bool exact, double tolerance, double twin_separation, double margin) {
    return exact ? margin * twin_separation : tolerance;
}

TrajectoryJudgement judge_trajectory(const std::vector<double>& times, const std::vector<double>& error,
                                     const std::vector<double>& twin_separation, double tolerance, bool exact,
                                     double margin) {
    if (error.size() != times.size())
        throw std::invalid_argument("judge_trajectory: " + std::to_string(times.size()) + " output times but " +
                                    std::to_string(error.size()) + " errors");
    TrajectoryJudgement j;
    j.times = times;
    j.error = error;
    j.measured = !twin_separation.empty();
    j.exact = exact && j.measured;
    j.twin_separation = j.measured ? twin_separation : std::vector<double>(times.size(), 0.0);
    j.horizon = predictability_horizon(times, j.twin_separation, tolerance, margin);
    for (std::size_t k = 0; k < j.horizon.judged; ++k) {
        j.limit.push_back(trajectory_limit(j.exact, tolerance, j.twin_separation[k], margin));
        const double r = error_ratio(error[k], j.limit[k]), w = error_ratio(error[j.worst], j.limit[j.worst]);
        if (!std::isnan(w) && !(r <= w)) j.worst = k;  // the first NaN stays the worst
    }
    return j;
}

int twin_sign(std::uint64_t seed, int twin, std::size_t disk, int coordinate) {
    // splitmix64 (Steele, Lea & Flood 2014) of the four numbers, one bit of the result.
    std::uint64_t z = seed * 0x9E3779B97F4A7C15ull + std::uint64_t(twin) * 0xBF58476D1CE4E5B9ull +
                      std::uint64_t(disk) * 0x94D049BB133111EBull + std::uint64_t(coordinate) + 1;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (z & 1u) ? 1 : -1;
}

}  // namespace collide::validation
