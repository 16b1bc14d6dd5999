// The twins of a reference run: the predictability horizon's measurement
// (compare/predictability_horizon.h, docs/validation.md "The predictability horizon").
//
// Twin k (1..K) starts from the reference's initial state with every coordinate of every disk
// moved by s * eps * L, eps = 2^-52 (double's machine epsilon), L the box's largest extent or
// coordinate (so at least one ulp of every coordinate in it), s = +-1 from twin_sign(seed, k,
// disk, coordinate): one rounding error of a position in the box, in a direction fixed by the
// scene's seed and the twin. A sign that would move a disk out
// of the region its centre may occupy (a wall's contact distance, the periodic cell) is turned.
#pragma once

#include <cstdint>
#include <vector>

#include "core/backend_registry.h"
#include "core/particle_state.h"
#include "core/scene/scene.h"
#include "validation/record/case_result.h"

namespace collide::validation {

// Twin `twin` of `initial` (see above).
ParticleState<double> twin_initial_state(const Scene& scene, const ParticleState<double>& initial, std::uint64_t seed,
                                         int twin);

// Runs `twins` twins of a reference run on `backend` and returns, at each of the reference's
// output times, the largest separation of any twin's disk from the reference's [r_min of the
// reference's initial state]. NaN from the first output a twin could not reach (it threw).
std::vector<double> twin_separation(const Scene& scene, const BackendInfo& backend, const BackendOptions& options,
                                    const ParticleState<double>& initial, const std::vector<Snapshot>& reference,
                                    std::uint64_t seed, int twins);

}  // namespace collide::validation
