// The `chipmunk` backend: the scene as a Chipmunk2D 7 space (Debian's libchipmunk-dev), one of
// the game engines people use for bouncing disks, beside `box2d`. One dynamic body with one
// circle shape per disk, a static body with four segments for the walls, static bodies for
// stones. Chipmunk computes in double (cpFloat, CP_USE_DOUBLES on 64-bit Debian) and has no
// absolute length scale but its collision slop, so scene units go in 1:1 (docs/engines.md).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "chipmunk_options.h"
#include "core/solver.h"

struct cpSpace;
struct cpBody;
struct cpShape;

namespace collide {

// Empty if Chipmunk can run the scene, otherwise why not (periodic boundaries).
std::optional<std::string> chipmunk_supports(const Scene& scene);

class ChipmunkSolver : public Solver {
public:
    // options.extra["iterations"], where a suite sweeps it, replaces the scene's iterations.
    explicit ChipmunkSolver(const BackendOptions& options = {});
    ~ChipmunkSolver() override;

    std::string name() const override { return "chipmunk"; }
    void load(const Scene& scene, const ParticleState<double>& initial) override;
    void advance_to(double t) override;
    void read_state(ParticleState<double>& out) const override;
    double time() const override { return double(step_count_) * scene_.run.dt; }
    SolverStats stats() const override;
    std::map<std::string, std::string> provenance() const override;

    const ChipmunkOptions& options() const { return options_; }
    // The space and disk i's body as built, so tests can read back what Chipmunk was told.
    const cpSpace* space() const { return space_; }
    const cpBody* body(std::size_t i) const { return bodies_.at(i); }

    // What the collision callbacks need: the scene's contact law, and the pair collisions so far.
    struct ContactLaw {
        double restitution = 1, wall_restitution = 1, friction = 0;
        bool set_per_contact = true;   // combine = "scene"
        std::int64_t disk_contacts = 0;
    };

private:
    void create_walls();
    void create_disks();
    void step();

    Scene scene_;
    ParticleState<double> initial_;  // radii, masses and stones, which Chipmunk does not change
    ChipmunkOptions options_;
    std::optional<int> iterations_;  // the suite's sweep value, if any
    int substeps_ = 1;
    // cpSpaceFree frees the space alone: its bodies and shapes are ours to free after it.
    void free_space();

    std::unique_ptr<ContactLaw> law_;  // the pre-solve callback's data, alive while the space is
    cpSpace* space_ = nullptr;
    std::vector<cpBody*> bodies_;    // bodies_[i] is disk i (static for a stone)
    std::vector<cpShape*> shapes_;   // every shape added, walls included
    std::int64_t step_count_ = 0;
    SolverStats stats_;
};

}  // namespace collide
