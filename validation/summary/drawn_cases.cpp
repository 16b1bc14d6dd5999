#include "validation/summary/drawn_cases.h"

#include <map>
#include <string>
#include <utility>

namespace collide::validation {

std::vector<bool> drawn_cases(const std::vector<CaseResult>& cases) {
    std::map<std::pair<std::string, std::string>, std::size_t> best;  // (scene, backend) -> case
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const CaseResult& c = cases[k];
        if (!c.finished()) continue;
        auto [it, fresh] = best.try_emplace({c.spec.scene, c.spec.backend}, k);
        const CaseResult& b = cases[it->second];
        if (!fresh && (c.dt < b.dt || (c.dt == b.dt && c.spec.seed < b.spec.seed))) it->second = k;
    }
    std::vector<bool> drawn(cases.size(), false);
    for (const auto& [key, k] : best) drawn[k] = true;
    return drawn;
}

}  // namespace collide::validation
