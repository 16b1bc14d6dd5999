#include "validation/compare/phase_shift.h"

#include <cmath>

namespace collide::validation {

double phase_shift(std::uint64_t seed, double dt) {
    const double phi = 0.5 * (std::sqrt(5.0) - 1.0);
    const double k = double(seed);
    return (k * phi - std::floor(k * phi)) * dt;
}

void advance_free_flight(const Scene& scene, ParticleState<double>& s, double delta) {
    const double gx = scene.physics.gravity_x, gy = scene.physics.gravity_y;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s.is_stone(i)) continue;
        // x(t) = x + v t + g t^2 / 2, v(t) = v + g t: exact for uniform gravity.
        s.x[i] += s.vx[i] * delta + 0.5 * gx * delta * delta;
        s.y[i] += s.vy[i] * delta + 0.5 * gy * delta * delta;
        s.vx[i] += gx * delta;
        s.vy[i] += gy * delta;
    }
}

}  // namespace collide::validation
