// The per-case checks: each turns measurements into a value, compares it with its tolerance and
// says pass, fail or left out (with the reason). What each check measures, its tolerance key
// and when it applies are declared once, in the check table (check_table.h); docs/validation.md
// shows the same table and derives the tolerances.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "validation/judge/applicability.h"
#include "validation/record/case_result.h"
#include "validation/record/check_result.h"
#include "validation/record/tolerances.h"

namespace collide::validation {

// The checks of one case on its own (run, conservation, overlaps), with the case's limits
// (ToleranceTable::for_case) and what its backend declares (a stepping rule's kinetic energy
// is held to the rule's energy-loss model).
std::vector<CheckResult> case_checks(const CaseResult& result, const SceneFeatures& features,
                                     const Tolerances& tolerances, const BackendInfo& backend);

}  // namespace collide::validation
