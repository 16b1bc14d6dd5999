// The `box2d` backend: the scene as a Box2D 2.4 world, the baseline a user would pick instead
// of collide. One dynamic body with one circle fixture per disk, a static chain loop for the
// walls, static bodies for stones, sleeping off. docs/box2d-baseline.md explains the mapping
// and every way in which Box2D's answer differs from the exact hard-disk dynamics.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "box2d_options.h"
#include "box2d_units.h"
#include "core/solver.h"

class b2World;
class b2Body;
class b2Fixture;
class b2ContactListener;

namespace collide {

// Empty if Box2D can run the scene, otherwise why not (periodic boundaries).
std::optional<std::string> box2d_supports(const Scene& scene);

class Box2dSolver : public Solver {
public:
    // options.extra["iterations"], where a suite sweeps it, replaces the scene's
    // velocity_iterations (Box2D's contact solver iterations).
    explicit Box2dSolver(const BackendOptions& options = {});
    ~Box2dSolver() override;

    std::string name() const override { return "box2d"; }
    void load(const Scene& scene, const ParticleState<double>& initial) override;
    void advance_to(double t) override;
    void read_state(ParticleState<double>& out) const override;
    double time() const override { return double(step_count_) * scene_.run.dt; }
    SolverStats stats() const override;
    std::map<std::string, std::string> provenance() const override;

    const Box2dOptions& options() const { return options_; }
    const Box2dUnits& units() const { return units_; }
    // The world and disk i's body as built, so tests can read back what Box2D was told.
    const b2World* world() const { return world_.get(); }
    const b2Body* body(std::size_t i) const { return bodies_.at(i); }

private:
    void create_walls();
    void create_disks();
    // One scene step dt = `substeps` Box2D steps of length dt/substeps.
    void step();
    // Counts the touching contacts and the bodies that hit b2_maxTranslation in the last
    // Box2D step of length h.
    void record_box2d_step(double h);
    // The restitution threshold in Box2D's units: the option scaled, or Box2D's own default.
    float restitution_threshold() const;

    Scene scene_;
    ParticleState<double> initial_;  // radii, masses and stones, which Box2D does not change
    Box2dOptions options_;
    Box2dUnits units_;
    std::optional<int> iterations_;  // the suite's sweep value, if any
    int substeps_ = 1;
    std::unique_ptr<b2World> world_;
    std::unique_ptr<b2ContactListener> wall_restitution_;
    b2Fixture* wall_fixture_ = nullptr;
    std::vector<b2Body*> bodies_;    // bodies_[i] is disk i
    std::int64_t step_count_ = 0;
    SolverStats stats_;
    std::int64_t cap_steps_ = 0, cap_body_steps_ = 0;
};

}  // namespace collide
