// RunWriter: one run's results as an HDF5 file. docs/output-format.md describes the layout
// in full, with units and how to read it; in short:
//
//   /                      attributes: format ("collide-run"), format_version, and the
//                          provenance (commit, compiler, versions, seed, command line,
//                          backend, scene text, ...), each a variable-length UTF-8 string
//   /particles/radius, mass, inv_mass        per-disk constants (N)
//   /metrics/<name>        one 1-D dataset per column of the run schema (core/io/run_schema.h),
//                          one entry per output time
//                          (chunked and extendible, so it grows as the run goes)
//   /stats                 attributes steps, contacts; /stats/phase_seconds and
//                          /stats/counters hold one attribute per named entry
//   /frames/time (T), /frames/position (T x N x 2), /frames/velocity (T x N x 2)
//                          only with frames enabled; chunked, gzip-compressed, extendible in T
//
// Every dataset is chunked and carries HDF5's Fletcher32 checksum filter, and the file uses
// the HDF5 1.8 object-header format, whose headers (holding the attributes) are checksummed
// too: HDF5 verifies both on read, so damage is found by the reader (core/io/run_reader.h).
//
// The file is written with AtomicOutputFile (core/io/output_file.h), the guard and atomic
// rename every output of collide shares: under a temporary name beside the target
// (".NAME.tmp-PID-K"), renamed into place by commit(), so an existing file is never left
// half-written; if the writer is destroyed without commit() the temporary file is removed and
// the target is untouched. A target that cannot be written (missing directory, no permission,
// a directory in the way, anything but a regular file: a device, a FIFO, a socket, a link to
// nothing) fails in the constructor, before any simulation time is spent. A symbolic link is
// followed: the regular file it points to is replaced and the link is kept.
//
// Every failure throws a std::runtime_error whose message names the file: OutputFileError
// for the path and the rename, Hdf5Error for HDF5 itself.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "core/metrics.h"
#include "core/particle_state.h"
#include "core/solver.h"

namespace collide {

// The root attribute `format_version`. 2: checksums on every dataset (Fletcher32) and on the
// object headers. 1 (before them) is refused by the reader: such a file is run again.
inline constexpr const char* run_format_version = "2";

// The text attributes at the root (provenance, scene text) are stored outside the checksummed
// headers (HDF5 keeps variable-length strings in a heap without checksums), so the writer adds
// the root attribute `attributes_checksum`: crc32_text (core/numerics/crc32.h) of every other root
// attribute, in name order, each as name NUL value NUL.
inline constexpr const char* attributes_checksum_name = "attributes_checksum";
std::string root_attributes_checksum(const std::map<std::string, std::string>& attributes);

class RunWriter {
public:
    RunWriter(const std::string& path, bool write_frames);
    ~RunWriter();
    RunWriter(const RunWriter&) = delete;
    RunWriter& operator=(const RunWriter&) = delete;

    // Root-group string attributes; a key written twice keeps the last value.
    void write_attributes(const std::map<std::string, std::string>& attributes);
    void write_particles(const ParticleState<double>& state);
    // Called once per output time, in order. `state` is used only when frames are enabled.
    void append(const Metrics& metrics, const ParticleState<double>& state);
    void write_stats(const SolverStats& stats);
    void commit();  // flush, close and rename into place; the writer is finished afterwards

    const std::string& path() const;             // the target path
    const std::string& temporary_path() const;   // where the file is written until commit()

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace collide
