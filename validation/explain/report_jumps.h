// The energy jumps the report shows, found and explained by `collide validate` once every case
// has run and been judged, and written into summary.json (`energy_jumps`), so that `collide
// report` only reads and lays them out: explaining a jump reruns the case's solver, and a report
// of a results directory someone sent runs no program (docs/refusals.md, "What collide never
// does").
//
// Which cases: the cases the report draws (validation/summary/drawn_cases.h) of every scene
// whose energy_drift check was judged (passed or failed, not left out), on every backend with
// time steps (an exact solver has no step to look inside, BackendInfo::exact). A case whose recorded series has a jump
// (largest_interval_jump) is rerun over that output interval and its step named (explain_case);
// a rerun that fails is kept with its reason, never dropped.
//
// Each case is explained once: a drawn case whose record holds the same numbers, bit for bit (its
// metric series and final state), as one explained before it on the same scene is not rerun; it
// gets that explanation, and `same_as` names the case it came from. The opencl backend on a CPU
// device computes exactly what `cpu` computes, and its rerun (one at a time on the device) would
// only name the same step again.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/backend_registry.h"
#include "validation/judge/checks.h"
#include "validation/plan/suite.h"
#include "validation/record/case_result.h"

namespace collide::validation {

// A case whose jump is looked for: drawn, on a scene that judged energy, on a stepped backend.
struct DrawnCase {
    std::string id, scene, backend;
};

// The cases among `cases` (a suite's, in plan order) whose jumps are explained; `checks` are
// their judged checks, `exact` says per backend whether it claims exact dynamics (no time step).
std::vector<DrawnCase> cases_to_explain(const std::vector<CaseResult>& cases, const std::vector<CheckResult>& checks,
                                        const std::map<std::string, bool>& exact);

// `dir` holds the suite's records (cases/<id>.toml); `suite` is the suite that ran them, with
// `backends` including its outside solvers; or no suite and `suite_problem`, why the cases cannot
// be rerun (each jump then carries that reason). Runs up to `jobs` reruns at once (the opencl
// backend's one at a time). Returns
// {"jumps": [{"case", "scene", "backend", "t0", "t1", "change", "median", "scale",
//             "explained": <explanation_json> or null, "problem": "" or why not,
//             "same_as": the case explained in its place (only where it has a twin)}, ...]}.
nlohmann::json report_energy_jumps(const std::string& dir, const std::vector<DrawnCase>& cases, const Suite* suite,
                                   const std::string& suite_problem, const std::vector<BackendInfo>& backends,
                                   int jobs);

}  // namespace collide::validation
