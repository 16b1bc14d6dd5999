// Which run of the reference backend (the suite's `reference`, event) a case is measured
// against: the same scene, scene-parameter values and seed, and the same dt where the
// reference runs once per dt (trajectory scenes: each dt starts at its own collision phase,
// phase_shift.h). The comparisons with the reference read it, and so do the limits of an exact
// solver, which count the case's collisions from it (exact_limits.h): an outside solver need
// not report its own.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "validation/record/case_result.h"

namespace collide::validation {

// The key a case shares with its reference runs: scene and scene-parameter values.
std::string reference_key(const CaseSpec& spec);

// Whether `reference` (a reference case of the same key) is the run `spec` is measured against.
bool is_reference_run_of(const CaseSpec& reference, const CaseSpec& spec);

// The reference runs among a suite's results, by key.
class ReferenceRuns {
public:
    explicit ReferenceRuns(const std::vector<CaseResult>& results);
    // The reference run of `spec` (itself for a reference case), or nullptr when the suite has none.
    const CaseResult* of(const CaseSpec& spec) const;

private:
    std::map<std::string, std::vector<const CaseResult*>> by_key_;
};

}  // namespace collide::validation
