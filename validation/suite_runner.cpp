#include "validation/suite_runner.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <thread>
#include <sstream>

#include "validation/compare/reference_comparison.h"
#include "validation/compare/reference_runs.h"
#include "validation/judge/checks.h"
#include "validation/judge/stability.h"
#include "validation/record/exact_limits.h"
#include "validation/plan/backend_variant.h"
#include "validation/plan/case_definition.h"
#include "validation/run/case_execution.h"
#include "validation/run/case_isolation.h"
#include "core/io/hdf5_handle.h"
#include "core/io/output_file.h"
#include "core/scene/scene_loader.h"
#include "validation/run/progress.h"
#include "validation/plan/scene_parameters.h"
#include "validation/summary/summary_writer.h"
#include "validation/explain/report_jumps.h"

namespace collide::validation {

namespace {

// The scene of every (scene, parameter point) of the suite, built before any case runs so that
// a sweep path that does not exist, or a value a scene rule rejects, stops the suite at once.
// Keyed by scene index and parameter_label; the features decide which checks apply.
struct CaseScenes {
    std::map<std::pair<std::size_t, std::string>, Scene> scenes;
    std::map<std::pair<std::size_t, std::string>, SceneFeatures> features;

    CaseScenes(const Suite& suite, const std::vector<Scene>& base) {
        for (std::size_t s = 0; s < suite.scenes.size(); ++s)
            for (const auto& point : parameter_points(suite.scenes[s])) {
                CaseSpec probe;
                probe.parameters = point;
                const auto key = std::make_pair(s, parameter_label(probe));
                Scene scene = scene_with_parameters(base[s], point);
                try {
                    features[key] = scene_features(scene, generate_initial_state(scene));
                } catch (const SceneError& e) {
                    if (point.empty()) throw;
                    throw SuiteError("[[scene]] " + suite.scenes[s].name + " with " + key.second + ": " + e.what());
                }
                scenes.emplace(key, std::move(scene));
            }
    }
    const Scene& scene(const CaseSpec& c) const { return scenes.at({c.scene_index, parameter_label(c)}); }
    const SceneFeatures& feature(const CaseSpec& c) const { return features.at({c.scene_index, parameter_label(c)}); }
};

// A suite's overrides (dt, duration, output_interval) obey the rules a scene file does: a dt
// that does not divide the output interval would stamp t = 0.1 on the state at t = 0.0999.
void check_case_run_settings(const Suite& suite, const std::vector<Scene>& scenes, const std::vector<CaseSpec>& specs) {
    for (const CaseSpec& spec : specs) {
        const SuiteScene& entry = suite.scenes[spec.scene_index];
        const Scene scene = case_scene(scenes[spec.scene_index], entry, spec);
        const std::string problem = run_settings_problem(scene.run);
        if (problem.empty()) continue;
        std::ostringstream msg;
        msg << (suite.source_path.empty() ? suite.name : suite.source_path);
        if (entry.line) msg << ":" << entry.line;
        msg << ": [[scene]] " << entry.name << " with dt = " << scene.run.dt << ", duration = " << scene.run.duration
            << ", output_interval = " << scene.run.output_interval << ": " << problem;
        throw SuiteError(msg.str());
    }
}

// Everything decided before a case runs: the backends, the scenes of every sweep point, the
// cases. Bad input (a scene file, a sweep value, a dt that does not divide the output interval)
// throws here, before anything is written.
struct SuitePlan {
    std::vector<BackendInfo> backends;
    std::vector<Scene> scenes;
    CaseScenes case_scenes;
    std::vector<SceneFeatures> features;  // per scene, its first sweep point (the comparisons ask only the radii)
    std::vector<CaseSpec> specs;

