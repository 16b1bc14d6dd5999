// SuiteOutcome: everything one run of a suite produced (cases, checks, classifications,
// comparisons, physics rows, provenance), as run_suite (suite_runner.h) returns it and the
// summary writers (summary/summary_writer.h) write it.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/backend_registry.h"
#include "validation/compare/physics_rows.h"
#include "validation/judge/stability.h"
#include "validation/record/case_result.h"
#include "validation/record/check_result.h"
#include "validation/record/comparisons.h"

namespace collide::validation {

struct SuiteOutcome {
    std::vector<CaseResult> cases;
    std::vector<CheckResult> checks;
    std::vector<Classification> classifications;  // parallel to cases; empty unless suite.stability
    std::vector<WorkPrecisionLine> work_precision;
    std::map<std::string, TrajectoryJudgement> trajectories;  // by case id (predictability_horizon.h)
    PhysicsComparison physics;                     // "Reference against physics" (physics_rows.h)
    std::size_t cases_run = 0, cases_resumed = 0;
    int jobs = 1;  // the cases run at the same time in this process (options.jobs resolved)
    double wall_seconds = 0;
    std::map<std::string, std::string> execution;  // ranks, hosts, jobs per rank (summary provenance)
    // backend -> what it declares (precision, exact, rule, conserves: BackendInfo)
    std::map<std::string, BackendInfo> declared;
    nlohmann::json energy_jumps = nlohmann::json::array();  // report_jumps.h, explained after judging
    std::size_t count(CheckStatus s) const;
    std::size_t physics_failures() const;
    bool passed() const { return count(CheckStatus::fail) == 0 && physics_failures() == 0; }
};

}  // namespace collide::validation
