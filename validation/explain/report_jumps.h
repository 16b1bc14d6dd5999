// The energy jumps the report shows, found and explained in C++ before the renderer starts, so
// that the renderer (validation/report/) only lays them out: `collide report` writes them to
// DIR/report/energy_jumps.json.
//
// Which cases: the cases the report draws (summary.json's `drawn`, validation/summary/drawn_cases.h)
// of every scene whose energy_drift check was judged (passed or failed, not left out), on every
// backend with time steps (summary.json's `exact` false: an exact solver has no step to
// look inside, BackendInfo::exact). A case whose recorded series has a jump
// (largest_interval_jump) is rerun over that output interval and its step named (explain_case);
// a rerun that fails is kept with its reason, never dropped.
//
// Each case is explained once: a drawn case whose record holds the same numbers, bit for bit (its
// metric series and final state), as one explained before it on the same scene is not rerun; it
// gets that explanation, and `same_as` names the case it came from. The opencl backend on a CPU
// device computes exactly what `cpu` computes, and its rerun (one at a time on the device) would
// only name the same step again.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/backend_registry.h"
#include "validation/plan/suite.h"

namespace collide::validation {

// `summary` is DIR/summary.json as read; `suite` the suite file it names, loaded, with
// `backends` including its outside solvers; or no suite and `suite_problem`, why it could not
// be loaded (each jump then carries that reason). Runs up to `jobs` reruns at once (the opencl
// backend's one at a time). Returns
// {"jumps": [{"case", "scene", "backend", "t0", "t1", "change", "median", "scale",
//             "explained": <explanation_json> or null, "problem": "" or why not,
//             "same_as": the case explained in its place (only where it has a twin)}, ...]}.
nlohmann::json report_energy_jumps(const std::string& dir, const nlohmann::json& summary, const Suite* suite,
                                   const std::string& suite_problem, const std::vector<BackendInfo>& backends,
                                   int jobs);

}  // namespace collide::validation
