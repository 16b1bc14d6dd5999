#include "extreme_scenes.h"

#include <array>
#include <cmath>
#include <random>
#include <regex>
#include <sstream>

namespace collide::test {
namespace {

// 10^u with u uniform in [-span, span].
double magnitude(std::mt19937_64& rng, double span) {
    return std::pow(10.0, std::uniform_real_distribution<double>(-span, span)(rng));
}

double uniform(std::mt19937_64& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

}  // namespace

ExtremeCase extreme_case(std::uint64_t seed, int index) {
    std::mt19937_64 rng(seed * 1000003 + std::uint64_t(index));
    ExtremeCase c;
    // A third of the cases near 1 (10^[-3, 3]), a third within 10^[-30, 30], a third within
    // 10^[-300, 300]; each magnitude of a case is drawn from its span.
    const double span = std::array{3.0, 30.0, 300.0}[std::size_t(index % 3)];
    auto draw = [&] { return magnitude(rng, span); };
    const double box = draw();
    // The radius from box / 800 to box / 8: 4 disks fit on a 2 x 2 lattice without touching,
    // and the stepping grids stay small (they take up to 2^26 cells of side 2 r, whatever the
    // number of disks, and would spend most of the test clearing them).
    double radius = box / 8 * std::pow(10.0, -uniform(rng, 0, 2));
    if (radius == 0) radius = box / 8;  // (underflowed in drawing: a radius must be > 0)
    const double mass = draw(), speed = draw(), dt = draw();
    const double gravity = uniform(rng, 0, 1) < 0.3 ? draw() : 0.0;
    c.scene.name = "extreme_" + std::to_string(index);
    c.scene.world = World{0, 0, box, box, Boundary::reflect};
    // Elastic: with e < 1 the event solver may meet an inelastic collapse (it stops with that
    // message), another limit than the numbers' range.
    c.scene.physics.restitution = 1.0;
    c.scene.physics.gravity_y = -gravity;
    c.scene.run.dt = dt;
    c.scene.run.duration = dt;
    c.scene.run.output_interval = dt;
    for (int k = 0; k < 4; ++k) {
        const double angle = uniform(rng, 0, 2 * M_PI);
        // Mass ratios up to 1e3: a light disk between a wall and a disk 1e28 times heavier
        // bounces ~1e14 times (the count grows as the root of the ratio), which the event
        // solver rightly stops as no progress; that is no question of representation.
        double m = uniform(rng, 0, 1) < 0.5 ? mass : mass * std::pow(10.0, uniform(rng, -3, 3));
        if (m == 0 || !std::isfinite(m)) m = mass;
        c.state.append_disk(box * (0.25 + 0.5 * (k % 2)), box * (0.25 + 0.5 * (k / 2)), speed * std::cos(angle),
                            speed * std::sin(angle), radius, m, false);
    }
    std::ostringstream s;
    s << c.scene.name << ": box " << box << ", radius " << radius << ", masses " << c.state.mass[0] << " "
      << c.state.mass[1] << " " << c.state.mass[2] << " " << c.state.mass[3] << ", speed " << speed << ", dt " << dt
      << ", gravity " << gravity << ", e " << c.scene.physics.restitution;
    c.summary = s.str();
    return c;
}

namespace {

// A refusal names the quantity, its value and the limit: "... radius r = 1e-300 for disk 0
// underflows below float's smallest normal number 1.18e-38", a Box2D length scale that is no
// number, or the event solver's bound on the number of events.
bool names_the_limit(const std::string& message) {
    static const std::regex representable(
        "cannot run scene '[^']*': .* = ([-+.0-9e]+|inf|nan)( for disk [0-9]+)? (overflows (float|double)'s largest number "
        "[.0-9e+]+|underflows below (float|double)'s smallest normal number [.0-9e-]+)");
    static const std::regex scale("cannot run scene '[^']*': length scale s = .* (is not a finite number|maps the mean)");
    return std::regex_search(message, representable) || std::regex_search(message, scale) ||
           message.find("events cannot finish") != std::string::npos;
}

// The disks as the backend holds them: finite, masses and radii as given (to float's
// rounding), movers still movers (inverse mass > 0) and moving disks still moving.
std::string intact(const ParticleState<double>& initial, const ParticleState<double>& now, bool check_speed) {
    if (now.size() != initial.size()) return "the backend holds " + std::to_string(now.size()) + " disks";
    for (std::size_t i = 0; i < now.size(); ++i) {
        const std::string disk = "disk " + std::to_string(i) + ": ";
        if (!now.is_finite(i)) return disk + "non-finite position or velocity";
        if (!(std::fabs(now.mass[i] / initial.mass[i] - 1) < 1e-6)) return disk + "mass changed";
        if (!(std::fabs(now.radius[i] / initial.radius[i] - 1) < 1e-6)) return disk + "radius changed";
        if (!(now.inv_mass[i] > 0 && std::isfinite(now.inv_mass[i]))) return disk + "became a stone (inverse mass 0)";
        const bool moving = initial.vx[i] != 0 || initial.vy[i] != 0;
        if (check_speed && moving && now.vx[i] == 0 && now.vy[i] == 0) return disk + "velocity zeroed";
    }
    return "";
}

}  // namespace

ExtremeOutcome run_extreme_case(const BackendInfo& backend, const BackendOptions& options, const ExtremeCase& c) {
    ExtremeOutcome out;
    if (backend.supports(c.scene)) {
        out.refused = true;
        return out;
    }
    auto solver = backend.create(options);
    try {
        solver->load(c.scene, c.state);
    } catch (const std::exception& e) {
        out.refused = true;
        if (!names_the_limit(e.what())) out.violation = std::string("refused without naming the limit: ") + e.what();
        return out;
    }
    ParticleState<double> state;
    solver->read_state(state);
    if (auto why = intact(c.state, state, true); !why.empty()) {
        out.violation = "after load: " + why;
        return out;
    }
    try {
        // The event solver may stop short of dt: a few box crossings show it computes (a time
        // step of 1e300 would be endless events). Under gravity it stops about when the
        // lowest disk could reach the floor: disks coming to rest there end in its "no
        // progress" error (docs/event-driven.md), another limit than the numbers' range.
        double t = c.scene.run.dt;
        if (backend.name == "event") {
            const double box = c.scene.world.width(), g = std::fabs(c.scene.physics.gravity_y);
            double fastest = 0;
            for (std::size_t i = 0; i < c.state.size(); ++i) fastest = std::max(fastest, std::hypot(c.state.vx[i], c.state.vy[i]));
            if (fastest > 0) t = std::min(t, 4 * box / fastest);
            if (g > 0) t = std::min(t, 0.5 * std::sqrt(box / g));
        }
        solver->advance_to(t);
        solver->read_state(state);
    } catch (const std::exception& e) {
        out.violation = std::string("accepted, then failed while running: ") + e.what();
        return out;
    }
    // (Collisions may stop a disk, so speeds are not compared after the step.)
    if (auto why = intact(c.state, state, false); !why.empty()) out.violation = "after one step: " + why;
    return out;
}

}  // namespace collide::test
