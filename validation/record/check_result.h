// CheckResult: the verdict of one check on one case or sweep group, as the judge makes it and
// the comparisons, the summary and the report read it. The checks themselves: judge/checks.h.
#pragma once

#include <cmath>
#include <string>

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

}  // namespace collide::validation
