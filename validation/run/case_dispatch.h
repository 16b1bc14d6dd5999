// How the runner shares a suite's cases out when `collide validate` is started by an MPI
// launcher (mpirun, mpiexec, srun): the interface the runner calls, and what it needs that
// does not depend on MPI. The MPI implementation is mpi_dispatch.h (compiled only when the
// build finds MPI); a plain run gets no dispatch and never initialises MPI. docs/scaling.md.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "validation/run/case_isolation.h"
#include "validation/record/case_result.h"
#include "core/scene/scene.h"
#include "validation/run/progress.h"

namespace collide::validation {

// What the runner hands to a dispatch: the planned cases and how to run one.
struct CaseWork {
    const std::vector<CaseSpec>* specs = nullptr;       // every case of the suite, in plan order
    std::map<std::string, CaseResult>* results = nullptr;  // in: kept by --resume; out (rank 0): all
    std::string output_dir;                              // this rank's; runs/ (HDF5) lies below it
    IsolationOptions isolation;                          // each rank's own per-case processes
    std::function<CaseResult(const CaseSpec&)> run_case;
    std::function<double(const CaseSpec&)> expected_cost;  // relative; longest cases go first
    Progress* progress = nullptr;                        // rank 0's progress line (may be null)
};

class CaseDispatch {
public:
    virtual ~CaseDispatch() = default;
    virtual bool is_root() const = 0;  // rank 0: judges the cases and writes the summary
    // Runs every case of `work` that has no result yet, across all ranks; on rank 0 every
    // result is in work.results when it returns. Called by every rank. Returns how many ran.
    virtual std::size_t run(CaseWork& work) = 0;
    // ranks, hosts, jobs per rank: the summary's "execution" record.
    virtual std::map<std::string, std::string> execution() const = 0;
};

// True when an MPI launcher started this process (it sets these variables for each rank).
bool launched_by_mpi_launcher();

// The MPI dispatch when launched by an MPI launcher, nullptr for a plain run. Initialises MPI
// (and finalises it when the dispatch is destroyed). A build without MPI that is launched on
// more than one rank throws: every rank would otherwise run the whole suite into one directory.
std::unique_ptr<CaseDispatch> start_case_dispatch(int jobs_per_rank, bool gather_hdf5);

// The "execution" record of a run without MPI: one rank on this host.
std::map<std::string, std::string> serial_execution(int jobs);

// The work of a case in disk-steps (disks x time steps), scaled to seconds by the measured
// speed of finished cases of the same scene and backend (or backend, or any) when there are
// some (--resume). Only the order matters: the longest cases are handed out first, so that
// no rank starts a long case when the others are about to finish.
double estimated_cost(const CaseSpec& spec, const Scene& scene, const std::map<std::string, CaseResult>& finished);

// `specs` indices of the cases without a result in `finished`, longest expected first (plan
// order among equals, so that every rank count sees the same list).
std::vector<int> longest_first(const std::vector<CaseSpec>& specs, const std::map<std::string, CaseResult>& finished,
                               const std::function<double(const CaseSpec&)>& cost);

std::string this_host();

}  // namespace collide::validation