    SuitePlan(const Suite& suite, const std::vector<BackendInfo>& available, std::FILE* progress)
        : backends(select_backends(suite, available)), scenes(load_suite_scenes(suite)), case_scenes(suite, scenes) {
        for (std::size_t s = 0; s < scenes.size(); ++s)
            features.push_back(case_scenes.features.lower_bound({s, ""})->second);
        specs = plan_cases(suite, scenes, backends);
        check_case_run_settings(suite, scenes, specs);
        for (CaseSpec& spec : specs) spec.definition = case_definition(suite, scenes[spec.scene_index], spec, progress);
    }
};

// The reference run a case is classified against: same scene, parameters and seed, and the
// same dt when the reference ran per dt (trajectory scenes).
const CaseResult* reference_for(const CaseResult& r, const std::vector<CaseResult>& all) {
    const CaseResult* found = nullptr;
    for (const CaseResult& q : all)
        if (q.spec.reference && q.spec.scene_index == r.spec.scene_index && q.spec.seed == r.spec.seed &&
            q.spec.parameters == r.spec.parameters && (!q.spec.dt || q.spec.dt == r.spec.dt))
            found = &q;
    return found;
}

// Cases that already have a readable result file from an earlier run (for --resume), whose
// HDF5 file is complete too (a truncated one, e.g. after a full disk, makes the case run again),
// and whose definition (case_definition.h) is the case's now: a case whose scene file, suite
// entry, backend settings, solver or collide build changed runs again, and so does one that
// timed out; one line says how many and why ("3 cases rerun: scene file changed (2), timed out
// before (1)").
std::map<std::string, CaseResult> finished_results(const std::vector<CaseSpec>& specs, const std::string& output_dir,
                                                   std::FILE* progress) {
    std::map<std::string, CaseResult> done;
    std::map<std::string, std::size_t> reasons;  // "duration changed" -> cases
    std::size_t changed = 0;
    for (const CaseSpec& spec : specs) {
        const std::string path = result_path(output_dir + "/cases", spec.id);
        if (!std::filesystem::exists(path)) continue;
        try {
            CaseResult result = read_case_result(path);
            std::vector<std::string> why = {"no definition in the record (an older collide)"};
            if (!result.spec.definition.empty()) {
                why.clear();
                for (const std::string& part : changed_parts(result.spec.definition, spec.definition))
                    why.push_back(part + " changed");
            }
            // A case killed at the time limit says how long the machine took that hour (or how
            // long it stood stopped), not what the case gives: it runs again.
            if (result.status == RunStatus::timed_out) why.push_back("timed out before");
            if (!why.empty()) {
                ++changed;
                for (const std::string& reason : why) ++reasons[reason];
                continue;
            }
            const std::string problem = case_files_problem(result, output_dir);
            if (!problem.empty()) throw std::runtime_error(problem);
            done.emplace(spec.id, std::move(result));
        } catch (const std::exception& e) {
            // An unreadable result counts as not finished: the case runs again.
            if (progress) std::fprintf(progress, "resume: running %s again: %s\n", spec.id.c_str(), e.what());
        }
    }
    if (progress && changed) {
        std::string why;
        for (const auto& [reason, cases] : reasons) why += (why.empty() ? "" : ", ") + reason + " (" + std::to_string(cases) + ")";
        std::fprintf(progress, "resume: %zu case%s rerun: %s\n", changed, changed == 1 ? "" : "s", why.c_str());
    }
    return done;
}

// An advisory lock (flock) on OUT/.lock, held until the suite is written: a second `collide
// validate` into the same directory would remove and rewrite the first one's case files under
// it. The holder's process id is written in the file, so the refusal can name it. The kernel
// releases the lock when the holder exits, however it ends (a SIGKILL too).
class OutputDirectoryLock {
public:
    explicit OutputDirectoryLock(const std::string& dir) : path_(dir + "/.lock") {
        // Through the output guard: a `.lock` that is a link (out of the directory, to a device)
        // is refused, not followed and truncated (core/io/output_file.h).
        fd_ = open_output_stream(path_, StreamStart::as_it_is);
        if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
            const std::string holder = holder_pid();
            ::close(fd_);
            throw std::runtime_error(dir + ": another `collide validate` (process " + holder +
                                     ") is writing into this directory; wait for it or choose another --out");
        }
        const std::string pid = std::to_string(::getpid()) + "\n";
        if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, pid.data(), pid.size(), 0) < 0) {}  // the lock is what counts
    }
    ~OutputDirectoryLock() { ::close(fd_); }
    OutputDirectoryLock(const OutputDirectoryLock&) = delete;
    OutputDirectoryLock& operator=(const OutputDirectoryLock&) = delete;

