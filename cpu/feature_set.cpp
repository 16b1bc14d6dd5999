#include "feature_set.h"

#include <algorithm>

namespace collide::cpu {

FeatureSet FeatureSet::of(const Scene& scene, const ParticleState<float>& state) {
    FeatureSet f;
    f.gravity = scene.has_gravity();
    f.damping = scene.has_damping();
    f.friction = scene.has_friction();
    f.stones = std::any_of(state.inv_mass.begin(), state.inv_mass.end(), [](float w) { return w == 0.0f; });
    f.uniform_radius = !state.radius.empty() &&
                       std::all_of(state.radius.begin(), state.radius.end(),
                                   [&](float r) { return r == state.radius.front(); });
    f.periodic = scene.periodic();
    return f;
}

FeatureSet FeatureSet::generic(const Scene& scene) {
    FeatureSet f;  // every optional feature on, radii read per disk
    f.periodic = scene.periodic();
    return f;
}

}  // namespace collide::cpu
