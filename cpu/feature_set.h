// FeatureSet: which loop instantiation a scene runs, made from its SceneFeatures
// (core/scene/scene_features.h, where what a scene uses is worked out), and the dispatch that turns
// it into template arguments, so that a scene pays only for what it uses (ARCHITECTURE: "leave out
// what a scene does not need").
//
// Each hot loop of the `cpu` backend is a template on the features it touches. With a feature
// off, its code is not compiled into that instantiation at all: no branch per particle, no
// load of an array the scene does not need (radius[j] for equal radii, inv_mass[i] when no
// stone exists). bench/features_suite.cpp measures what this saves.
#pragma once

#include "core/scene/scene.h"
#include "core/scene/scene_features.h"

namespace collide::cpu {

struct FeatureSet {
    bool gravity = true;
    bool damping = true;
    bool friction = true;
    bool stones = true;          // some disk has inverse mass 0
    bool uniform_radius = false; // every disk has the same radius
    bool periodic = false;       // periodic boundaries (a geometry choice, always honoured)

    // The features the scene actually uses.
    static FeatureSet of(const SceneFeatures& features);
    // The unspecialised instantiation: every optional feature compiled in, driven by the
    // scene's runtime values (zero gravity, zero friction, ...). Gives bitwise the same
    // results as the specialised one; the benchmark compares their speed.
    static FeatureSet generic(const Scene& scene);
};

// Calls f.template operator()<B1, ..., Bk>() with the runtime booleans b1..bk as template
// arguments, e.g.
//     dispatch([&]<bool Friction, bool Periodic>() { ... }, features.friction, features.periodic);
// instantiates the body once per combination and picks the matching one at run time.
template <bool... Chosen, typename F>
void dispatch(F&& f) {
    f.template operator()<Chosen...>();
}

template <bool... Chosen, typename F, typename... Rest>
void dispatch(F&& f, bool next, Rest... rest) {
    if (next)
        dispatch<Chosen..., true>(f, rest...);
    else
        dispatch<Chosen..., false>(f, rest...);
}

}  // namespace collide::cpu
