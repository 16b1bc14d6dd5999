#include "validation/judge/observables.h"

#include <cmath>
#include <numbers>

#include "core/scene/scene_features.h"
#include "core/uniform_grid.h"
#include "physics/stepping_laws.h"

namespace collide::validation {

double compressibility_factor(const Scene& scene, const ParticleState<double>& s, double shell) {
    const std::size_t n = s.size();
    if (n < 2 || !uniform_radius(s)) return std::nan("");
    const double sigma = 2 * s.radius.front();
    const double reach = sigma * (1 + shell);
    UniformGrid<double> grid;
    grid.configure(scene.world, reach);
    grid.build(s.x.data(), s.y.data(), n);
    const double lx = scene.world.width(), ly = scene.world.height();
    std::size_t pairs_in_contact = 0;
    for (std::size_t i = 0; i < n; ++i)
        grid.for_each_candidate(s.x[i], s.y[i], [&](std::uint32_t j) {
            if (j <= i) return;
            double dx = s.x[i] - s.x[j], dy = s.y[i] - s.y[j];
            if (scene.periodic()) {
                dx = WallLaw<double>::minimum_image(dx, lx);
                dy = WallLaw<double>::minimum_image(dy, ly);
            }
            if (dx * dx + dy * dy < reach * reach) ++pairs_in_contact;
        });
    const double area = lx * ly;
    const double rho = double(n) / area;
    // Ideal-gas expectation of pairs in the shell sigma <= d < reach: (n/2) rho pi (reach^2 - sigma^2).
    const double ideal_pairs = 0.5 * double(n) * rho * std::numbers::pi * (reach * reach - sigma * sigma);
    const double g_contact = double(pairs_in_contact) / ideal_pairs;
    return 1 + 0.5 * std::numbers::pi * rho * sigma * sigma * g_contact;
}

std::vector<double> speeds(const ParticleState<double>& s) {
    std::vector<double> out;
    for (std::size_t i = 0; i < s.size(); ++i)
        if (!s.is_stone(i)) out.push_back(std::hypot(s.vx[i], s.vy[i]));
    return out;
}

}  // namespace collide::validation
