#include "box2d_options.h"

#include <cmath>
#include <stdexcept>

namespace collide {
namespace {

// Where a bad value came from, for error messages: "scene 'NAME' (FILE) [backend.box2d] KEY".
std::string where(const Scene& scene, const std::string& key) {
    std::string s = "scene '" + scene.name + "'";
    if (!scene.source_path.empty()) s += " (" + scene.source_path + ")";
    return s + " [backend.box2d] " + key;
}

[[noreturn]] void bad_value(const Scene& scene, const std::string& key, const std::string& value,
                            const std::string& expected) {
    throw std::runtime_error(where(scene, key) + " = '" + value + "': expected " + expected);
}

// Parses the whole text as a number; std::stod alone would accept "8abc".
double parse_number(const Scene& scene, const std::string& key, const std::string& value) {
    std::size_t used = 0;
    double v = 0;
    try {
        v = std::stod(value, &used);
    } catch (const std::exception&) {
        bad_value(scene, key, value, "a number");
    }
    if (used != value.size() || !std::isfinite(v)) bad_value(scene, key, value, "a finite number");
    return v;
}

int parse_positive_int(const Scene& scene, const std::string& key, const std::string& value) {
    const double v = parse_number(scene, key, value);
    if (v < 1 || v != std::floor(v) || v > 1e6) bad_value(scene, key, value, "a whole number >= 1");
    return int(v);
}

bool parse_bool(const Scene& scene, const std::string& key, const std::string& value) {
    if (value == "true") return true;
    if (value == "false") return false;
    bad_value(scene, key, value, "true or false");
}

}  // namespace

Box2dOptions parse_box2d_options(const Scene& scene) {
    Box2dOptions o;
    const auto table = scene.backend_options.find("box2d");
    if (table == scene.backend_options.end()) return o;
    for (const auto& [key, value] : table->second) {
        if (key == "restitution_threshold") {
            o.restitution_threshold = parse_number(scene, key, value);
            if (o.restitution_threshold < 0) bad_value(scene, key, value, "a speed >= 0");
        } else if (key == "velocity_iterations") {
            o.velocity_iterations = parse_positive_int(scene, key, value);
        } else if (key == "position_iterations") {
            o.position_iterations = parse_positive_int(scene, key, value);
        } else if (key == "substeps") {
            o.substeps = parse_positive_int(scene, key, value);
        } else if (key == "bullet") {
            o.bullet = parse_bool(scene, key, value);
        } else if (key == "length_scale") {
            o.length_scale = parse_number(scene, key, value);
            if (*o.length_scale <= 0) bad_value(scene, key, value, "a scale > 0 (Box2D metres per scene unit)");
        } else {
            throw std::runtime_error(where(scene, key) +
                                     ": unknown key; expected one of restitution_threshold, velocity_iterations, "
                                     "position_iterations, substeps, bullet, length_scale");
        }
    }
    return o;
}

}  // namespace collide
