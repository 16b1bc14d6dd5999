#include "step_solver.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include <Eigen/Core>

#include "core/numerics/phase_timer.h"
#include "core/numerics/representability.h"
#include "physics/step_schedule.h"
#include "physics/stepping_laws.h"

namespace collide {

using Eigen::Vector2d;

void StepSolver::load(const Scene& scene, const ParticleState<double>& initial) {
    if (initial.size() == 0) throw std::invalid_argument("step: the scene has no disks");
    if (!(scene.run.dt > 0)) throw std::invalid_argument("step: dt must be positive");
    require_representable(scene, initial, Precision::double_, Method::stepping_rules, "step");
    scene_ = scene;
    state_ = initial;
    step_count_ = 0;
    stats_ = SolverStats{};
    const double r_max = *std::max_element(state_.radius.begin(), state_.radius.end());
    grid_.configure(scene_.world, 2 * r_max);
    for (auto* a : {&dx_, &dy_, &dvx_, &dvy_}) a->assign(state_.size(), 0.0);
}

void StepSolver::advance_to(double t) {
    const std::int64_t target = target_step(scene_, t, step_count_, "step");
    while (step_count_ < target) step();
}

void StepSolver::step() {
    step_by_rule<double>(scene_.run, [this](double dt) { step_collide_first(dt); },
                         [this](double h) { substep_integrate_first(h); });
    ++step_count_;
    ++stats_.steps;
}

void StepSolver::step_collide_first(double dt) {
    build_grid();
    collide();
    correct();
    // Explicit Euler: x_{n+1} = x_n + v_n dt uses the velocity after the contacts but before
    // the forces of this step, which are applied after.
    integrate_positions(dt);
    integrate_velocities(dt);
    apply_walls();
}

void StepSolver::substep_integrate_first(double h) {
    // Semi-implicit (symplectic) Euler: velocity first, then position with the new velocity.
    integrate_velocities(h);
    integrate_positions(h);
    build_grid();
    collide();
    correct();
    apply_walls();
}

void StepSolver::build_grid() {
    PhaseTimer timer(stats_, phase::grid);
    grid_.build(state_.x.data(), state_.y.data(), state_.size());
}

void StepSolver::collide() {
    PhaseTimer timer(stats_, phase::collide);
    const auto& s = state_;
    const bool periodic = scene_.periodic();
    const double lx = scene_.world.width(), ly = scene_.world.height();
    const double e = scene_.physics.restitution, mu = scene_.physics.friction;
    // Disk k's position and velocity as the vectors of docs/stepping-rules.md (copies: the
    // state is a structure of arrays). Vector2d arithmetic rounds each component as the scalar
    // lines did, so the state hashes are unchanged.
    auto position = [&s](std::size_t k) { return Vector2d(s.x[k], s.y[k]); };
    auto velocity = [&s](std::size_t k) { return Vector2d(s.vx[k], s.vy[k]); };
    // Disks that receive two or more impulses in this pass: the Jacobi sum does not conserve
    // kinetic energy for them even at e = 1 (docs/stepping-rules.md, "Energy at e = 1").
    // Counting only; it changes no arithmetic.
    std::int64_t multi_contact_disks = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        dx_[i] = dy_[i] = dvx_[i] = dvy_[i] = 0;
        if (s.is_stone(i)) continue;  // a stone's share is always zero
        int impulses = 0;
        const Vector2d x_i = position(i), v_i = velocity(i);
        grid_.for_each_candidate(x_i.x(), x_i.y(), [&](std::uint32_t j) {
            if (j == i) return;
            Vector2d separation = x_i - position(j);  // x_i - x_j, from j towards i
            if (periodic) {
                separation.x() = WallLaw<double>::minimum_image(separation.x(), lx);
                separation.y() = WallLaw<double>::minimum_image(separation.y(), ly);
            }
            const double contact = s.radius[i] + s.radius[j];
            if (separation.squaredNorm() >= contact * contact) return;  // |x_i - x_j| >= r_i + r_j: apart
            const Vector2d u = v_i - velocity(j);  // relative velocity v_i - v_j
            // The law itself is shared with the float and OpenCL rules (physics/contact_law.cl.h,
            // C that OpenCL compiles too), so it takes the components.
            const auto d = ContactLaw<double>::delta(separation.x(), separation.y(), u.x(), u.y(), contact,
                                                     s.inv_mass[i], s.inv_mass[j], e, mu);
            dx_[i] += d.dx;
            dy_[i] += d.dy;
            dvx_[i] += d.dvx;
            dvy_[i] += d.dvy;
            if (d.dvx != 0 || d.dvy != 0) ++impulses;  // approaching pairs only get an impulse
            // Each pair once: by its lower index, or by the moving disk when the other is a
            // stone (a stone never runs this loop).
            if (i < j || s.is_stone(j)) ++stats_.contacts;
        });
        if (impulses >= 2) ++multi_contact_disks;
    }
    stats_.counters["multi_contact_disks"] += double(multi_contact_disks);
}

void StepSolver::correct() {
    PhaseTimer timer(stats_, phase::correct);
    for (std::size_t i = 0; i < state_.size(); ++i) {
        state_.x[i] += dx_[i];
        state_.y[i] += dy_[i];
        state_.vx[i] += dvx_[i];
        state_.vy[i] += dvy_[i];
    }
}

// The integration and wall passes stay in scalars: they update the structure-of-arrays state
// one axis at a time (the wall law is per axis), and a Vector2d built and taken apart per disk
// would not make v += (g - gamma v) h read any closer to the equation.
void StepSolver::integrate_velocities(double h) {
    const double gx = scene_.physics.gravity_x, gy = scene_.physics.gravity_y;
    const double gamma = scene_.physics.damping;
    PhaseTimer timer(stats_, phase::integrate);
    for (std::size_t i = 0; i < state_.size(); ++i) {
        if (state_.is_stone(i)) continue;  // kinematic: never integrated
        state_.vx[i] += (gx - gamma * state_.vx[i]) * h;
        state_.vy[i] += (gy - gamma * state_.vy[i]) * h;
    }
}

void StepSolver::integrate_positions(double h) {
    PhaseTimer timer(stats_, phase::integrate);
    for (std::size_t i = 0; i < state_.size(); ++i) {
        if (state_.is_stone(i)) continue;
        state_.x[i] += state_.vx[i] * h;
        state_.y[i] += state_.vy[i] * h;
    }
}

void StepSolver::apply_walls() {
    PhaseTimer timer(stats_, phase::correct);
    const World& w = scene_.world;
    const double e_wall = scene_.physics.wall_restitution;
    const bool periodic = scene_.periodic();
    for (std::size_t i = 0; i < state_.size(); ++i) {
        if (state_.is_stone(i)) continue;
        if (periodic) {
            state_.x[i] = WallLaw<double>::wrap(state_.x[i], w.xmin, w.width());
            state_.y[i] = WallLaw<double>::wrap(state_.y[i], w.ymin, w.height());
        } else {
            const double r = state_.radius[i];
            WallLaw<double>::reflect_axis(&state_.x[i], &state_.vx[i], r, w.xmin, w.xmax, e_wall);
            WallLaw<double>::reflect_axis(&state_.y[i], &state_.vy[i], r, w.ymin, w.ymax, e_wall);
        }
    }
}

}  // namespace collide
