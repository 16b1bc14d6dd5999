#include "suite_runner.h"

#include <chrono>
#include <filesystem>
#include <map>

#include "case_execution.h"
#include "case_isolation.h"
#include "core/scene_loader.h"
#include "progress.h"
#include "scene_parameters.h"
#include "summary_writer.h"

namespace collide::validation {

std::size_t SuiteOutcome::count(CheckStatus s) const {
    std::size_t n = 0;
    for (const auto& c : checks) n += c.status == s;
    return n;
}

namespace {

std::vector<Scene> load_scenes(const Suite& suite) {
    std::vector<Scene> scenes;
    for (const SuiteScene& entry : suite.scenes) {
        Scene scene = entry.scene ? *entry.scene : load_scene(entry.path);
        if (scene.name.empty()) scene.name = entry.name;
        scenes.push_back(std::move(scene));
    }
    return scenes;
}

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

// Cases that already have a readable result file from an earlier run (for --resume).
std::map<std::string, CaseResult> finished_results(const std::vector<CaseSpec>& specs, const std::string& dir) {
    std::map<std::string, CaseResult> done;
    for (const CaseSpec& spec : specs) {
        const std::string path = result_path(dir, spec.id);
        if (!std::filesystem::exists(path)) continue;
        try {
            done.emplace(spec.id, read_case_result(path));
        } catch (const std::exception&) {
            // An unreadable result counts as not finished: the case runs again.
        }
    }
    return done;
}

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

}  // namespace

SuiteOutcome run_suite(const Suite& suite, const std::vector<BackendInfo>& available, const RunnerOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<const BackendInfo*> backends = select_backends(suite, available);
    const std::vector<Scene> scenes = load_scenes(suite);  // bad scene files fail here, before any case
    const CaseScenes case_scenes(suite, scenes);
    std::vector<SceneFeatures> features;
    // Per scene for the comparisons (which only ask about the disks' radii): its first sweep point.
    for (std::size_t s = 0; s < scenes.size(); ++s) features.push_back(case_scenes.features.lower_bound({s, ""})->second);
    const std::vector<CaseSpec> specs = plan_cases(suite, scenes, backends);

    std::filesystem::create_directories(options.output_dir);
    const std::string result_dir = options.output_dir + "/cases";
    std::map<std::string, CaseResult> results;
    // MPI hook: rank 0 alone decides what is finished (every record is in its directory).
    const bool judges = !options.dispatch || options.dispatch->is_root();
    if (options.resume && judges) results = finished_results(specs, result_dir);

    SuiteOutcome outcome;
    outcome.cases_resumed = results.size();
    std::vector<CaseSpec> to_run;
    for (const auto& spec : specs)
        if (!results.count(spec.id)) to_run.push_back(spec);

    std::map<std::string, const BackendInfo*> by_name;
    for (const BackendInfo* b : backends) by_name[b->name] = b;
    IsolationOptions isolation{options.jobs, suite.time_limit_seconds, result_dir};
    auto run_case = [&](const CaseSpec& spec) {
        CaseContext context{&suite, &case_scenes.scene(spec), by_name.at(spec.backend), options.output_dir};
        return execute_case(spec, context);
    };
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
        run_isolated(to_run, isolation, run_case, [&](const CaseResult& r) {
            ++done;
            if (r.status != RunStatus::completed && r.status != RunStatus::left_out) ++failed;
            results[r.spec.id] = r;
            if (progress) progress->update(done, failed, r.spec.id);
        });
    }
    if (progress) progress->finish();
    outcome.execution = options.dispatch ? options.dispatch->execution() : serial_execution(options.jobs);
    outcome.cases_run = to_run.size();

    // Judge every case in plan order, then the comparisons with the reference.
    std::map<std::string, Tolerances> tolerances;
    for (const BackendInfo* b : backends) tolerances[b->name] = suite.tolerances.for_backend(b->name, b->precision);
    for (const CaseSpec& spec : specs) {
        outcome.cases.push_back(results.at(spec.id));
        const auto checks = case_checks(outcome.cases.back(), case_scenes.feature(spec), tolerances.at(spec.backend));
        outcome.checks.insert(outcome.checks.end(), checks.begin(), checks.end());
    }
    if (suite.stability) classify_all(outcome, case_scenes, tolerances);
    Comparisons comparisons = compare_with_reference(suite, outcome.cases, features, tolerances);
    outcome.checks.insert(outcome.checks.end(), comparisons.checks.begin(), comparisons.checks.end());
    outcome.work_precision = std::move(comparisons.work_precision);
    outcome.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    write_summary_json(suite, outcome, options.output_dir + "/summary.json");
    write_junit_xml(suite, outcome, options.output_dir + "/junit.xml");
    return outcome;
}

}  // namespace collide::validation
