#include "sampling/metropolis_sampler.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "core/numerics/target_time.h"
#include "core/scene/option_reader.h"
#include "sampling/sampler_input.h"
#include "core/structure/orientational_order.h"
#include "core/thermo/pressure_record.h"

namespace collide {

namespace {
constexpr SamplerLimits metropolis_limits{.walls = true};
}

std::optional<std::string> MetropolisSampler::supports(const Scene& scene) {
    return outside_sampler_model(scene_features(scene), metropolis_limits);
}

void MetropolisSampler::load(const Scene& scene, const ParticleState<double>& initial) {
    check_sampler_start("metropolis", scene, initial, metropolis_limits);
    scene_ = scene;
    start_ = initial;
    periodic_ = scene.periodic();
    radius_ = initial.radius[0];
    sigma_ = 2 * radius_;
    sigma2_ = sigma_ * sigma_;
    OptionReader options("metropolis", &scene, options_.extra);
    target_acceptance_ = options.get_double("acceptance", default_metropolis_acceptance, 0,
                                            "a target acceptance in (0, 1)", true);
    if (target_acceptance_ >= 1) options.fail("acceptance", "a target acceptance in (0, 1)");
    delta_ = sigma_ * options.get_double("step", 0.1, 0, "a first trial step > 0, in diameters", true);
    options.refuse_unknown();
    // [run] sweeps, or 100 per unit of the scene's duration (docs/monte-carlo.md).
    sweeps_total_ = scene.run.sweeps > 0 ? scene.run.sweeps : std::max<std::int64_t>(2, std::llround(std::ceil(100 * scene.run.duration)));
    tuning_sweeps_ = std::max<std::int64_t>(1, sweeps_total_ / 10);
    histogram_ = ContactHistogram(contact_window_diameters * sigma_, contact_bins);

    const double origin[2] = {scene.world.xmin, scene.world.ymin}, length[2] = {scene.world.width(), scene.world.height()};
    try {
        cells_.configure(origin, length, sigma_ + histogram_.window());
    } catch (const std::runtime_error& e) {
        throw std::runtime_error("metropolis: scene '" + scene.name + "': " + e.what());
    }
    pos_[0] = initial.x;
    pos_[1] = initial.y;
    const std::size_t n = initial.size();
    for (int a = 0; a < 2; ++a) cell_[a].resize(n);
    slot_.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        for (int a = 0; a < 2; ++a) {
            pos_[a][i] = wrap(a, pos_[a][i]);
            cell_[a][i] = cells_.coordinate_of(a, pos_[a][i]);
        }
        slot_[i] = cells_.insert(cells_.index(cell_[0][i], cell_[1][i]), i);
    }
    rng_.reset(gsl_rng_alloc(gsl_rng_mt19937));
    gsl_rng_set(rng_.get(), (unsigned long)(scene.seed ^ 0x4d455452u));  // a stream of its own ("METR")
    sweeps_done_ = trials_ = accepted_ = tuning_accepted_ = tuning_trials_ = 0;
    now_ = 0;
    const World& w = scene.world;
    series_ = {{}, 1, {}, double(n) * std::numbers::pi * sigma2_ / (4 * w.width() * w.height()), {}};
}

double MetropolisSampler::wrap(int axis, double p) const {
    return periodic_ ? wrap_into_box(p, cells_.origin(axis), cells_.length(axis)) : p;
}

void MetropolisSampler::advance_to(double t) {
    check_target_time("metropolis", t, now_, scene_.run.dt, false);  // NaN, infinity, the past: refused
    const std::int64_t target = sampler_steps_at(t, scene_, sweeps_total_);
    while (sweeps_done_ < target) sweep();
    now_ = t;
}

void MetropolisSampler::sweep() {
    const std::size_t n = pos_[0].size();
    std::int64_t accepted = 0;
    for (std::size_t k = 0; k < n; ++k) accepted += try_move(std::uint32_t(gsl_rng_uniform_int(rng_.get(), n)));
    if (sweeps_done_++ < tuning_sweeps_) {
        tune_step(accepted, std::int64_t(n));
        return;
    }
    trials_ += std::int64_t(n);
    accepted_ += accepted;
    record_pressure();
}

// Scales delta by the ratio of the acceptance to the target (within a factor 2), once per block
// of at least tuning_block_trials trials (a sweep of 4 disks is too few to measure it), and keeps
// delta below half the box's shorter side.
void MetropolisSampler::tune_step(std::int64_t accepted, std::int64_t trials) {
    tuning_accepted_ += accepted;
    tuning_trials_ += trials;
    if (tuning_trials_ < tuning_block_trials) return;
    const double acceptance = double(tuning_accepted_) / double(tuning_trials_);
    tuning_accepted_ = tuning_trials_ = 0;
    delta_ *= std::clamp(acceptance / target_acceptance_, 0.5, 2.0);
    delta_ = std::min(delta_, 0.5 * std::min(cells_.length(0), cells_.length(1)));
}