private:
    std::string holder_pid() const {
        char text[32] = {};
        const ssize_t n = ::pread(fd_, text, sizeof text - 1, 0);
        std::string pid(text, n > 0 ? std::size_t(n) : 0);
        while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
        return pid.empty() ? "unknown" : pid;
    }
    std::string path_;
    int fd_ = -1;
};

// One outcome per case (stability.h), and a `stability` check per case so that the check
// table, the JUnit file and the exit code show the unstable cases too.
void classify_all(SuiteOutcome& outcome, const CaseScenes& case_scenes, const std::map<std::string, Tolerances>& tolerances) {
    for (const CaseResult& r : outcome.cases) {
        const Classification c = classify(r, reference_for(r, outcome.cases), case_scenes.feature(r.spec),
                                          tolerances.at(r.spec.backend));
        outcome.classifications.push_back(c);
        CheckResult check;
        check.subject = r.spec.id;
        check.scene = r.spec.scene;
        check.backend = r.spec.backend;
        check.check = "stability";
        check.status = c.outcome == Outcome::stable ? CheckStatus::pass
                       : c.outcome == Outcome::left_out ? CheckStatus::left_out : CheckStatus::fail;
        check.detail = std::string(to_string(c.outcome)) + ": " + c.reason;
        outcome.checks.push_back(check);
    }
}

// Every place the suite writes is checked before the first case runs (core/io/output_file.h):
// a FIFO, a device or a link to nothing named summary.json is refused now, not after an hour.
void check_output_places(const std::string& dir, const std::vector<CaseSpec>& specs, bool hdf5) {
    namespace fs = std::filesystem;
    check_output_directory(dir);
    for (const char* sub : {"/cases", "/runs"}) check_output_directory(dir + sub);
    if (!fs::is_directory(dir)) return;  // created empty: nothing in it to refuse
    for (const char* file : {"/summary.json", "/junit.xml"}) check_output_path(dir + file);
    check_output_stream_path(dir + "/.lock");
    for (const CaseSpec& spec : specs) {
        if (fs::is_directory(dir + "/cases")) check_output_path(result_path(dir + "/cases", spec.id));
        if (fs::is_directory(dir + "/cases")) check_output_stream_path(case_log_path(dir + "/cases", spec.id));
        if (hdf5 && fs::is_directory(dir + "/runs")) check_output_path(dir + "/runs/" + spec.id + ".h5");
    }
}

// An earlier run's summary.json and junit.xml, removed once this run holds the directory: from
// its first case on they would judge records that are no longer theirs, and a run cut short
// (killed, a full disk) would leave them to be read as this run's verdicts by `collide report`,
// `collide compare` or a script. Written again, atomically, when this run ends. A link named
// so is the user's and stays (every writer keeps a link and replaces what it points to,
// core/io/output_file.h): its target is rewritten at the end like the file.
void remove_earlier_verdicts(const std::string& dir) {
    for (const char* file : {"/summary.json", "/junit.xml"}) {
        std::error_code error;
        if (std::filesystem::is_symlink(dir + file, error)) continue;
        std::filesystem::remove(dir + file, error);
        if (error) throw std::runtime_error("cannot remove the earlier run's '" + dir + file + "': " + error.message());
    }
}

