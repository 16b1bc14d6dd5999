#include "core/numerics/representability.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <utility>

namespace collide {
namespace {

// A real number >= 0 as m * 2^e with m in [0.5, 1) (or m = 0): a double whose exponent cannot
// overflow. Products such as m v^2 of numbers near double's limits are formed with one
// rounding each, as the backend's own arithmetic would form them, only without the overflow
// to infinity or the underflow to 0, so they can be compared with the limits exactly.
struct Wide {
    double m = 0;
    std::int64_t e = 0;

    static Wide of(double v) {
        Wide w;
        if (!std::isfinite(v)) return {std::fabs(v), 0};  // inf and NaN stay what they are
        int k = 0;
        w.m = std::frexp(std::fabs(v), &k);
        w.e = k;
        return w;
    }
    bool zero() const { return m == 0; }
    bool finite() const { return std::isfinite(m); }
};

Wide normalised(double m, std::int64_t e) {
    if (m == 0 || !std::isfinite(m)) return {m, 0};
    int k = 0;
    const double f = std::frexp(m, &k);
    return {f, e + k};
}

Wide operator*(Wide a, Wide b) { return normalised(a.m * b.m, a.e + b.e); }
Wide operator*(Wide a, double c) { return a * Wide::of(c); }
Wide operator/(Wide a, Wide b) { return normalised(a.m / b.m, a.e - b.e); }

Wide operator+(Wide a, Wide b) {
    if (a.zero() || !b.finite()) return b;
    if (b.zero() || !a.finite()) return a;
    if (a.e < b.e) std::swap(a, b);
    const std::int64_t shift = std::max<std::int64_t>(b.e - a.e, -2000);  // far below a's last digit
    return normalised(a.m + std::ldexp(b.m, int(shift)), a.e);
}

// a < b for finite values; NaN and infinity compare above every finite value.
bool less(Wide a, Wide b) {
    if (!a.finite()) return false;
    if (!b.finite()) return true;
    if (a.zero() || b.zero()) return a.m < b.m;
    return a.e != b.e ? a.e < b.e : a.m < b.m;
}

// The value in the style of %.3g ("1e-46", "2.5e+400"), also beyond double's range.
std::string text(Wide w) {
    char buffer[48];
    if (!w.finite() || w.zero() || (w.e > -1000 && w.e < 1000)) {
        std::snprintf(buffer, sizeof buffer, "%.3g", w.finite() ? std::ldexp(w.m, int(w.e)) : w.m);
        return buffer;
    }
    const double log10_value = std::log10(w.m) + double(w.e) * std::log10(2.0);
    double exponent = std::floor(log10_value);
    double mantissa = std::pow(10.0, log10_value - exponent);
    if (mantissa >= 9.995) {
        mantissa /= 10;
        exponent += 1;
    }
    std::snprintf(buffer, sizeof buffer, "%.3ge%+.0f", mantissa, exponent);
    return buffer;
}

// The smallest and the largest value of one quantity over the disks, with the disk each came
// from. The smallest counts only values > 0: a quantity that is exactly 0 (a disk at rest)
// loses nothing in any precision.
struct Range {
    Wide lo{std::numeric_limits<double>::infinity(), 0}, hi;
    std::int64_t lo_disk = -1, hi_disk = -1;

