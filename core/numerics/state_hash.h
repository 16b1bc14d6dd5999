// A hash of the exact bit patterns of a state: golden tests of the seeded generators and
// bitwise-determinism tests (same state for any thread count) compare these.
#pragma once

#include <cstdint>
#include <cstring>

#include "core/particle_state.h"

namespace collide {

// 64-bit FNV-1a over every array of the state, in a fixed order.
template <typename Real>
std::uint64_t state_hash(const ParticleState<Real>& s) {
    std::uint64_t h = 14695981039346656037ull;
    auto mix = [&h](const std::vector<Real>& a) {
        for (Real v : a) {
            unsigned char bytes[sizeof(Real)];
            std::memcpy(bytes, &v, sizeof(Real));
            for (unsigned char b : bytes) { h ^= b; h *= 1099511628211ull; }
        }
    };
    for (const auto* a : {&s.x, &s.y, &s.vx, &s.vy, &s.radius, &s.mass, &s.inv_mass}) mix(*a);
    return h;
}

}  // namespace collide
