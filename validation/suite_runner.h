// run_suite: the validation runner behind `collide validate`. Plans the cases, runs each in
// an isolated child process, judges the results and writes the summary (summary.json), the
// JUnit file (junit.xml) and one HDF5 file per case into the output directory:
//
//   <out>/summary.json     everything the report needs: cases, checks, work-precision, provenance,
//                          the energy jumps explained (the report runs no solver itself)
//   <out>/junit.xml        one testcase per (case, check), for CI systems
//   <out>/cases/<id>.toml  each case's measurements (read back by --resume and the report)
//   <out>/cases/<id>.log   what the case's process printed
//   <out>/runs/<id>.h5     each case's metrics and provenance (RunWriter)
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "core/backend_registry.h"
#include "validation/plan/suite.h"
#include "validation/record/case_spec.h"
#include "validation/run/case_dispatch.h"
#include "validation/suite_outcome.h"

namespace collide::validation {

struct RunnerOptions {
    std::string output_dir = "results";
    int jobs = 1;                   // cases at the same time; 0: one per core (default_jobs())
    bool resume = false;            // keep every case that already has a result file
    std::FILE* progress = nullptr;  // progress lines go here (nullptr: none)
    bool progress_is_terminal = false;
    CaseDispatch* dispatch = nullptr;  // MPI ranks share the cases (case_dispatch.h); null: this process alone
};

// One case per core: std::thread::hardware_concurrency(), or 1 where it cannot tell.
int default_jobs();

// Whether a case runs in a worker process, one that runs case after case and keeps its
// start-up (case_isolation.h): every case a backend runs at all. A case's own process would
// pay, for each case, the fork's copied pages, the libraries' set-up and (opencl) the OpenCL
// platform, context and program (0.2-0.3 s on PoCL); the default suite took 114-123 s that
// way against 75-83 s in workers, with the same value for every check. A case left out (the
// backend refuses the scene) only records why, in a worker too: a fork of its own for each of
// them copied the runner's page tables and then faulted on every page the runner wrote
// (copy-on-write), about 5 % of the default suite's processor time (bench/journal.md).
bool runs_in_worker(const CaseSpec& spec);

// The cases run_suite would run, after every check that needs no run (`collide validate
// --plan`): the scene files load, each sweep point builds, each case's dt divides its duration
// and output interval. Throws SuiteError / SceneError naming the file and line otherwise.
std::vector<CaseSpec> plan_suite(const Suite& suite, const std::vector<BackendInfo>& backends);

// `backends` are the backends the suite may use (all_backends() in the program, test doubles
// in tests). Throws SuiteError / SceneError for bad input before any case runs.
SuiteOutcome run_suite(const Suite& suite, const std::vector<BackendInfo>& backends, const RunnerOptions& options);

}  // namespace collide::validation
