#include "case_replay.h"

#include <algorithm>
#include <stdexcept>

#include "case_execution.h"
#include "scene_parameters.h"
#include "suite.h"

namespace collide::validation {

ReplayedCase replay_case(const std::string& suite_path, const std::string& case_id,
                         const std::vector<BackendInfo>& available) {
    const Suite suite = load_suite(suite_path);
    const std::vector<Scene> scenes = load_suite_scenes(suite);
    const std::vector<BackendInfo> backends = select_backends(suite, available);
    const std::vector<CaseSpec> specs = plan_cases(suite, scenes, backends);
    const auto spec = std::find_if(specs.begin(), specs.end(), [&](const CaseSpec& s) { return s.id == case_id; });
    if (spec == specs.end())
        throw std::runtime_error(suite_path + ": the suite plans no case '" + case_id +
                                 "' (was the suite file edited since the run, or the case id mistyped?)");
    const auto backend = std::find_if(backends.begin(), backends.end(),
                                      [&](const BackendInfo& b) { return b.name == spec->backend; });
    const SuiteScene& entry = suite.scenes[spec->scene_index];
    ReplayedCase out{*spec, case_scene(scene_with_parameters(scenes[spec->scene_index], spec->parameters), entry, *spec),
                     {}, *backend, case_backend_options(*spec)};
    out.initial = case_initial_state(out.scene, entry, spec->seed);
    return out;
}

}  // namespace collide::validation