    void add(Wide v, std::size_t disk) {
        if (!v.zero() && less(v, lo)) {
            lo = v;
            lo_disk = std::int64_t(disk);
        }
        if (hi_disk < 0 || less(hi, v)) {
            hi = v;
            hi_disk = std::int64_t(disk);
        }
    }
    bool empty() const { return hi_disk < 0; }
    bool has_nonzero() const { return lo_disk >= 0; }
    // The range of f(value) for an increasing f, from the same disks.
    template <typename F>
    Range mapped(F f) const {
        Range r = *this;
        r.lo = has_nonzero() ? f(lo) : lo;
        r.hi = f(hi);
        return r;
    }
};

// Every per-disk quantity the checks need, gathered in one pass over the disks.
struct DiskRanges {
    Range mass, inverse_mass, radius, speed, momentum, kinetic_energy;
    Wide total_kinetic_energy, total_potential_energy;
};

DiskRanges disk_ranges(const Scene& scene, const ParticleState<double>& s) {
    DiskRanges r;
    const Wide gx = Wide::of(scene.physics.gravity_x), gy = Wide::of(scene.physics.gravity_y);
    for (std::size_t i = 0; i < s.size(); ++i) {
        const Wide mass = Wide::of(s.mass[i]);
        r.mass.add(mass, i);
        r.radius.add(Wide::of(s.radius[i]), i);
        if (s.is_stone(i)) continue;  // kinematic: inverse mass 0, never moves (core/particle_state.h)
        const Wide speed = Wide::of(std::hypot(s.vx[i], s.vy[i]));
        const Wide energy = mass * (speed * speed) * 0.5;
        r.inverse_mass.add(Wide::of(1.0) / mass, i);
        r.speed.add(speed, i);
        r.momentum.add(mass * speed, i);
        r.kinetic_energy.add(energy, i);
        r.total_kinetic_energy = r.total_kinetic_energy + energy;
        r.total_potential_energy =
            r.total_potential_energy + mass * (gx * Wide::of(s.x[i]) + gy * Wide::of(s.y[i]));
    }
    return r;
}

// Checks quantities against one precision's normal range and keeps the first problem.
class Checker {
public:
    Checker(std::string who, Precision p) : who_(std::move(who)), type_(to_string(p)) {
        const bool single = p == Precision::single;
        max_ = Wide::of(single ? double(std::numeric_limits<float>::max()) : std::numeric_limits<double>::max());
        min_ = Wide::of(single ? double(std::numeric_limits<float>::min()) : std::numeric_limits<double>::min());
    }

    // The largest value must not overflow, the smallest value > 0 must not underflow.
    void range(const std::string& quantity, const Range& r) {
        if (r.empty()) return;
        at_most(quantity, r.hi, r.hi_disk);
        if (r.has_nonzero()) at_least(quantity, r.lo, r.lo_disk);
    }
    void at_most(const std::string& quantity, Wide value, std::int64_t disk = -1) {
        if (!problem_ && less(max_, value))
            fail(quantity, value, disk, "overflows " + type_ + "'s largest number " + text(max_));
    }
    // Underflow: below the smallest normal number a value keeps fewer significant digits
    // (subnormal, IEEE 754 section 3.4) or becomes 0.
    void at_least(const std::string& quantity, Wide value, std::int64_t disk = -1) {
        if (!problem_ && !value.zero() && less(value, min_))
            fail(quantity, value, disk, "underflows below " + type_ + "'s smallest normal number " + text(min_));
    }
    const std::optional<std::string>& problem() const { return problem_; }

private:
    void fail(const std::string& quantity, Wide value, std::int64_t disk, const std::string& what) {
        problem_ = who_ + " in " + type_ + ": " + quantity + " = " + text(value) +
                   (disk >= 0 ? " for disk " + std::to_string(disk) : "") + " " + what;
    }

