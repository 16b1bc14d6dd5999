// What a sampler (sampling/: `ecmc`, `metropolis`) can take. A sampler draws configurations of
// equal hard disks from the uniform (Boltzmann) measure; it has no time and no velocities, so
// a scene that states dynamics (gravity, stones that move, e < 1: a claim about collisions) is
// refused with the reason, as other backends refuse what they do not model.
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include "core/particle_state.h"
#include "core/scene/scene.h"
#include "core/scene/scene_features.h"

namespace collide {

struct SamplerLimits {
    bool walls = false;  // whether the sampler handles reflecting walls (hard walls: a disk may not cross)
};

// The reason `who` cannot sample the scene as written, or nullopt. Reads the scene file's
// statements only (periodic or walls, gravity, damping, friction, e, wall e: scene_features(scene)).
std::optional<std::string> outside_sampler_model(const SceneFeatures& features, const SamplerLimits& limits);

// The same for the generated start: stones (moving or not: a sampler moves every disk),
// unequal radii, positions outside the box, and an overlap (the pair named). Throws
// std::runtime_error whose message starts with `who`.
void check_sampler_start(const std::string& who, const Scene& scene, const ParticleState<double>& start,
                         const SamplerLimits& limits);

// p moved into [origin, origin + length) by whole box lengths; a p already inside is returned
// unchanged (to the bit: a start configuration is sampled as given).
inline double wrap_into_box(double p, double origin, double length) {
    if (p >= origin && p < origin + length) return p;
    double q = origin + std::fmod(p - origin, length);
    if (q < origin) q += length;
    return q >= origin + length ? origin : q;
}

// The number of sampler steps (chains, sweeps) done at output time t of a run of `total`:
// round(total t / duration), so the output times divide the run as they divide a dynamics run.
std::int64_t sampler_steps_at(double t, const Scene& scene, std::int64_t total);

}  // namespace collide
