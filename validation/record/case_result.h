// CaseResult: what one case measured, written by the process that ran it and read back by
// the runner (cases/<id>.toml). It holds measurements only; the judgement (checks against
// tolerances) is made afterwards by checks.h, so every case is judged the same way, crashed
// ones included.
#pragma once

#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "validation/record/case_spec.h"
#include "core/metrics.h"

namespace collide::validation {

enum class RunStatus {
    completed,  // ran to the end
    left_out,   // the backend refused the scene (reason in `diagnostic`)
    error,      // threw an exception (including NaN/Inf detected by run_scene)
    crashed,    // the process died (signal or exit without a result)
    timed_out,  // killed after the suite's time limit
};
const char* to_string(RunStatus s);
RunStatus run_status_from_string(const std::string& s);

// Metrics at every output time, one row each (the columns are the run schema's,
// core/io/run_schema.h; the case record stores them under the same names).
using MetricSeries = std::vector<Metrics>;

struct Snapshot {  // positions and radii, for pictures and trajectory comparison
    std::vector<double> x, y, vx, vy, radius;
};

struct CaseResult {
    CaseSpec spec;
    RunStatus status = RunStatus::completed;
    std::string diagnostic;        // the error message, signal or left-out reason
    std::size_t disks = 0;
    double total_mass = 0;         // of the mobile disks (scales the momentum drift)
    double duration = 0;           // simulated time
    double dt = 0;                 // the time step the case ran with (scene's or the sweep's)
    int substeps = 1;
    double wall_seconds = 0;       // in advance_to() only, after the warm-up
    double warmup_seconds = 0;
    std::int64_t steps = 0, contacts = 0;
    std::map<std::string, double> phase_seconds, counters;
    std::map<std::string, std::string> provenance;  // the solver's own (device, build options)
    MetricSeries series;
    Snapshot initial, final_state;
    std::vector<double> trajectory_time;       // output times of the recorded trajectory
    std::vector<Snapshot> trajectory;          // positions at those times (few-body scenes only)
    // A reference run of a trajectory scene: its twins' largest separation from it at each of
    // those times [r_min] (twin_runs.h); empty for every other case.
    std::vector<double> twin_separation;
    std::vector<double> overlap_depths;        // relative depths of overlapping pairs, final state
    std::vector<double> compressibility;       // Z = P/(rho kT) per snapshot in the second half
    std::string hdf5_file;                     // relative to the output directory, "" if none

    bool finished() const { return status == RunStatus::completed; }
    // A counter the solver or the pressure record left, NaN where it left none.
    double counter(const std::string& name) const {
        const auto it = counters.find(name);
        return it == counters.end() ? std::nan("") : it->second;
    }
};

// The record's first line is `checksum = "crc32:XXXXXXXX"` over the rest of the file.
void write_case_result(const CaseResult& result, const std::string& path);  // atomic (core/io/output_file.h)
// Throws std::runtime_error naming the file when the record is damaged: no checksum line or one
// that does not match, a field the writer always writes missing or of another type.
CaseResult read_case_result(const std::string& path);

// A case's spec as TOML text and back, left_out included: what the runner hands a worker
// process that runs cases one after another (case_isolation.h). A damaged text throws
// std::runtime_error.
std::string case_spec_text(const CaseSpec& spec);
CaseSpec case_spec_from_text(const std::string& text);

// Why the files of a kept case cannot be trusted (its HDF5 file missing, or failing a check of
// core/io/run_reader.h in any dataset or frame, or with other counts of outputs or disks than
// the case record), or "" when they can. `output_dir` holds runs/. With `frames` false the
// stored frames are left unread (`collide report` reads none; `collide render` checks those it draws).
std::string case_files_problem(const CaseResult& result, const std::string& output_dir, bool frames = true);

// What a case's HDF5 file must agree with: where it is (relative to the output directory, ""
// if none), the host that wrote it when an MPI rank kept it on its own node, and the record's
// counts of outputs and disks. From a record, or from the case's entry in summary.json.
struct RunFileExpectation {
    std::string hdf5_file, hdf5_host;
    std::size_t outputs = 0, disks = 0;
};
RunFileExpectation run_file_expectation(const CaseResult& result);
std::string run_file_problem(const RunFileExpectation& expected, const std::string& output_dir, bool frames);

// Throws std::runtime_error naming the file when the record's bytes do not match its checksum
// (cut short, edited, damaged); parses nothing. `collide report` checks every record so and
// parses those it reads.
void verify_case_record(const std::string& path);

}  // namespace collide::validation