bool MetropolisSampler::try_move(std::uint32_t i) {
    const double x = pos_[0][i] + delta_ * (2 * gsl_rng_uniform(rng_.get()) - 1);
    const double y = pos_[1][i] + delta_ * (2 * gsl_rng_uniform(rng_.get()) - 1);
    const World& w = scene_.world;
    if (!periodic_ && (x < w.xmin + radius_ || x > w.xmax - radius_ || y < w.ymin + radius_ || y > w.ymax - radius_))
        return false;  // across a wall
    const double nx = wrap(0, x), ny = wrap(1, y);
    if (overlaps_any(i, nx, ny)) return false;
    pos_[0][i] = nx;
    pos_[1][i] = ny;
    const int cx = cells_.coordinate_of(0, nx), cy = cells_.coordinate_of(1, ny);
    if (cx != cell_[0][i] || cy != cell_[1][i]) {
        const std::uint32_t moved = cells_.erase(cells_.index(cell_[0][i], cell_[1][i]), slot_[i]);
        slot_[moved] = slot_[i];
        cell_[0][i] = cx;
        cell_[1][i] = cy;
        slot_[i] = cells_.insert(cells_.index(cx, cy), i);
    }
    return true;
}

// The squared separation of disk i from (x, y) (periodic: the minimum image).
double MetropolisSampler::separation2(std::uint32_t i, double x, double y) const {
    double ux = pos_[0][i] - x, uy = pos_[1][i] - y;
    if (periodic_) {
        const double lx = cells_.length(0), ly = cells_.length(1);
        ux -= lx * std::round(ux / lx);
        uy -= ly * std::round(uy / ly);
    }
    return ux * ux + uy * uy;
}

// Whether disk i at (x, y) would overlap another disk: the 3 x 3 cells around (x, y) hold
// every disk closer than sigma (cells at least sigma wide).
bool MetropolisSampler::overlaps_any(std::uint32_t i, double x, double y) const {
    bool overlap = false;
    for_each_near(x, y, [&](std::uint32_t j, double r2) { overlap = overlap || (j != i && r2 < sigma2_); });
    return overlap;
}
// One beta P d^2 from this configuration's separations at contact (see the header).
void MetropolisSampler::record_pressure() {
    // psi6 at every recorded sweep (a sweep moves each disk by at most the step size, so the
    // phase moves little between samples: orientational_order.h's mixing check).
    ParticleState<double> configuration;
    read_state(configuration);
    series_.psi6_phase.push_back(std::arg(global_psi6(scene_.world, configuration)));
    const std::size_t n = pos_[0].size();
    histogram_.clear();
    const World& w = scene_.world;
    if (periodic_) {
        // Cells are at least sigma + window wide: every pair the histogram counts lies in
        // each other's 3 x 3 cells.
        for (std::uint32_t i = 0; i < n; ++i)
            for_each_neighbour(i, [&](std::uint32_t j, double r2) { if (j > i) histogram_.add(std::sqrt(r2) - sigma_); });
        const double z = 1 + sigma_ * histogram_.contact_density(1) / (2 * double(n));
        series_.beta_pressure.push_back(z * double(n) * sigma2_ / (w.width() * w.height()));
        return;
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        histogram_.add(pos_[0][i] - radius_ - w.xmin);
        histogram_.add(w.xmax - radius_ - pos_[0][i]);
        histogram_.add(pos_[1][i] - radius_ - w.ymin);
        histogram_.add(w.ymax - radius_ - pos_[1][i]);
    }
    const double perimeter = 2 * (w.width() + w.height());
    series_.beta_pressure.push_back(histogram_.contact_density(1) / perimeter * sigma2_);
}

void MetropolisSampler::read_state(ParticleState<double>& out) const {
    out = start_;
    out.x = pos_[0];
    out.y = pos_[1];
    for (std::size_t i = 0; i < out.size(); ++i) out.vx[i] = out.vy[i] = 0;  // no velocities
}

SolverStats MetropolisSampler::stats() const {
    SolverStats s;
    s.steps = sweeps_done_;
    s.contacts = accepted_;
    auto& c = s.counters;
    c["sweeps"] = double(sweeps_done_);
    c["tuning_sweeps"] = double(tuning_sweeps_);
    c["step_size"] = delta_;
    c["acceptance"] = trials_ > 0 ? double(accepted_) / double(trials_) : 0;
    c["contact_window"] = histogram_.window();
    // The counters every backend records (core/thermo/pressure_record.h), lengths in sweeps.
    if (series_.beta_pressure.size() >= 2)
        for (const auto& [name, value] : counters_.counters(series_)) c[name] = value;
    return s;
}

}  // namespace collide