    std::string who_, type_;
    Wide max_, min_;
    std::optional<std::string> problem_;
};

Wide squared(Wide w) { return w * w; }

// Masses, radii, speeds, the box and the contact law's pair quantities
// (physics/contact_law.cl.h), which the stepping rules and the event solver share.
void check_contact_law(Checker& c, const Scene& scene, const DiskRanges& r) {
    const World& w = scene.world;
    c.range("mass m", r.mass);
    c.range("inverse mass 1/m", r.inverse_mass);
    c.range("sum of inverse masses 1/m_i + 1/m_j (up to 2/m)", r.inverse_mass.mapped([](Wide v) { return v * 2.0; }));
    c.range("radius r", r.radius);
    c.range("squared contact distance (r_i + r_j)^2 (4 r^2 for two such disks)",
            r.radius.mapped([](Wide v) { return squared(v * 2.0); }));
    for (double corner : {w.xmin, w.ymin, w.xmax, w.ymax}) c.at_most("box coordinate", Wide::of(corner));
    for (double side : {w.width(), w.height()}) {
        c.at_most("box side", Wide::of(side));
        c.at_least("box side", Wide::of(side));
    }
    c.at_most("squared distance of two disks (up to the box diagonal^2, width^2 + height^2)",
              squared(Wide::of(w.width())) + squared(Wide::of(w.height())));
    c.range("speed |v|", r.speed);
    // (Only the friction's tangential speed is formed from it: underflow loses nothing there.)
    c.at_most("squared relative speed |v_i - v_j|^2 (up to (2 |v|)^2)", squared(r.speed.hi * 2.0), r.speed.hi_disk);
    // J = (1 + e) |u_n| / (1/m_i + 1/m_j) <= (1 + e) (|v_i| + |v_j|) min(m_i, m_j)
    //   <= 2 (1 + e) max(m_i |v_i|, m_j |v_j|).
    const double e = scene.physics.restitution;
    c.range("collision impulse (up to 2 (1 + e) m |v|)", r.momentum.mapped([e](Wide v) { return v * (2 * (1 + e)); }));
}

// The time step of the stepping rules: dt, the sub-step h, and what one step adds.
void check_time_step(Checker& c, const Scene& scene, const DiskRanges& r) {
    const RunSettings& run = scene.run;
    const Physics& p = scene.physics;
    const Wide h = Wide::of(run.order == StepOrder::integrate_first ? run.dt / run.substeps : run.dt);
    c.at_most("time step dt", Wide::of(run.dt));
    c.at_least("time step dt", Wide::of(run.dt));
    c.at_most("sub-step dt / substeps", h);
    c.at_least("sub-step dt / substeps", h);
    // A displacement |v| h that underflows to 0 leaves a moving disk where it is for ever.
    c.range("displacement per step |v| dt", r.speed.mapped([h](Wide v) { return v * h; }));
    const Wide g = Wide::of(std::hypot(p.gravity_x, p.gravity_y));
    c.at_most("gravity |g|", g);
    c.at_most("velocity change per step |g| dt", g * h);
    c.at_least("velocity change per step |g| dt", g * h);
    c.at_most("displacement per step by gravity |g| dt^2", g * h * h);
    c.at_most("damping per step gamma dt", Wide::of(p.damping) * h);
}

// The event solver's pair collision time (physics/collision_time.h): b = d.u and (u.u) c with
// |d| up to the box diagonal, and its impulse per length g = J / |d| (|d| >= r_i + r_j).
void check_collision_times(Checker& c, const Scene& scene, const DiskRanges& r) {
    if (r.speed.empty()) return;  // (only stones)
    const Wide diagonal = Wide::of(std::hypot(scene.world.width(), scene.world.height()));
    const Wide relative_speed = r.speed.hi * 2.0;
    // u.u below the smallest normal number would make the discriminant (d.u)^2 - (u.u) c
    // vanish with it: a pair that should collide would pass through.
    c.range("squared relative speed |v_i - v_j|^2 (about (2 |v|)^2)",
            r.speed.mapped([](Wide v) { return squared(v * 2.0); }));
    c.at_most("collision-time discriminant (d.u)^2 (up to (box diagonal x 2 |v|)^2)",
              squared(diagonal * relative_speed), r.speed.hi_disk);
    // The collision rule divides by |d|^2 (1/m_i + 1/m_j), |d| = r_i + r_j at contact: as inf
    // the impulse would be 0 and the pair would collide "now" for ever; as 0, infinite.
    if (!r.inverse_mass.empty()) {
        const char* denominator = "collision denominator |d|^2 (1/m_i + 1/m_j) (from (2 r)^2 / m to (2 r)^2 2/m)";
        c.at_most(denominator, squared(r.radius.hi * 2.0) * r.inverse_mass.hi * 2.0, r.inverse_mass.hi_disk);
        c.at_least(denominator, squared(r.radius.lo * 2.0) * r.inverse_mass.lo, r.inverse_mass.lo_disk);
    }
    const double e = scene.physics.restitution;
    const Wide impulse = r.momentum.hi * (2 * (1 + e));
    c.at_most("impulse per contact distance J / (r_i + r_j) (up to 2 (1 + e) m |v| / (2 r_min))",
              impulse / (r.radius.lo * 2.0), r.momentum.hi_disk);
    c.at_most("collision virial J |d| (up to 2 (1 + e) m |v| x box diagonal)", impulse * diagonal,
              r.momentum.hi_disk);
    // Wall and cell-border times under gravity: the discriminant v^2 + 2 a d, d up to the box
    // diagonal; the solver's fall speed sqrt(|g| 2 r) is formed the same way.
    const Wide g = Wide::of(std::hypot(scene.physics.gravity_x, scene.physics.gravity_y));
    c.at_most("crossing-time discriminant 2 |g| d (up to 2 |g| x box diagonal)", g * diagonal * 2.0);
}

// core/metrics.cpp sums momentum, v^2, m v^2 / 2 and m g.x in double for every backend.
void check_metrics(Checker& c, const DiskRanges& r) {
    // Upper limits only for single disks: a slow disk's share that underflows is negligible
    // against the totals; a total that underflows is not.
    c.at_most("squared speed |v|^2", squared(r.speed.hi), r.speed.hi_disk);
    c.at_most("momentum m |v|", r.momentum.hi, r.momentum.hi_disk);
    c.at_most("kinetic energy m |v|^2 / 2", r.kinetic_energy.hi, r.kinetic_energy.hi_disk);
    c.at_most("total kinetic energy sum m |v|^2 / 2", r.total_kinetic_energy);
    c.at_least("total kinetic energy sum m |v|^2 / 2", r.total_kinetic_energy);
    c.at_most("potential energy sum m |g.x|", r.total_potential_energy);
}

std::optional<std::string> nonfinite_problem(const ParticleState<double>& s) {
    for (std::size_t i = 0; i < s.size(); ++i)
        for (double v : {s.x[i], s.y[i], s.vx[i], s.vy[i], s.radius[i], s.mass[i]})
            if (!std::isfinite(v)) return "disk " + std::to_string(i) + " has a value that is not a finite number";
    return std::nullopt;
}

}  // namespace

const char* to_string(Precision p) { return p == Precision::single ? "float" : "double"; }

std::optional<std::string> representability_problem(const Scene& scene, const ParticleState<double>& state,
                                                    Precision precision, Method method, const std::string& backend) {
    if (auto problem = nonfinite_problem(state)) return problem;
    const DiskRanges ranges = disk_ranges(scene, state);
    Checker own(backend + " computes", precision);
    if (method != Method::metrics_only) check_contact_law(own, scene, ranges);
    if (method == Method::stepping_rules) check_time_step(own, scene, ranges);
    if (method == Method::event_driven) check_collision_times(own, scene, ranges);
    if (own.problem()) return own.problem();
    Checker metrics("the metrics (every backend) are computed", Precision::double_);
    check_metrics(metrics, ranges);
    return metrics.problem();
}

std::optional<std::string> value_problem(const std::string& who, Precision precision, const std::string& quantity,
                                         std::initializer_list<double> factors, long long disk) {
    Wide value = Wide::of(1.0);
    for (double f : factors) value = value * Wide::of(f);
    Checker c(who, precision);
    c.at_most(quantity, value, disk);
    c.at_least(quantity, value, disk);
    return c.problem();
}

void require_representable(const Scene& scene, const ParticleState<double>& state, Precision precision,
                           Method method, const std::string& backend) {
    if (auto problem = representability_problem(scene, state, precision, method, backend))
        throw std::runtime_error(backend + " cannot run scene '" + scene.name + "': " + *problem +
                                 " (docs/refusals.md)");
}

}  // namespace collide
