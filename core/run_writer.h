// RunWriter: one run's results as an HDF5 file (layout in docs/output-format.md).
//
//   /                      attributes: provenance (commit, compiler, versions, seed, command
//                          line, backend, scene text, ...)
//   /particles/radius, mass, inv_mass        per-disk constants (N)
//   /metrics/<name>        one 1-D dataset per Metrics field, one entry per output time
//   /stats                 attributes: SolverStats (steps, contacts, phase seconds, counters)
//   /frames/time (T), /frames/position (T x N x 2), /frames/velocity (T x N x 2)
//                          only with frames enabled; chunked and gzip-compressed
//
// The file is written under a temporary name beside the target and renamed into place by
// commit(), so an existing file is never left half-written; if the writer is destroyed
// without commit() the temporary file is removed and the target is untouched.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "metrics.h"
#include "particle_state.h"
#include "solver.h"

namespace collide {

class RunWriter {
public:
    RunWriter(const std::string& path, bool write_frames);
    ~RunWriter();
    RunWriter(const RunWriter&) = delete;
    RunWriter& operator=(const RunWriter&) = delete;

    void write_attributes(const std::map<std::string, std::string>& attributes);
    void write_particles(const ParticleState<double>& state);
    // Called once per output time, in order.
    void append(const Metrics& metrics, const ParticleState<double>& state);
    void write_stats(const SolverStats& stats);
    void commit();  // flush, close and rename into place

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace collide
