// ViewSession: a scene advanced by one backend (and optionally by a second one to compare with,
// e.g. the exact `event` solver), one output step at a time, through the common Solver
// interface. It keeps what a frame shows: the states, their metrics, the overlapping pairs (one
// search serves both), and the time each part took (for the HUD and `collide bench view`).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/backend_registry.h"
#include "core/metrics.h"
#include "frame_geometry.h"
#include "overlap_pairs.h"

namespace collide::view {

class ViewSession {
public:
    // `compare` may be null. The caller has checked that both backends support the scene.
    ViewSession(const Scene& scene, const ParticleState<double>& initial, const BackendInfo& backend,
                const BackendInfo* compare, const BackendOptions& options);

    void restart();                 // back to t = 0 with fresh solvers
    void advance(int output_steps); // moves both solvers on by this many output intervals
    void analyse();                 // metrics and overlap marks of the current state

    // The frame as it stands (valid until the next advance/analyse); `extra_hud` is appended.
    FrameContent frame(const std::string& extra_hud) const;

    const Scene& scene() const { return scene_; }
    int threads() const { return options_.threads; }  // also the drawing's (0: all cores)
    std::size_t disk_count() const { return initial_.size(); }
    double time() const;
    double last_simulation_seconds() const { return simulation_seconds_; }
    double particle_steps_per_second() const { return particle_steps_per_second_; }

private:
    Scene scene_;
    ParticleState<double> initial_;
    const BackendInfo& backend_;
    const BackendInfo* compare_;
    BackendOptions options_;
    std::unique_ptr<Solver> solver_, compare_solver_;
    std::int64_t output_index_ = 0;  // time = index * interval: no drift from summing intervals
    ParticleState<double> state_, compare_state_;
    Metrics initial_metrics_, metrics_;
    OverlapFinder finder_;
    std::vector<OverlapMark> overlaps_;
    double speed_max_ = 1;
    double simulation_seconds_ = 0, particle_steps_per_second_ = 0;
};

// The HUD's physics: simulated time, energy drift (total energy under gravity) relative to the
// initial value, momentum change (relative to |p0|, absolute if p0 = 0), largest overlap.
std::string physics_hud(const Scene& scene, const Metrics& initial, const Metrics& now);

}  // namespace collide::view
