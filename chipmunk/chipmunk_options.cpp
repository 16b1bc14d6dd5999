#include "chipmunk_options.h"

#include <chipmunk/chipmunk.h>

#include <memory>
#include <string_view>

#include "chipmunk_space.h"
#include "core/scene/option_reader.h"

namespace collide {
namespace {

// Chipmunk 7 as it comes: every space setting read from a cpSpace Chipmunk itself initialises,
// so that another Chipmunk build cannot silently disagree with a copied number.
ChipmunkOptions shipped_options() {
    const std::unique_ptr<cpSpace, decltype(&cpSpaceFree)> space(new_chipmunk_space(), &cpSpaceFree);
    ChipmunkOptions o;
    o.preset = "shipped";
    o.collision_slop = cpSpaceGetCollisionSlop(space.get());
    o.collision_bias = cpSpaceGetCollisionBias(space.get());
    o.iterations = cpSpaceGetIterations(space.get());
    o.combine = "product";
    o.fixed_rotation = false;
    return o;
}

ChipmunkOptions tuned_options() {
    ChipmunkOptions o = shipped_options();  // the bias and iterations stay Chipmunk's
    o.preset = "tuned";
    o.collision_slop = 0;
    o.combine = "scene";
    o.fixed_rotation = true;
    return o;
}

void read_keys(OptionReader& r, ChipmunkOptions& o) {
    constexpr std::string_view whole = "a whole number >= 1";
    o.collision_slop = r.get_double("collision_slop", o.collision_slop, 0, "a length >= 0 (scene units)");
    o.collision_bias = r.get_double("collision_bias", o.collision_bias, 0, "a fraction in [0, 1]");
    if (o.collision_bias > 1) r.fail("collision_bias", "a fraction in [0, 1]");
    o.iterations = int(r.get_int("iterations", o.iterations, 1, max_chipmunk_iterations, whole));
    if (const auto n = r.find_int("substeps", 1, max_chipmunk_iterations, whole)) o.substeps = int(*n);
    o.combine = r.get_choice("combine", {"scene", "product"}, o.combine);
    o.fixed_rotation = r.get_bool("fixed_rotation", o.fixed_rotation);
}

}  // namespace

std::optional<ChipmunkOptions> chipmunk_preset(const std::string& name) {
    if (name == "tuned") return tuned_options();
    if (name == "shipped") return shipped_options();
    return std::nullopt;
}

ChipmunkOptions parse_chipmunk_options(const Scene& scene) {
    OptionReader r("chipmunk", &scene);
    ChipmunkOptions o = *chipmunk_preset(r.get_choice("preset", {"tuned", "shipped"}, "tuned"));
    read_keys(r, o);
    r.refuse_unknown();
    return o;
}

}  // namespace collide
