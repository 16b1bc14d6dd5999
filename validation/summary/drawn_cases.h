// The cases the report draws: the one rule, applied when summary.json is written (each case's
// `drawn`), read by `collide report` for the energy jumps it explains
// (validation/explain/report_jumps.h) and by the renderer for the figures of each scene.
#pragma once

#include <vector>

#include "validation/record/case_result.h"

namespace collide::validation {

// For every (scene, backend), the completed case with the smallest dt (the most accurate), then
// the smallest seed: one case per backend and scene, each backend shown at its best setting.
// Returns one flag per case of `cases`, in their order.
std::vector<bool> drawn_cases(const std::vector<CaseResult>& cases);

}  // namespace collide::validation
