// The `step` backend: the time-stepped collision rules of both engines collide grew from, in double
// precision, serial, written to be read next to docs/stepping-rules.md. The `cpu` and
// `opencl` backends implement the same rules in float; comparing them with this one
// measures their rounding and implementation error alone.
#pragma once

#include <vector>

#include "core/solver.h"
#include "core/uniform_grid.h"

namespace collide {

class StepSolver : public Solver {
public:
    std::string name() const override { return "step"; }
    void load(const Scene& scene, const ParticleState<double>& initial) override;
    void advance_to(double t) override;
    void read_state(ParticleState<double>& out) const override { out = state_; }
    double time() const override { return double(step_count_) * scene_.run.dt; }
    SolverStats stats() const override { return stats_; }

    // One full time step dt of the scene's rule.
    void step();

private:
    // Rule "collide-first": contacts on the current state, then Euler, then walls.
    void step_collide_first(double dt);
    // Rule "integrate-first": one sub-step of length h, forces and Euler before the contacts.
    void substep_integrate_first(double h);

    // The phases (core/numerics/phase_timer.h names them for every stepping backend).
    void build_grid();
    // Jacobi contact pass: every disk's correction is computed from the same snapshot and
    // stored in dx_/dy_/dvx_/dvy_; nothing moves until correct().
    void collide();
    void correct();
    void integrate_velocities(double h);  // v += (g - gamma v) h
    void integrate_positions(double h);   // x += v h
    void apply_walls();

    Scene scene_;
    ParticleState<double> state_;
    UniformGrid<double> grid_;
    std::vector<double> dx_, dy_, dvx_, dvy_;
    std::int64_t step_count_ = 0;
    SolverStats stats_;
};

}  // namespace collide
