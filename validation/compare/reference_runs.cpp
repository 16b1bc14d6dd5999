#include "validation/compare/reference_runs.h"

#include "validation/plan/case_plan.h"

namespace collide::validation {

std::string reference_key(const CaseSpec& spec) { return spec.scene + "|" + parameter_label(spec); }

bool is_reference_run_of(const CaseSpec& reference, const CaseSpec& spec) {
    return reference.seed == spec.seed && (!reference.dt || reference.dt == spec.dt);
}

ReferenceRuns::ReferenceRuns(const std::vector<CaseResult>& results) {
    for (const CaseResult& r : results)
        if (r.spec.reference) by_key_[reference_key(r.spec)].push_back(&r);
}

const CaseResult* ReferenceRuns::of(const CaseSpec& spec) const {
    const auto it = by_key_.find(reference_key(spec));
    if (it == by_key_.end()) return nullptr;
    const CaseResult* found = nullptr;
    for (const CaseResult* q : it->second)
        if (is_reference_run_of(q->spec, spec)) found = q;  // the last, as the comparisons take it
    return found;
}

}  // namespace collide::validation
