#include "chipmunk_solver.h"

#include <chipmunk/chipmunk.h>

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "core/numerics/number_text.h"
#include "core/numerics/representability.h"
#include "chipmunk_space.h"
#include "core/scene/option_reader.h"
#include "physics/step_schedule.h"

namespace collide {
namespace {

// Collision types: contacts with the walls take the wall restitution and no friction.
constexpr cpCollisionType disk_type = 1, wall_type = 2;

bool touches_wall(cpArbiter* arbiter) {
    CP_ARBITER_GET_SHAPES(arbiter, a, b);
    return cpShapeGetCollisionType(a) == wall_type || cpShapeGetCollisionType(b) == wall_type;
}

// Chipmunk calls this once when two shapes come into touch: one pair collision, the
// `contacts` of docs/your-solver.md (a pair that stays in touch over many steps is one).
cpBool begin(cpArbiter* arbiter, cpSpace*, cpDataPointer data) {
    if (!touches_wall(arbiter)) ++static_cast<ChipmunkSolver::ContactLaw*>(data)->disk_contacts;
    return cpTrue;
}

// Chipmunk calls this for every touching pair before each step's solver. With combine =
// "scene" it replaces Chipmunk's product rule (e = e_a e_b, mu = mu_a mu_b) by the scene's law,
// as box2d_solver.cpp's WallRestitution does for Box2D's max rule.
cpBool pre_solve(cpArbiter* arbiter, cpSpace*, cpDataPointer data) {
    const auto& law = *static_cast<ChipmunkSolver::ContactLaw*>(data);
    if (law.set_per_contact) {
        const bool wall = touches_wall(arbiter);
        cpArbiterSetRestitution(arbiter, wall ? law.wall_restitution : law.restitution);
        cpArbiterSetFriction(arbiter, wall ? 0.0 : law.friction);
    }
    return cpTrue;
}

}  // namespace

void ChipmunkSolver::free_space() {
    if (!space_) return;
    cpSpaceFree(space_);
    space_ = nullptr;
    for (cpShape* shape : shapes_) cpShapeFree(shape);
    for (cpBody* body : bodies_) cpBodyFree(body);
    shapes_.clear();
    bodies_.clear();
}

std::optional<std::string> chipmunk_supports(const Scene& scene) {
    if (scene.periodic())
        return "Chipmunk2D has no periodic boundaries (a body cannot wrap around the space), "
               "and a faked wrap would not be Chipmunk's answer";
    return std::nullopt;
}

ChipmunkSolver::ChipmunkSolver(const BackendOptions& options) {
    OptionReader given("chipmunk", nullptr, options.extra);
    if (const auto n = given.find_int("iterations", 1, max_chipmunk_iterations, "a positive integer")) iterations_ = int(*n);
    given.refuse_unknown();
}
ChipmunkSolver::~ChipmunkSolver() { free_space(); }

void ChipmunkSolver::load(const Scene& scene, const ParticleState<double>& initial) {
    if (auto reason = chipmunk_supports(scene)) throw std::runtime_error("chipmunk: scene '" + scene.name + "': " + *reason);
    if (initial.size() == 0) throw std::runtime_error("chipmunk: scene '" + scene.name + "' has no disks");
    scene_ = scene;
    initial_ = initial;
    options_ = parse_chipmunk_options(scene);
    if (iterations_) options_.iterations = *iterations_;
    substeps_ = engine_substeps("chipmunk", scene, options_.substeps);
    require_representable(scene, initial, Precision::double_, Method::metrics_only, "chipmunk");
    step_count_ = 0;
    stats_ = SolverStats{};
    free_space();  // before its contact law
    law_ = std::make_unique<ContactLaw>(ContactLaw{.restitution = scene.physics.restitution,
                                                   .wall_restitution = scene.physics.wall_restitution,
                                                   .friction = scene.physics.friction,
                                                   .set_per_contact = options_.combine == "scene"});
    space_ = new_chipmunk_space();
    cpSpace* space = space_;
    cpSpaceSetIterations(space, options_.iterations);
    cpSpaceSetGravity(space, cpv(scene.physics.gravity_x, scene.physics.gravity_y));
    // Chipmunk's damping is the fraction of velocity kept per second, applied as v <- v d^h:
    // the exact solution of dv/dt = -c v over h is v e^{-c h}, so d = e^{-c}.
    cpSpaceSetDamping(space, std::exp(-scene.physics.damping));
    cpSpaceSetCollisionSlop(space, options_.collision_slop);
    cpSpaceSetCollisionBias(space, options_.collision_bias);
    cpCollisionHandler* handler = cpSpaceAddDefaultCollisionHandler(space);
    handler->beginFunc = begin;
    handler->preSolveFunc = pre_solve;
    handler->userData = law_.get();
    create_walls();
    create_disks();
}

// Four segments of radius 0 on the space's static body, on the scene's walls. Segments
// collide on both sides, so their order does not matter (unlike Box2D's one-sided chain).
void ChipmunkSolver::create_walls() {
    const World& w = scene_.world;
    const cpVect corners[4] = {cpv(w.xmin, w.ymin), cpv(w.xmin, w.ymax), cpv(w.xmax, w.ymax), cpv(w.xmax, w.ymin)};
    cpBody* walls = cpSpaceGetStaticBody(space_);
    for (int k = 0; k < 4; ++k) {
        cpShape* segment = shapes_.emplace_back(cpSegmentShapeNew(walls, corners[k], corners[(k + 1) % 4], 0));
        // Under the product rule the wall's own elasticity multiplies the disk's, as a user would set it.
        cpShapeSetElasticity(segment, scene_.physics.wall_restitution);
        cpShapeSetFriction(segment, 0);  // the walls of the exact model are smooth
        cpShapeSetCollisionType(segment, wall_type);
        cpSpaceAddShape(space_, segment);
    }
}

void ChipmunkSolver::create_disks() {
    const ParticleState<double>& s = initial_;
    bodies_.assign(s.size(), nullptr);
    for (std::size_t i = 0; i < s.size(); ++i) {
        const double m = s.mass[i], r = s.radius[i];
        // A stone is a static body: it never moves and has no mass (inverse mass 0).
        cpBody* body = s.is_stone(i) ? cpBodyNewStatic()
                                     : cpBodyNew(m, options_.fixed_rotation ? INFINITY : cpMomentForCircle(m, 0, r, cpvzero));
        bodies_[i] = body;
        cpSpaceAddBody(space_, body);
        cpBodySetPosition(body, cpv(s.x[i], s.y[i]));
        if (!s.is_stone(i)) cpBodySetVelocity(body, cpv(s.vx[i], s.vy[i]));
        cpShape* circle = shapes_.emplace_back(cpCircleShapeNew(body, r, cpvzero));
        cpShapeSetElasticity(circle, scene_.physics.restitution);
        cpShapeSetFriction(circle, scene_.physics.friction);
        cpShapeSetCollisionType(circle, disk_type);
        cpSpaceAddShape(space_, circle);  // after the body's position: the shape's bounds are computed here
    }
}

void ChipmunkSolver::advance_to(double t) {
    if (!space_) throw std::logic_error("chipmunk: advance_to() before load()");
    const std::int64_t target = target_step(scene_, t, step_count_, "chipmunk");
    while (step_count_ < target) step();
}

void ChipmunkSolver::step() {
    const double h = scene_.run.dt / substeps_;
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < substeps_; ++k) cpSpaceStep(space_, h);
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    stats_.phase_seconds["chipmunk_step"] += elapsed.count();
    ++step_count_;
    ++stats_.steps;
}

