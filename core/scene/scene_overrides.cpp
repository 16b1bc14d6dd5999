#include "core/scene/scene_overrides.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>

#include "core/scene/scene_loader.h"
#include "core/scene/toml_fields.h"
#include "core/text/printable.h"

namespace collide {
namespace {

std::vector<std::string> split_path(const std::string& path) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        const auto dot = path.find('.', start);
        parts.push_back(path.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
        if (dot == std::string::npos) return parts;
        start = dot + 1;
    }
}

std::string where(const std::string& walked) {
    return walked.empty() ? std::string("the scene's top level") : "'" + walked + "'";
}

// The element `part` of the array `a` (an index that exists), or `fail`.
toml::node* element(toml::array& a, const std::string& part, const std::string& walked, const TomlPathFail& fail) {
    char* end = nullptr;
    const unsigned long index = std::strtoul(part.c_str(), &end, 10);
    if (*end != '\0' || part[0] == '-') fail("'" + part + "' is not an index of the array " + where(walked));
    if (index >= a.size())
        fail("no element " + part + " in " + where(walked) + " (it has " + std::to_string(a.size()) + ")");
    return a.get(index);
}

// The text after '=' as a TOML node: a TOML value, else (a bare word) a string.
toml::table value_holder(const SceneOverride& o) {
    const std::string line = "value = " + o.value;
    check_toml_nesting(line, "--set " + shortened(o.path));  // before toml++ recurses into [[[[...
    try {
        return toml::parse(line);
    } catch (const toml::parse_error& e) {
        if (o.value.find_first_of("\"'[]{}=#\n") != std::string::npos || o.value.empty())
            throw SceneError("--set " + shortened(o.text()) + ": the value is no TOML value (" +
                             std::string(e.description()) + ")");
        toml::table t;
        t.insert("value", o.value);
        return t;
    }
}

// Puts `value` at the last part of the path, under `parent`.
void put(toml::node& parent, const std::string& last, const std::string& walked, const toml::node& value,
         const TomlPathFail& fail) {
    if (toml::table* t = parent.as_table()) {
        value.visit([&](const auto& v) { t->insert_or_assign(last, v); });
    } else if (toml::array* a = parent.as_array()) {
        element(*a, last, walked, fail);  // the index must exist
        const auto at = a->cbegin() + static_cast<std::ptrdiff_t>(std::strtoul(last.c_str(), nullptr, 10));
        value.visit([&](const auto& v) { a->replace(at, v); });
    } else {
        fail(where(walked) + " is a value, not a table or an array, so it has no '" + last + "'");
    }
}

}  // namespace

void check_path_depth(const std::string& path, const TomlPathFail& fail) {
    const auto parts = std::count(path.begin(), path.end(), '.') + 1;
    if (parts > max_key_parts)
        fail("a path with more than " + std::to_string(max_key_parts) + " dotted parts (it has " +
             std::to_string(parts) + "): expected at most " + std::to_string(max_key_parts) +
             ", as for a key in a scene file");
}

toml::node* find_toml_path(toml::table& root, const std::string& path, const TomlPathFail& fail, bool add_tables) {
    check_path_depth(path, fail);
    toml::node* node = &root;
    std::string walked;
    for (const std::string& part : split_path(path)) {
        if (part.empty()) fail("an empty component");
        if (toml::table* t = node->as_table()) {
            node = t->get(part);
            if (!node && add_tables) node = t->insert(part, toml::table{}).first->second.as_table();
            if (!node) fail("no key '" + part + "' in " + where(walked));
        } else if (toml::array* a = node->as_array()) {
            node = element(*a, part, walked, fail);
        } else {
            fail(where(walked) + " is a value, not a table or an array, so it has no '" + part + "'");
        }
        walked += (walked.empty() ? "" : ".") + part;
    }
    return node;
}

Scene scene_from_changed_table(const toml::table& root, const Scene& original) {
    Scene out = read_scene_table(root, original.source_path.empty() ? original.name : original.source_path);
    std::ostringstream text;
    text << root << "\n";
    out.source_text = text.str();
    out.name = original.name;
    out.source_path = original.source_path;
    return out;
}

SceneOverride parse_override(const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
        throw SceneError("--set " + text + ": expected PATH=VALUE, e.g. run.dt=2.5e-4 or world.boundary=periodic");
    return {text.substr(0, eq), text.substr(eq + 1)};
}

Scene scene_with_overrides(const Scene& scene, const std::vector<SceneOverride>& overrides) {
    if (overrides.empty()) return scene;
    const std::string file = scene.source_path.empty() ? scene.name : scene.source_path;
    if (scene.source_text.empty()) throw SceneError(file + ": --set: the scene has no source text to change");
    toml::table root = toml::parse(scene.source_text, file);  // parsed once before, so it parses
    for (const SceneOverride& o : overrides) {
        const TomlPathFail fail = [&](const std::string& why) {
            throw SceneError(file + ": --set " + shortened(printable(o.text())) + ": " + why);
        };
        // A line break would end the value's TOML line: "run.dt=0.002\n# x" ran with 0.002 and
        // recorded the whole text. Any control character is refused, so what runs is what is recorded.
        if (has_control_character(o.path) || has_control_character(o.value))
            fail(std::string("the ") + (has_control_character(o.path) ? "path" : "value") +
                 " holds a control character (shown as \\xNN); a --set is one line of printable text");
        check_path_depth(o.path, fail);  // before a table is added for each part
        const auto dot = o.path.rfind('.');
        const std::string last = dot == std::string::npos ? o.path : o.path.substr(dot + 1);
        if (last.empty()) fail("an empty component");
        toml::node* parent = dot == std::string::npos ? &root : find_toml_path(root, o.path.substr(0, dot), fail, true);
        const toml::table holder = value_holder(o);
        put(*parent, last, dot == std::string::npos ? "" : o.path.substr(0, dot), *holder.get("value"), fail);
    }
    try {
        Scene out = scene_from_changed_table(root, scene);
        out.overrides = (scene.overrides.empty() ? "" : scene.overrides + "; ") + overrides_text(overrides);
        return out;
    } catch (const SceneError& e) {
        // The loader's message as a file with these values would get it, then where they came from.
        throw SceneError(std::string(e.what()) + " (with --set " + shortened(overrides_text(overrides)) + ")");
    }
}

std::string overrides_text(const std::vector<SceneOverride>& overrides) {
    std::string text;
    for (const SceneOverride& o : overrides) text += (text.empty() ? "" : "; ") + o.text();
    return text;
}

}  // namespace collide
