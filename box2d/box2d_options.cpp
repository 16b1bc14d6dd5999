#include "box2d_options.h"

#include <box2d/box2d.h>

#include <string_view>

#include "core/scene/option_reader.h"

namespace collide {
namespace {

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

// Reads every key but `preset` into `o` (the preset's values are the defaults).
void read_keys(OptionReader& r, Box2dOptions& o) {
    constexpr std::string_view whole = "a whole number >= 1";
    if (const auto t = r.find_double("restitution_threshold", 0, "a speed >= 0 (a number)")) o.restitution_threshold = *t;
    o.velocity_iterations = int(r.get_int("velocity_iterations", o.velocity_iterations, 1, max_box2d_iterations, whole));
    o.position_iterations = int(r.get_int("position_iterations", o.position_iterations, 1, max_box2d_iterations, whole));
    if (const auto n = r.find_int("substeps", 1, max_box2d_iterations, whole)) o.substeps = int(*n);
    o.bullet = r.get_bool("bullet", o.bullet);
    if (const auto s = r.find_double("length_scale", 0, "a scale > 0 (Box2D metres per scene unit)", true))
        o.length_scale = *s;
    o.sleeping = r.get_bool("sleeping", o.sleeping);
    o.warm_starting = r.get_bool("warm_starting", o.warm_starting);
    o.continuous = r.get_bool("continuous", o.continuous);
    o.fixed_rotation = r.get_bool("fixed_rotation", o.fixed_rotation);
}

}  // namespace

std::optional<Box2dOptions> box2d_preset(const std::string& name) {
    if (name == "tuned") return Box2dOptions{};
    if (name == "shipped") return shipped_options();
    return std::nullopt;
}

Box2dOptions parse_box2d_options(const Scene& scene) {
    OptionReader r("box2d", &scene);
    Box2dOptions o = *box2d_preset(r.get_choice("preset", {"tuned", "shipped"}, "tuned"));
    read_keys(r, o);
    r.refuse_unknown();
    return o;
}

}  // namespace collide
