// `--set PATH=VALUE` for `run`, `view` and `explain`: the suite's `set` paths, on the command
// line, checked by the scene loader as the same keys in the file would be.
#include <stdexcept>

#include "commands.h"
#include "core/scene/scene_loader.h"

namespace collide::cli {

void add_set_option(CLI::App& cmd, std::vector<SceneOverride>& overrides) {
    cmd.add_option_function<std::vector<std::string>>(
           "--set",
           [&overrides](const std::vector<std::string>& words) {
               for (const std::string& w : words) overrides.push_back(parse_override(w));
           },
           "Change a key of the scene file, PATH=VALUE (e.g. run.dt=2.5e-4, world.boundary=periodic); repeatable")
        ->expected(1)  // one word per --set: `--set a=1 scene.toml` leaves the scene to its place
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
        ->type_name("PATH=VALUE");
}

Scene load_scene_with_overrides(const std::string& path, const std::vector<SceneOverride>& overrides) {
    return scene_with_overrides(load_scene(path), overrides);
}

}  // namespace collide::cli