// The energy jumps of the drawn cases, explained here, where the solvers run anyway
// (report_jumps.h): each explanation reruns its case up to the jump. `collide report` only reads
// them from summary.json; a report of results someone sent runs no program of theirs.
// `available` are the backends run_suite was given (explain_case plans the suite again, variants
// included: the selected backends would plan each variant twice).
nlohmann::json explain_energy_jumps(const Suite& suite, const std::vector<BackendInfo>& available,
                                    const SuiteOutcome& outcome, const RunnerOptions& options) {
    std::map<std::string, bool> exact;
    for (const auto& [name, backend] : outcome.declared) exact[name] = backend.exact;
    const std::vector<DrawnCase> drawn = cases_to_explain(outcome.cases, outcome.checks, exact);
    if (options.progress && !drawn.empty())
        std::fprintf(options.progress, "looking for energy jumps in %zu drawn case(s), explaining each one found\n",
                     drawn.size());
    return report_energy_jumps(options.output_dir, drawn, &suite, "", available, outcome.jobs)["jumps"];
}

// A kill during the summary's rename leaves its temporary: removed on --resume, and said.
void say_removed(const std::vector<std::string>& names, const std::string& dir, std::FILE* progress) {
    if (names.empty() || !progress) return;
    std::fprintf(progress, "resume: removed %zu temporary file(s) an interrupted run left in %s:", names.size(), dir.c_str());
    for (const std::string& name : names) std::fprintf(progress, " %s", name.c_str());
    std::fprintf(progress, "\n");
}

}  // namespace

int default_jobs() { return std::max(1u, std::thread::hardware_concurrency()); }

bool runs_in_worker(const CaseSpec&) { return true; }

std::vector<CaseSpec> plan_suite(const Suite& suite, const std::vector<BackendInfo>& available) {
    return SuitePlan(suite, available, nullptr).specs;
}

