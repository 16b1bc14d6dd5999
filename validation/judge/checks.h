// The per-case checks: each turns measurements into a value, compares it with its tolerance and
// says pass, fail or left out (with the reason). What each check measures, its tolerance key
// and when it applies are declared once, in the check table (check_table.h); docs/validation.md
// shows the same table and derives the tolerances.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "validation/judge/applicability.h"
#include "validation/run/case_result.h"
#include "validation/judge/tolerances.h"

namespace collide::validation {

enum class CheckStatus { pass, fail, left_out };
const char* to_string(CheckStatus s);

struct CheckResult {
    std::string subject;     // a case id, or a group id (case id without the seed) for statistics
    std::string scene, backend;
    std::string check;
    CheckStatus status = CheckStatus::left_out;
    double value = 0;
    double tolerance = 0;
    std::string comparison = "<=";  // how value relates to tolerance for a pass ("<=" or ">=")
    std::string detail;             // failure message or left-out reason
    // energy_drift of a stepped backend: the drift the rule itself predicts (energy_loss_model.h)
    double predicted = std::nan(""), predicted_uncertainty = std::nan("");
};

// The checks of one case on its own (run, conservation, overlaps), with the case's limits
// (ToleranceTable::for_case) and what its backend declares (a stepping rule's kinetic energy
// is held to the rule's energy-loss model).
std::vector<CheckResult> case_checks(const CaseResult& result, const SceneFeatures& features,
                                     const Tolerances& tolerances, const BackendInfo& backend);

// The id of a case's sweep group: the case id without the "__seed<N>" suffix.
std::string group_id(const CaseSpec& spec);

}  // namespace collide::validation
