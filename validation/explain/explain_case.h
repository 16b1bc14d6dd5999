// One case of a finished suite explained: where its energy jumped and why. `collide explain`
// explains the case and the interval a user names; `collide report` finds the jumps itself, in
// the cases it draws, and explains each (report_jumps.h). Both go through here, so the report
// says what `collide explain` says.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/backend_registry.h"
#include "core/scene/scene_overrides.h"
#include "validation/explain/case_replay.h"
#include "validation/explain/energy_jump.h"
#include "validation/plan/suite.h"
#include "validation/record/case_result.h"

namespace collide::validation {

// The largest change of mechanical energy over one output interval of a recorded series,
// relative to the largest kinetic energy, where it stands out: at least `threshold` and at
// least `factor` times the median interval's change. The report shows such a jump and has it
// explained; a series of fewer than three points, or with a non-finite value, has none.
struct IntervalJump {
    double t0 = 0, t1 = 0;  // the output interval
    double change = 0;      // (E(t1) - E(t0)) / max K
    double median = 0;      // the median |change| over all intervals
    double scale = 0;       // max K
};
std::optional<IntervalJump> largest_interval_jump(const MetricSeries& series, double threshold = 1e-3,
                                                  double factor = 10.0);

struct ExplainedCase {
    ReplayedCase replayed;
    EnergyJump jump;
};

// Rebuilds case `case_id` of the results in `dir` from `suite` (case_replay.h), checks that the
// rerun retraces the record (unless `overrides` make it a what-if), runs it to `from`, then
// steps it one dt at a time up to `to` (< 0: the case's duration) and names the step that
// changed the energy most (energy_jump.h). Throws std::runtime_error naming the case and what
// is wrong: an exact backend (no steps to look inside), a record that differs from the rerun,
// an interval outside the run. `on_progress(t, t_end)` is called as the run goes.
ExplainedCase explain_case(const std::string& dir, const Suite& suite, const std::string& case_id,
                           const std::vector<BackendInfo>& backends, const std::vector<SceneOverride>& overrides,
                           double from, double to, const std::function<void(double, double)>& on_progress = {});

// The explanation as `collide explain --json` prints it and the report reads it.
nlohmann::json explanation_json(const ExplainedCase& explained);

}  // namespace collide::validation
