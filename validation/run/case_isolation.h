// Runs each case in its own child process (fork), up to `jobs` at a time, so that a case that
// crashes (segfault, abort), hangs past the time limit or throws is recorded as failed with
// its diagnostic while the others go on. The child writes its CaseResult to a file and exits;
// the parent reads the file back, or writes a result describing how the child died.
//
// Cases that IsolationOptions::in_worker selects (the suite: every case a backend runs) go to
// worker processes instead: a worker is forked as a case's process is, but after writing its
// case's result it waits for the next case, so what a process pays once (the fork's copied
// pages, the libraries' set-up, an OpenCL driver's platform, context and program cache: 0.2-0.3
// s on PoCL) is paid once per worker. The guarantees stay: each case writes its own log and
// result file; a worker that crashes, exits or runs past the time limit is killed and its case
// recorded exactly as a case's own process would be (crashed, timed out), and the next case
// starts a new worker. What a worker does not give is a fresh address space per case: a case
// that corrupted memory without crashing could change the next case of the same worker. The
// suite's test that one worker for every case and a worker per case give the same value for
// every check (tests/validation/test_backend_variants.cpp), and the sanitizer build of the
// tests, are what hold that line. At most `jobs` workers exist; they end when the runner has
// no case left for them.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "validation/record/case_result.h"

namespace collide::validation {

struct IsolationOptions {
    int jobs = 1;
    double time_limit_seconds = 120;
    std::string result_dir;  // <id>.toml (result) and <id>.log (the child's stdout and stderr)
    std::string runs_dir;    // where children write HDF5 files ("" if none): cleaned as they die
    std::function<bool(const CaseSpec&)> in_worker;  // cases run by workers (unset: none)
};

// Removes the temporary files a writer leaves when its process dies without cleaning up
// (SIGKILL, a crash, the time limit): ".NAME.tmp-PID-K" HDF5 files in `runs_dir` and records
// in `result_dir` (core/io/output_file.h names every temporary so). With pid = 0 every one of
// them goes, and "NAME.partial" records older versions left (for --resume,
// which holds the output directory's lock, so no other run is writing them).
void remove_temporaries(const std::string& runs_dir, const std::string& result_dir, int pid = 0);

// Runs `run_case` for every spec in a child process; calls `on_done` in the parent (in
// completion order) with each result. `run_case` runs only in children.
void run_isolated(const std::vector<CaseSpec>& specs, const IsolationOptions& options,
                  const std::function<CaseResult(const CaseSpec&)>& run_case,
                  const std::function<void(const CaseResult&)>& on_done);

// The same with the cases handed out one at a time: `claim` gives the next case to start, or
// nothing when none is left (the MPI runner claims from a counter that every rank shares,
// mpi_dispatch.h); `idle` runs between polls of the children (the MPI runner's rank 0
// receives the other ranks' results there, so they arrive while its own cases run).
void run_isolated_claiming(const IsolationOptions& options, const std::function<std::optional<CaseSpec>()>& claim,
                           const std::function<CaseResult(const CaseSpec&)>& run_case,
                           const std::function<void(const CaseResult&)>& on_done,
                           const std::function<void()>& idle = [] {});

std::string result_path(const std::string& result_dir, const std::string& id);
// The case's log (its output) beside its record: RESULT_DIR/ID.log.
std::string case_log_path(const std::string& result_dir, const std::string& id);

}  // namespace collide::validation
