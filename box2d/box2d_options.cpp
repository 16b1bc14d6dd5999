#include "box2d_options.h"

#include <box2d/box2d.h>

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

// Box2D 2.4 as it comes: every value read from objects Box2D itself initialises, so that a
// different Box2D build cannot silently disagree with a copied number. The iteration counts
// are the exception: Box2D 2.4 has no default for them, and its manual recommends 8 and 3.
Box2dOptions shipped_options() {
    const b2World world(b2Vec2(0.0f, 0.0f));
    const b2BodyDef body;
    Box2dOptions o;
    o.preset = "shipped";
    o.restitution_threshold.reset();  // the solver leaves b2FixtureDef's value (1 m/s) alone
    o.velocity_iterations = 8;
    o.position_iterations = 3;
    o.bullet = body.bullet;
    o.length_scale = 1.0;  // scene units are metres
    o.sleeping = world.GetAllowSleeping() && body.allowSleep;
    o.warm_starting = world.GetWarmStarting();
    o.continuous = world.GetContinuousPhysics();
    o.fixed_rotation = body.fixedRotation;
    return o;
}

// Applies one key other than `preset` to `o`.
void apply_key(const Scene& scene, const std::string& key, const std::string& value, Box2dOptions& o) {
    if (key == "restitution_threshold") {
        o.restitution_threshold = parse_number(scene, key, value);
        if (*o.restitution_threshold < 0) bad_value(scene, key, value, "a speed >= 0");
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
    } else if (key == "sleeping") {
        o.sleeping = parse_bool(scene, key, value);
    } else if (key == "warm_starting") {
        o.warm_starting = parse_bool(scene, key, value);
    } else if (key == "continuous") {
        o.continuous = parse_bool(scene, key, value);
    } else if (key == "fixed_rotation") {
        o.fixed_rotation = parse_bool(scene, key, value);
    } else {
        throw std::runtime_error(where(scene, key) +
                                 ": unknown key; expected one of preset, restitution_threshold, velocity_iterations, "
                                 "position_iterations, substeps, bullet, length_scale, sleeping, warm_starting, "
                                 "continuous, fixed_rotation");
    }
}

}  // namespace

std::optional<Box2dOptions> box2d_preset(const std::string& name) {
    if (name == "tuned") return Box2dOptions{};
    if (name == "shipped") return shipped_options();
    return std::nullopt;
}

Box2dOptions parse_box2d_options(const Scene& scene) {
    const auto table = scene.backend_options.find("box2d");
    if (table == scene.backend_options.end()) return Box2dOptions{};
    const auto preset = table->second.find("preset");
    const std::string name = preset == table->second.end() ? "tuned" : preset->second;
    const auto base = box2d_preset(name);
    if (!base) bad_value(scene, "preset", name, "\"tuned\" or \"shipped\"");
    Box2dOptions o = *base;
    for (const auto& [key, value] : table->second)
        if (key != "preset") apply_key(scene, key, value, o);
    return o;
}

}  // namespace collide