void ChipmunkSolver::read_state(ParticleState<double>& out) const {
    out = initial_;  // radii, masses, stones (which never move)
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (initial_.is_stone(i)) continue;
        const cpVect p = cpBodyGetPosition(bodies_[i]), v = cpBodyGetVelocity(bodies_[i]);
        out.x[i] = p.x;
        out.y[i] = p.y;
        out.vx[i] = v.x;
        out.vy[i] = v.y;
    }
}

SolverStats ChipmunkSolver::stats() const {
    SolverStats s = stats_;
    if (law_) s.contacts = law_->disk_contacts;
    s.counters["chipmunk_substeps"] = substeps_;
    if (stats_.steps > 0) s.counters["seconds_per_step"] = stats_.phase_seconds.at("chipmunk_step") / double(stats_.steps);
    return s;
}

// The preset, every effective setting and the library's own version string, so that a run
// file says which Chipmunk ran and how.
std::map<std::string, std::string> ChipmunkSolver::provenance() const {
    return {
        {"chipmunk_version", cpVersionString},
        {"chipmunk_preset", options_.preset},
        {"chipmunk_collision_slop", round_trip_text(options_.collision_slop)},
        {"chipmunk_collision_bias", round_trip_text(options_.collision_bias)},
        {"chipmunk_iterations", std::to_string(options_.iterations)},
        {"chipmunk_substeps", std::to_string(substeps_)},
        {"chipmunk_combine", options_.combine},
        {"chipmunk_fixed_rotation", options_.fixed_rotation ? "true" : "false"},
    };
}

}  // namespace collide
