#include "view_session.h"

#include <chrono>
#include <cmath>
#include <cstdio>

namespace collide::view {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

ViewSession::ViewSession(const Scene& scene, const ParticleState<double>& initial, const BackendInfo& backend,
                         const BackendInfo* compare, const BackendOptions& options)
    : scene_(scene), initial_(initial), backend_(backend), compare_(compare), options_(options) {
    speed_max_ = default_speed_max(scene_, initial_);
    initial_metrics_ = compute_metrics(scene_, initial_, 0);
    restart();
}

void ViewSession::restart() {
    solver_ = backend_.create(options_);
    solver_->load(scene_, initial_);
    if (compare_) {
        compare_solver_ = compare_->create(BackendOptions{});
        compare_solver_->load(scene_, initial_);
    }
    output_index_ = 0;
    state_ = initial_;
    compare_state_ = initial_;
    simulation_seconds_ = particle_steps_per_second_ = 0;
    analyse();
}

double ViewSession::time() const { return double(output_index_) * scene_.run.output_interval; }

void ViewSession::advance(int output_steps) {
    output_index_ += output_steps;
    const double t = time();
    const std::int64_t steps_before = solver_->stats().steps;
    const auto start = std::chrono::steady_clock::now();
    solver_->advance_to(t);
    solver_->read_state(state_);
    const double own = seconds_since(start);
    if (compare_solver_) {
        compare_solver_->advance_to(t);
        compare_solver_->read_state(compare_state_);
    }
    simulation_seconds_ = seconds_since(start);
    // Particle-steps: disks times the backend's own steps (events, for the event solver).
    const double steps = double(solver_->stats().steps - steps_before);
    particle_steps_per_second_ = own > 0 ? steps * double(state_.size()) / own : 0;
}

void ViewSession::analyse() {
    // One pair search per frame, shared by the red marks and the HUD's overlap figures; the
    // rest of the metrics are O(N) sums.
    finder_.find(scene_.world, state_, overlaps_, options_.threads);
    metrics_ = frame_metrics(scene_, state_, time(), overlaps_);
}

FrameContent ViewSession::frame(const std::string& extra_hud) const {
    FrameContent c;
    c.state = &state_;
    c.compare = compare_solver_ ? &compare_state_ : nullptr;
    c.overlaps = &overlaps_;
    c.speed_max = speed_max_;
    c.hud = physics_hud(scene_, initial_metrics_, metrics_) + extra_hud;
    return c;
}

std::string physics_hud(const Scene& scene, const Metrics& initial, const Metrics& now) {
    const double e0 = scene.has_gravity() ? initial.total_energy() : initial.kinetic_energy;
    const double e1 = scene.has_gravity() ? now.total_energy() : now.kinetic_energy;
    const double p0 = std::hypot(initial.momentum_x, initial.momentum_y);
    const double dp = std::hypot(now.momentum_x - initial.momentum_x, now.momentum_y - initial.momentum_y);
    char text[256];
    std::snprintf(text, sizeof text, "T %.3f  DE/E %+.2e  DP%s %.2e  MAX OVERLAP %.2e", now.time,
                  e0 != 0 ? (e1 - e0) / std::fabs(e0) : e1 - e0, p0 > 0 ? "/P" : "", p0 > 0 ? dp / p0 : dp,
                  now.max_overlap);
    return text;
}

}  // namespace collide::view
