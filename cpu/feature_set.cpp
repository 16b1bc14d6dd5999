#include "feature_set.h"

namespace collide::cpu {

FeatureSet FeatureSet::of(const SceneFeatures& scene) {
    FeatureSet f;
    f.gravity = scene.gravity;
    f.damping = scene.damping;
    f.friction = scene.friction;
    f.stones = scene.stones;
    f.uniform_radius = scene.uniform_radius;
    f.periodic = scene.periodic();
    return f;
}

FeatureSet FeatureSet::generic(const Scene& scene) {
    FeatureSet f;  // every optional feature on, radii read per disk
    f.periodic = scene.periodic();
    return f;
}

}  // namespace collide::cpu
