// The cases of a suite shared across MPI ranks (compiled only when the build finds MPI).
//
// Hand-out: rank 0 orders the cases without a result longest expected first and broadcasts
// the order; every rank then claims the next case with MPI_Fetch_and_op on a counter that
// lives in a window on rank 0 (the cluster form of an atomic chunk cursor), so a slow rank
// or a long case never leaves the others idle while cases remain. Each rank runs its cases
// with the usual per-case processes (case_isolation.h), up to --jobs at a time.
//
// Results: a rank sends each case's result record (the text of cases/<id>.toml) to rank 0,
// which writes it into its own output directory, so the directory need not be shared. The
// record's provenance says on which host and rank the case ran, and on which host its HDF5
// file lies (rank 0's with --gather-hdf5, which also sends the file).
//
// Forked cases never call MPI: they compute, write their files and _exit.
#pragma once

#include <mpi.h>

#include <optional>
#include <string>
#include <vector>

#include "validation/run/case_dispatch.h"

namespace collide::validation {

class MpiDispatch : public CaseDispatch {
public:
    MpiDispatch(int jobs_per_rank, bool gather_hdf5);  // MPI_Init
    ~MpiDispatch() override;                            // MPI_Finalize
    MpiDispatch(const MpiDispatch&) = delete;
    MpiDispatch& operator=(const MpiDispatch&) = delete;

    bool is_root() const override { return rank_ == 0; }
    std::size_t run(CaseWork& work) override;
    std::map<std::string, std::string> execution() const override;

private:
    struct Run;  // one run's state: the counter window, the order, rank 0's tallies

    std::vector<int> agreed_order(const CaseWork& work) const;
    void open_cursor(Run& run) const;
    std::optional<CaseSpec> claim(Run& run) const;
    void receive_pending(Run& run);
    void send_result(const CaseResult& r, const CaseWork& work) const;
    void receive_result(Run& run, const MPI_Status& probed);
    void record(Run& run, CaseResult r, int from_rank);

    int rank_ = 0, size_ = 1, jobs_ = 1;
    bool gather_hdf5_ = false;
    std::vector<std::string> hosts_;          // per rank
    std::vector<std::size_t> cases_per_rank_;  // of the last run, as rank 0 counted them
};

}  // namespace collide::validation
