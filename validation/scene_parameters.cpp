#include "scene_parameters.h"

#include <cmath>
#include <sstream>
#include <toml++/toml.h>

#include "core/scene_loader.h"

namespace collide::validation {
namespace {

std::string number_text(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

std::vector<std::string> split(const std::string& path) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        const auto dot = path.find('.', start);
        parts.push_back(path.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
        if (dot == std::string::npos) return parts;
        start = dot + 1;
    }
}

// Walks `path` from `root` and returns the node it names; `fail` gets what went wrong.
template <typename Fail>
toml::node* find(toml::table& root, const std::string& path, Fail&& fail) {
    toml::node* node = &root;
    std::string walked;
    for (const std::string& part : split(path)) {
        const std::string here = walked.empty() ? std::string("the scene's top level") : "'" + walked + "'";
        if (part.empty()) fail("an empty component");
        if (toml::table* t = node->as_table()) {
            node = t->get(part);
            if (!node) fail("no key '" + part + "' in " + here);
        } else if (toml::array* a = node->as_array()) {
            char* end = nullptr;
            const unsigned long index = std::strtoul(part.c_str(), &end, 10);
            if (*end != '\0' || part[0] == '-')
                fail("'" + part + "' is not an index of the array " + here);
            if (index >= a->size())
                fail("no element " + part + " in " + here + " (it has " + std::to_string(a->size()) + ")");
            node = a->get(index);
        } else {
            fail(here + " is a value, not a table or an array, so it has no '" + part + "'");
        }
        walked += (walked.empty() ? "" : ".") + part;
    }
    return node;
}

void set_number(toml::table& root, const std::string& file, const std::string& path, double value) {
    auto fail = [&](const std::string& why) {
        throw SuiteError(file + ": set \"" + path + "\": " + why + "; expected the path of an existing number");
    };
    toml::node* node = find(root, path, fail);
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
    std::ostringstream text;
    text << root << "\n";
    try {
        Scene out = parse_scene(text.str(), file);
        out.name = scene.name;
        out.source_path = scene.source_path;
        return out;
    } catch (const SceneError& e) {
        throw SuiteError("with " + applied + ": " + e.what());
    }
}

}  // namespace collide::validation
