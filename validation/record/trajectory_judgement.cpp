#include "validation/record/trajectory_judgement.h"

#include <cmath>
#include <limits>

namespace collide::validation {

double error_ratio(double error, double limit) {
    if (std::isnan(error)) return error;
    if (limit > 0) return error / limit;
    return error > 0 ? std::numeric_limits<double>::infinity() : 0.0;
}

bool PredictabilityHorizon::judges_anything(const std::vector<double>& times) const {
    for (std::size_t k = 0; k < judged && k < times.size(); ++k)
        if (times[k] > times.front()) return true;
    return false;
}

bool TrajectoryJudgement::passed() const {
    for (std::size_t k = 0; k < limit.size(); ++k)
        if (!(error[k] <= limit[k])) return false;
    return true;
}

double TrajectoryJudgement::ratio() const {
    return limit.empty() ? 0.0 : error_ratio(error[worst], limit[worst]);
}

}  // namespace collide::validation
