// Suite: what a validation run does, as read from validation/suites/*.toml (format in
// docs/validation.md). A suite names scenes, backends, parameter sweeps, replicate seeds,
// tolerances and output options; case_plan.h expands it into the list of cases to run.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/scene/scene.h"
#include "external/external_solver.h"
#include "validation/record/tolerances.h"

namespace collide::validation {

// Thrown for any problem with a suite file; the message names the file, the key and what
// was expected, e.g. "suites/x.toml: [[scene]] #2 .dt: expected an array of positive numbers".
class SuiteError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// How the cases of one scene are compared with the reference backend.
enum class Comparison {
    none,        // only the per-case checks (conservation, overlaps)
    trajectory,  // few bodies, short horizon: positions at every output time vs the reference
    statistics,  // many bodies: observables averaged over replicates vs the reference
};
const char* to_string(Comparison c);

// A sweep over values of one key of the scene file, e.g. "particles.0.disks.1.mass" = [1, 1e9]:
// the path names tables by key and arrays by index (scene_parameters.h applies it).
struct SceneParameter {
    std::string path;
    std::vector<double> values;
};

struct SuiteScene {
    std::string name;                 // scene file stem; also the name used in case ids
    std::string path;                 // resolved scene file path ("" when `scene` is given)
    std::optional<Scene> scene;       // a scene built in code (tests); overrides `path`
    Comparison comparison = Comparison::none;
    std::vector<double> dt;           // sweep; empty = the scene's own dt
    std::vector<int> substeps;        // sweep; empty = the scene's own substeps
    std::vector<int> iterations;      // sweep of a backend's solver iterations (box2d); empty = default
    std::vector<std::uint64_t> seeds; // replicates; empty = the suite's seeds
    std::vector<SceneParameter> set;  // scene-key sweeps (all combinations, crossed with dt)
    std::optional<double> duration;   // overrides [run].duration of the scene
    std::optional<double> output_interval;
    std::optional<bool> frames;       // overrides [output].frames for this scene's cases
    int line = 0;                     // in the suite file: of dt (or the overrides), else [[scene]]
    std::vector<std::string> physics; // rows of "Reference against physics" it feeds (physics_rows.h)
    std::vector<std::string> backends;// only these backends run it (empty: the suite's backends)
    // A published finite-N pressure this scene is held to, "KEY:ID" (data/references/KEY.toml,
    // its [[rows]] entry ID; validation/compare/published_rows.h); "" when none.
    std::string published;
};

// One backend run with settings of its own, reported as a backend of its own: the suite's
// [variant."box2d[shipped]"] table gives label "box2d[shipped]", base "box2d", and settings
// that every case of this variant writes into the scene's [backend.box2d] table (over the
// scene's own keys), e.g. {"preset": "shipped"}. Tolerances: [tolerances."box2d[shipped]"].
struct BackendVariant {
    std::string label;
    std::string base;
    std::map<std::string, std::string> settings;  // values as text, like Scene::backend_options
    // Checks that do not apply to what this variant simulates (leave_out = [...]), each then
    // reported as left out with leave_out_reason instead of judged against a tolerance.
    std::vector<std::string> leave_out;
    std::string leave_out_reason;
};

struct OutputOptions {
    bool hdf5 = true;                 // one HDF5 file per case (RunWriter)
    bool frames = false;              // positions and velocities at every output time
    std::size_t max_overlap_samples = 20000;  // overlap depths kept per case for histograms
    std::size_t max_trajectory_disks = 64;    // record trajectories only up to this many disks
};

// When the report's per-backend verdict names a fact beside the passes and fails (suite table
// [verdicts]; docs/reading-a-report.md, "Where each verdict is decided"). They never change
// whether a check passes; validation/summary/verdict_facts.h decides with them.
struct VerdictThresholds {
    double loose_tolerance_ratio = 5;  // a tolerance this many times the other backends' median
    double energy_drift = 0.01;        // a largest energy drift of at least this (1 %)
    double pressure_sigmas = 3;        // a resolved pressure difference of at least this many SE
    // The accuracy a backend's "use for" verdict states (accuracy_verdicts.h): its trajectory
    // error within this many r_min, its Z, a cooling gas's Haff cooling time tau and (where Z is
    // left out) its collision rate within these relative differences of the reference's.
    double trajectory_accuracy = 1e-2;
    double pressure_accuracy = 5e-3;
    double cooling_accuracy = 5e-3;
    double collision_rate_accuracy = 5e-3;
};

struct Suite {
    std::string name;
    std::string description;
    std::string source_path;          // the suite file ("" when built in code)
    std::string reference_dir;        // published references (data/references), resolved
    std::vector<std::string> backends;  // names; {"all"} = every backend given to the runner,
                                        // then every variant whose base is among them
    std::vector<BackendVariant> variants;
    std::string reference = "event";  // the backend the comparisons are made against
    std::vector<std::uint64_t> seeds = {1};
    double time_limit_seconds = 120;  // per case; a case running longer is killed and fails
    double warmup_fraction = 0.1;     // of the duration, run once before the timed run
    bool stability = false;           // classify every case by failure mode (stability.h)
    OutputOptions output;
    VerdictThresholds verdicts;
    // The relative standard error each backend's published finite-N rows must reach
    // ([published_precision] NAME = x); a backend not named: 2e-4 (published_rows.h).
    std::map<std::string, double> published_precision;
    ToleranceTable tolerances;
    std::vector<SuiteScene> scenes;
    // Outside solvers ([solver.NAME], --solver): backends of this run (external_solvers.h).
    std::vector<external::ExternalSolverSpec> solvers;
};

// Whether the run file of a case of `entry` holds frames (positions and velocities at every
// output time): the scene's own `frames`, else the suite's [output] frames.
bool stores_frames(const Suite& suite, const SuiteScene& entry);

Suite load_suite(const std::string& path);

// The scene of every [[scene]] entry, in order (a scene file's, or the suite's inline one).
std::vector<Scene> load_suite_scenes(const Suite& suite);
// `source_dir` resolves relative scene paths (the suite file's directory).
Suite parse_suite(const std::string& text, const std::string& source_name, const std::string& source_dir);

}  // namespace collide::validation
