// RunFile: a run file (RunWriter, docs/output-format.md) read back with every check its
// readers rely on, so that `collide render`, `--resume` and `collide report` never draw or
// judge a damaged file. Opening a file checks, and names the file, the dataset and what is
// wrong when one fails:
//
//   - what it is: root attribute format = "collide-run" and format_version = 2 (a file of
//     format 1, written before checksums, is refused with "written by an older collide");
//   - structure: every dataset the readers use exists, holds 8-byte numbers of the right kind
//     (float or integer), has the shape the file implies (N disks from /particles/radius,
//     T outputs from /metrics/time) and carries its Fletcher32 checksum filter;
//   - integrity: HDF5 verifies each chunk's checksum (and the object headers' checksums)
//     as it reads, so a flipped bit or a cut-short file fails to read; the root text
//     attributes (scene text, provenance) must match /attributes_checksum;
//   - values the file itself guarantees: radius and mass finite and > 0, inv_mass 1/mass or
//     0 (a stone), times finite and non-decreasing, kinetic energy and overlap measures not
//     negative, counts within range, frame times equal to the metric times.
//
// Frames are read one at a time (a long run's frames need not fit in memory); each frame is
// checked against the run's own record: the disks with a NaN or Inf coordinate or velocity
// must be exactly those /metrics/nonfinite counted when the run wrote the frame. A frame that
// holds non-finite values the run never recorded is damage.
#pragma once

#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/io/hdf5_handle.h"
#include "core/metrics.h"
#include "core/particle_state.h"
#include "core/solver.h"

namespace collide {

// Every check that fails throws RunFileError; its message starts with the file's path.
class RunFileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class RunFile {
public:
    explicit RunFile(const std::string& path);

    const std::string& path() const { return path_; }
    std::size_t disk_count() const { return constants_.radius.size(); }
    std::size_t output_count() const { return metrics_.at("time").size(); }
    bool has_frames() const { return has_frames_; }

    // A root string attribute (scene_text, backend, ...); throws when it is missing.
    std::string attribute(const std::string& name) const;
    // radius, mass and inv_mass, checked; x, y, vx, vy sized N.
    const ParticleState<double>& constants() const { return constants_; }
    // /metrics/<name> for a column of the run schema (core/io/run_schema.h), one value per output
    // (count columns converted to double).
    const std::vector<double>& metric(const std::string& name) const;
    // Every column at output k, as the run computed them.
    Metrics metrics_at(std::size_t k) const;
    // Every root attribute (all are text), by name.
    std::map<std::string, std::string> root_attributes() const;
    // /stats as the run recorded it (RunWriter::write_stats): steps and contacts, the wall time
    // per phase and the backend's counters; each attribute an 8-byte number of its kind.
    SolverStats stats() const;

    // Frames (only with has_frames()): the time of each, and the state at frame k.
    const std::vector<double>& frame_times() const { return frame_times_; }
    void read_frame(std::size_t k, ParticleState<double>& out) const;
    // Reads every frame, so every checksum of the file has been verified.
    void verify_frames() const;

private:
    [[noreturn]] void fail(const std::string& what) const;
    Hdf5Handle open_dataset(const std::string& name, bool integer, const std::vector<hsize_t>& shape) const;
    std::vector<double> read_all(const std::string& name, bool integer, const std::vector<hsize_t>& shape) const;
    void check_format() const;
    void read_constants();
    void read_metrics();
    void read_frame_times();
    void check_frame(std::size_t k, const ParticleState<double>& state) const;

    std::string path_;
    Hdf5Handle file_;
    ParticleState<double> constants_;
    std::map<std::string, std::vector<double>> metrics_;
    bool has_frames_ = false;
    std::vector<double> frame_times_;
};

}  // namespace collide
