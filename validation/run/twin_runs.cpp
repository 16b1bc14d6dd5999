#include "validation/run/twin_runs.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "core/run_driver.h"
#include "validation/compare/predictability_horizon.h"
#include "validation/compare/reference_comparison.h"

namespace collide::validation {
namespace {

// Moves one coordinate by sign * delta, turning the sign where the first would leave [lo, hi].
double nudged(double value, double delta, int sign, double lo, double hi) {
    const double moved = value + sign * delta;
    return moved < lo || moved > hi ? value - sign * delta : moved;
}

}  // namespace

ParticleState<double> twin_initial_state(const Scene& scene, const ParticleState<double>& initial, std::uint64_t seed,
                                         int twin) {
    const World& w = scene.world;
    // eps times the box's largest extent or coordinate: at least one ulp of any coordinate in
    // the box (a box [100, 110] would round eps * 10 away at x = 105).
    const double extent = std::max({w.width(), w.height(), std::fabs(w.xmin), std::fabs(w.xmax), std::fabs(w.ymin),
                                    std::fabs(w.ymax)});
    const double delta = std::numeric_limits<double>::epsilon() * extent;
    ParticleState<double> out = initial;
    for (std::size_t i = 0; i < out.size(); ++i) {
        if (out.is_stone(i)) continue;  // a stone is part of the scene's fixed geometry
        const double r = scene.periodic() ? 0.0 : out.radius[i];  // a wall's contact distance
        out.x[i] = nudged(out.x[i], delta, twin_sign(seed, twin, i, 0), w.xmin + r, w.xmax - r);
        out.y[i] = nudged(out.y[i], delta, twin_sign(seed, twin, i, 1), w.ymin + r, w.ymax - r);
    }
    return out;
}

std::vector<double> twin_separation(const Scene& scene, const BackendInfo& backend, const BackendOptions& options,
                                    const ParticleState<double>& initial, const std::vector<Snapshot>& reference,
                                    std::uint64_t seed, int twins) {
    const double r_min = smallest_radius(Snapshot{initial.x, initial.y, initial.vx, initial.vy, initial.radius});
    std::vector<double> worst(reference.size(), 0.0);
    for (int twin = 1; twin <= twins; ++twin) {
        std::size_t k = 0;
        RunOptions run;
        run.on_state = [&](const ParticleState<double>& state, const Metrics&) {
            if (k >= reference.size()) return;
            const double s = snapshot_separation({state.x, state.y, {}, {}, {}}, reference[k], r_min);
            if (!(s <= worst[k])) worst[k] = s;  // NaN carried through
            ++k;
        };
        auto solver = backend.create(options);
        try {
            run_scene(scene, *solver, twin_initial_state(scene, initial, seed, twin), run);
        } catch (const std::exception&) {
            // The reference ran this scene, so a twin one rounding error away that cannot is
            // itself a sign that the scene is not predictable from here on.
        }
        for (; k < reference.size(); ++k) worst[k] = std::nan("");
    }
    return worst;
}

}  // namespace collide::validation
