#include "validation/plan/scene_parameters.h"

#include <cmath>
#include <sstream>
#include <toml++/toml.h>

#include "core/scene/scene_loader.h"
#include "core/scene/toml_fields.h"

namespace collide::validation {
namespace {

std::string number_text(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

void set_number(toml::table& root, const std::string& file, const std::string& path, double value) {
    auto fail = [&](const std::string& why) {
        throw SuiteError(file + ": set \"" + path + "\": " + why + "; expected the path of an existing number");
    };
    toml::node* node = find_toml_path(root, path, fail);
    if (auto* f = node->as_floating_point()) {
        *f = value;
    } else if (auto* i = node->as_integer()) {
        if (value != std::floor(value) || std::fabs(value) > 9e15)
            fail("the key holds an integer and " + number_text(value) + " is not one");
        *i = static_cast<std::int64_t>(value);
    } else {
        fail("the key holds a " + std::string(node->is_string() ? "string" : node->is_table() ? "table"
                                                  : node->is_array() ? "array" : "non-number"));
    }
}

}  // namespace

Scene scene_with_parameters(const Scene& scene, const std::vector<std::pair<std::string, double>>& parameters) {
    if (parameters.empty()) return scene;
    const std::string file = scene.source_path.empty() ? scene.name : scene.source_path;
    if (scene.source_text.empty())
        throw SuiteError(file + ": set: the scene has no source text to change (built in code?)");
    toml::table root = toml::parse(scene.source_text, file);  // parsed once before, so it parses
    std::string applied;
    for (const auto& [path, value] : parameters) {
        set_number(root, file, path, value);
        applied += (applied.empty() ? "" : ", ") + path + " = " + number_text(value);
    }
    try {
        return scene_from_changed_table(root, scene);
    } catch (const SceneError& e) {
        throw SuiteError("with " + applied + ": " + e.what());
    }
}

}  // namespace collide::validation
