#include "validation/explain/case_replay.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "validation/run/case_execution.h"
#include "core/scene/scene_loader.h"
#include "validation/plan/scene_parameters.h"
#include "validation/plan/suite.h"

namespace collide::validation {

namespace {

// The case's scene: the suite's sweep parameters and settings, then the overrides, whose run
// settings and seed win over the suite's (a user who says --set run.dt=1e-4 means it).
Scene scene_of_case(const Scene& base, const SuiteScene& entry, const CaseSpec& spec,
                    const std::vector<SceneOverride>& overrides) {
    const Scene changed = scene_with_overrides(scene_with_parameters(base, spec.parameters), overrides);
    Scene out = case_scene(changed, entry, spec);
    for (const SceneOverride& o : overrides) {
        if (o.path == "seed") out.seed = changed.seed;
        if (o.path == "run.dt") out.run.dt = changed.run.dt;
        if (o.path == "run.substeps") out.run.substeps = changed.run.substeps;
        if (o.path == "run.duration") out.run.duration = changed.run.duration;
        if (o.path == "run.output_interval") out.run.output_interval = changed.run.output_interval;
    }
    const std::string problem = run_settings_problem(out.run);
    if (!problem.empty())
        throw SceneError("case " + spec.id + " with --set " + overrides_text(overrides) + ": [run]." + problem);
    return out;
}

}  // namespace

ReplayedCase replay_case(const Suite& suite, const std::string& case_id, const std::vector<BackendInfo>& available,
                         const std::vector<SceneOverride>& overrides) {
    const std::string& suite_path = suite.source_path;
    const std::vector<Scene> scenes = load_suite_scenes(suite);
    const std::vector<BackendInfo> backends = select_backends(suite, available);
    const std::vector<CaseSpec> specs = plan_cases(suite, scenes, backends);
    const auto spec = std::find_if(specs.begin(), specs.end(), [&](const CaseSpec& s) { return s.id == case_id; });
    if (spec == specs.end()) {
        std::string names;
        for (const BackendInfo& b : backends) names += (names.empty() ? "" : ", ") + b.name;
        throw std::runtime_error(suite_path + ": the suite plans no case '" + case_id +
                                 "' with the backends this build has (" + names +
                                 "); was the suite file edited since the run, or the case id mistyped?");
    }
    if (!spec->left_out.empty())
        throw std::runtime_error("case " + case_id + " was left out, not run: " + spec->left_out);
    const auto backend = std::find_if(backends.begin(), backends.end(),
                                      [&](const BackendInfo& b) { return b.name == spec->backend; });
    const SuiteScene& entry = suite.scenes[spec->scene_index];
    ReplayedCase out{*spec, scene_of_case(scenes[spec->scene_index], entry, *spec, overrides), {}, *backend,
                     case_backend_options(*spec)};
    out.initial = case_initial_state(out.scene, entry, spec->seed);
    return out;
}

namespace {

void require_equal(const std::string& id, const char* what, double rebuilt, double recorded) {
    if (rebuilt != recorded)
        throw std::runtime_error("case " + id + ": the rebuilt case has " + what + " = " + std::to_string(rebuilt) +
                                 ", the run recorded " + std::to_string(recorded) +
                                 " (the suite or scene file was edited since the run; validate again)");
}

}  // namespace

void require_same_start(const ReplayedCase& replay, const CaseResult& record) {
    const std::string& id = replay.spec.id;
    require_equal(id, "dt", replay.scene.run.dt, record.dt);
    require_equal(id, "substeps", replay.scene.run.substeps, record.substeps);
    require_equal(id, "duration", replay.scene.run.duration, record.duration);
    require_equal(id, "the number of disks", double(replay.initial.size()), double(record.disks));
    const Snapshot& s = record.initial;
    if (s.x.size() != replay.initial.size()) return;  // a record without the initial state
    for (std::size_t i = 0; i < s.x.size(); ++i)
        if (s.x[i] != replay.initial.x[i] || s.y[i] != replay.initial.y[i] || s.vx[i] != replay.initial.vx[i] ||
            s.vy[i] != replay.initial.vy[i])
            throw std::runtime_error("case " + id + ": disk " + std::to_string(i) +
                                     " starts elsewhere or otherwise than the run recorded (the suite or scene file "
                                     "was edited since the run; validate again)");
}

std::optional<double> recorded_kinetic_energy(const CaseResult& record, double t) {
    for (const Metrics& row : record.series)
        if (std::fabs(row.time - t) <= 1e-9 * record.dt) return row.kinetic_energy;
    return std::nullopt;
}

}  // namespace collide::validation
