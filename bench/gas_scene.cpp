#include "gas_scene.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace collide::bench {

GasCase gas_case(std::int64_t n, double phi, std::uint64_t seed) {
    const double radius = 0.5, pi = 3.14159265358979323846;
    const double edge = std::sqrt(double(n) * pi * radius * radius / phi);
    const auto per_row = std::int64_t(std::ceil(std::sqrt(double(n))));
    const double spacing = edge / double(per_row);
    // At phi <= 0.3 the spacing is >= sqrt(pi / 0.3) r = 3.24 r, so a
    // jitter of a quarter of the free gap per axis never makes two disks touch.
    const double jitter = std::max(0.0, 0.25 * (spacing - 2 * radius));

    GasCase c;
    Scene& s = c.scene;
    s.name = "bench_gas";
    s.description = "benchmark gas, area fraction " + std::to_string(phi);
    s.seed = seed;
    s.world = World{0, 0, edge, edge, Boundary::reflect};
    s.run.dt = 0.01;
    s.run.order = StepOrder::collide_first;

    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> shift(-jitter, jitter), velocity(-1, 1);
    std::vector<std::int64_t> order(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), rng);
    ParticleState<double>& p = c.initial;
    p.resize(std::size_t(n));
    for (std::int64_t k = 0; k < n; ++k) {
        const std::size_t i = std::size_t(order[std::size_t(k)]);
        p.x[i] = (double(k % per_row) + 0.5) * spacing + shift(rng);
        p.y[i] = (double(k / per_row) + 0.5) * spacing + shift(rng);
        p.vx[i] = velocity(rng);
        p.vy[i] = velocity(rng);
        p.radius[i] = radius;
        p.mass[i] = 1;
        p.inv_mass[i] = 1;
    }
    return c;
}

}  // namespace collide::bench
