#include "validation/suite_outcome.h"

#include <algorithm>

namespace collide::validation {

std::size_t SuiteOutcome::count(CheckStatus s) const {
    std::size_t n = 0;
    for (const auto& c : checks) n += c.status == s;
    return n;
}

std::size_t SuiteOutcome::physics_failures() const {
    return std::size_t(std::count_if(physics.rows.begin(), physics.rows.end(),
                                     [](const PhysicsRow& r) { return r.verdict == PhysicsVerdict::fail; }));
}

}  // namespace collide::validation
