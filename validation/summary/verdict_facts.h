// What the first screen's verdict names about each backend beside its passes and fails
// (docs/reading-a-report.md, "Where each verdict is decided"): its loosest tolerance against the
// other backends', its largest energy drift, its largest resolved pressure difference; each with
// whether it is large enough to be named, against the suite's `[verdicts]` thresholds
// (VerdictThresholds, validation/plan/suite.h). Decided here and written to summary.json
// (`verdicts`, `verdict_thresholds`); validation/report/verdicts.py only words them.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "validation/record/comparisons.h"
#include "validation/record/check_result.h"
#include "validation/plan/suite.h"

namespace collide::validation {

// The check whose tolerance is the largest multiple of the median tolerance the other backends
// (neither this one nor the reference) have for it; only upper limits ("<=") are compared.
struct LoosestTolerance {
    double ratio = 0;  // tolerance / the others' median
    std::string check;
    double tolerance = 0;
    bool named = false;  // ratio >= VerdictThresholds::loose_tolerance_ratio
};

// The largest energy drift of a judged energy_drift check, and its scene.
struct LargestEnergyDrift {
    double value = 0;
    std::string scene;
    bool named = false;  // value >= VerdictThresholds::energy_drift
};

// The largest resolved pressure difference from the reference, in standard errors, over the
// backend's work-precision points. Named only where it is not judged against the stepped
// rules' bias model (a stepping rule's pressure is meant to differ) or its check is left out.
struct PressureOffset {
    std::optional<double> sigmas;  // none: no resolved difference
    bool left_out = false;         // every pressure check of the backend was left out
    bool named = false;            // sigmas >= VerdictThresholds::pressure_sigmas, as above
};

struct VerdictFacts {
    std::optional<LoosestTolerance> loosest_tolerance;  // none for the reference, or nothing to compare
    std::optional<LargestEnergyDrift> largest_energy_drift;
    PressureOffset pressure_offset;
};

// Per backend with a check, what its verdict names. `stepping_rule` says per backend whether its
// pressure is judged against the stepped rules' model (follows_stepping_rules; absent: no).
std::map<std::string, VerdictFacts> verdict_facts(const std::string& reference, const std::vector<CheckResult>& checks,
                                                  const std::vector<WorkPrecisionLine>& lines,
                                                  const VerdictThresholds& thresholds,
                                                  const std::map<std::string, bool>& stepping_rule);

}  // namespace collide::validation