SuiteOutcome run_suite(const Suite& suite, const std::vector<BackendInfo>& available, const RunnerOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    const SuitePlan plan(suite, available, options.progress);
    const std::vector<BackendInfo>& backends = plan.backends;
    const CaseScenes& case_scenes = plan.case_scenes;
    const std::vector<SceneFeatures>& features = plan.features;
    const std::vector<CaseSpec>& specs = plan.specs;

    check_output_places(options.output_dir, specs, suite.output.hdf5);
    std::filesystem::create_directories(options.output_dir);
    // MPI hook: rank 0 alone decides what is finished (every record is in its directory), and
    // alone holds the directory's lock (other ranks may share the directory).
    const bool judges = !options.dispatch || options.dispatch->is_root();
    std::optional<OutputDirectoryLock> lock;
    if (judges) {
        lock.emplace(options.output_dir);
        remove_earlier_verdicts(options.output_dir);
    }
    const std::string result_dir = options.output_dir + "/cases", runs_dir = options.output_dir + "/runs";
    std::map<std::string, CaseResult> results;
    if (options.resume && judges) {
        remove_temporaries(runs_dir, result_dir);  // left by a SIGKILL: no process cleaned them
        say_removed(remove_stale_temporaries(options.output_dir), options.output_dir, options.progress);
        results = finished_results(specs, options.output_dir, options.progress);
    }

    SuiteOutcome outcome;
    outcome.cases_resumed = results.size();
    std::vector<CaseSpec> to_run;
    for (const auto& spec : specs)
        if (!results.count(spec.id)) to_run.push_back(spec);

    std::map<std::string, const BackendInfo*> by_name;
    for (const BackendInfo& b : backends) by_name[b.name] = &b;
    outcome.jobs = options.jobs > 0 ? options.jobs : default_jobs();
    IsolationOptions isolation{outcome.jobs, suite.time_limit_seconds, result_dir, runs_dir, runs_in_worker};
    auto run_case = [&](const CaseSpec& spec) {
        CaseContext context{&suite, &case_scenes.scene(spec), by_name.at(spec.backend), options.output_dir};
        return execute_case(spec, context);
    };
    initialise_hdf5();  // once here, not again in every case process (each writes an HDF5 file)
    std::unique_ptr<Progress> progress;
    if (options.progress) progress = std::make_unique<Progress>(to_run.size(), options.progress, options.progress_is_terminal);
    std::size_t done = 0, failed = 0;
    // --- MPI hook (case_dispatch.h, docs/scaling.md): under an MPI launcher the ranks share
    // the cases out and rank 0 receives every result; the other ranks stop here.
    if (options.dispatch) {
        auto cost = [&](const CaseSpec& s) {
            return estimated_cost(s, case_scene(case_scenes.scene(s), suite.scenes[s.scene_index], s), results);
        };
        CaseWork work{&specs, &results, options.output_dir, isolation, run_case, cost, progress.get()};
        options.dispatch->run(work);
        if (!options.dispatch->is_root()) return outcome;
    } else {  // --- end of the MPI hook
        // Said before the first case finishes, so a user sees at once how the machine is used.
        if (options.progress && !to_run.empty())
            std::fprintf(options.progress, "running %zu cases, %d at a time (--jobs %d)\n", to_run.size(),
                         int(std::min<std::size_t>(std::size_t(outcome.jobs), to_run.size())), outcome.jobs);
        run_isolated(to_run, isolation, run_case, [&](const CaseResult& r) {
            ++done;
            if (r.status != RunStatus::completed && r.status != RunStatus::left_out) ++failed;
            results[r.spec.id] = r;
            if (progress) progress->update(done, failed, r.spec.id);
        });
    }
    if (progress) progress->finish();
    outcome.execution = options.dispatch ? options.dispatch->execution() : serial_execution(outcome.jobs);
    outcome.cases_run = to_run.size();

    // Judge every case in plan order, then the comparisons with the reference. Each case's
    // limits follow from what its backend declares, at the case's scale (an exact solver's
    // counts its collisions from the reference run: exact_limits.h).
    std::map<std::string, Tolerances> tolerances;
    for (const BackendInfo& b : backends) {
        tolerances[b.name] = suite.tolerances.for_backend(b);
        outcome.declared.emplace(b.name, b);
    }
    for (const CaseSpec& spec : specs) outcome.cases.push_back(results.at(spec.id));
    const ReferenceRuns reference_runs(outcome.cases);
    for (const CaseResult& r : outcome.cases) {
        const BackendInfo& backend = *by_name.at(r.spec.backend);
        const RoundingScale scale = rounding_scale(r, case_scenes.scene(r.spec), reference_runs.of(r.spec));
        const auto checks = case_checks(r, case_scenes.feature(r.spec), suite.tolerances.for_case(backend, scale), backend);
        outcome.checks.insert(outcome.checks.end(), checks.begin(), checks.end());
    }
    if (suite.stability) classify_all(outcome, case_scenes, tolerances);
    Comparisons comparisons = compare_with_reference(suite, outcome.cases, features, tolerances, by_name);
    outcome.trajectories = std::move(comparisons.trajectories);
    outcome.checks.insert(outcome.checks.end(), comparisons.checks.begin(), comparisons.checks.end());
    apply_variant_leave_outs(outcome.checks, suite.variants);
    outcome.work_precision = std::move(comparisons.work_precision);
    outcome.physics = compare_with_physics(suite, outcome.cases, [&](const CaseSpec& c) -> const Scene& {
        return case_scenes.scene(c);
    });
    outcome.energy_jumps = explain_energy_jumps(suite, available, outcome, options);
    outcome.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    // summary.json last: its presence says the run is over, and no process of the suite is left
    // to write after it (run_isolated ends every descendant of the cases first).
    write_junit_xml(suite, outcome, options.output_dir + "/junit.xml");
    write_summary_json(suite, outcome, options.output_dir + "/summary.json");
    return outcome;
}

}  // namespace collide::validation
