// run_suite: the validation runner behind `collide validate`. Plans the cases, runs each in
// an isolated child process, judges the results and writes the summary (summary.json), the
// JUnit file (junit.xml) and one HDF5 file per case into the output directory:
//
//   <out>/summary.json     everything the report needs: cases, checks, work-precision, provenance
//   <out>/junit.xml        one testcase per (case, check), for CI systems
//   <out>/cases/<id>.toml  each case's measurements (read back by --resume and the report)
//   <out>/cases/<id>.log   what the case's process printed
//   <out>/runs/<id>.h5     each case's metrics and provenance (RunWriter)
#pragma once

#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "case_dispatch.h"
#include "case_result.h"
#include "checks.h"
#include "core/backend_registry.h"
#include "physics_rows.h"
#include "reference_comparison.h"
#include "stability.h"
#include "suite.h"

namespace collide::validation {

struct RunnerOptions {
    std::string output_dir = "results";
    int jobs = 1;                   // cases at the same time; 0: one per core (default_jobs())
    bool resume = false;            // keep every case that already has a result file
    std::FILE* progress = nullptr;  // progress lines go here (nullptr: none)
    bool progress_is_terminal = false;
    CaseDispatch* dispatch = nullptr;  // MPI ranks share the cases (case_dispatch.h); null: this process alone
};

struct SuiteOutcome {
    std::vector<CaseResult> cases;
    std::vector<CheckResult> checks;
    std::vector<Classification> classifications;  // parallel to cases; empty unless suite.stability
    std::vector<WorkPrecisionLine> work_precision;
    PhysicsComparison physics;                     // "Reference against physics" (physics_rows.h)
    std::size_t cases_run = 0, cases_resumed = 0;
    int jobs = 1;  // the cases run at the same time in this process (options.jobs resolved)
    double wall_seconds = 0;
    std::map<std::string, std::string> execution;  // ranks, hosts, jobs per rank (summary provenance)
    std::map<std::string, std::string> precision;  // backend -> "double", "float", ... (BackendInfo)
    std::size_t count(CheckStatus s) const;
    std::size_t physics_failures() const;
    bool passed() const { return count(CheckStatus::fail) == 0 && physics_failures() == 0; }
};

// One case per core: std::thread::hardware_concurrency(), or 1 where it cannot tell.
int default_jobs();

// Whether a case runs in a worker process that keeps its start-up for the next case
// (case_isolation.h): the cases of a backend (or variant) marked BackendInfo::keeps_process,
// the opencl backend, whose process start pays for the OpenCL platform, context and compiled
// program (0.2-0.3 s on PoCL, most of a small case), when the backend runs them at all.
bool runs_in_worker(const CaseSpec& spec, const BackendInfo& backend);

// `backends` are the backends the suite may use (all_backends() in the program, test doubles
// in tests). Throws SuiteError / SceneError for bad input before any case runs.
SuiteOutcome run_suite(const Suite& suite, const std::vector<BackendInfo>& backends, const RunnerOptions& options);

}  // namespace collide::validation
