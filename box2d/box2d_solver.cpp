#include "box2d_solver.h"

#include <box2d/box2d.h>

#include "box2d/box2d_profiler.h"
#include "core/numerics/number_text.h"
#include "core/scene/option_reader.h"
#include "core/numerics/representability.h"
#include "physics/step_schedule.h"

#include <cfloat>
#include <chrono>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace collide {
namespace {

// Box2D mixes the restitution of two fixtures as max(e_a, e_b), so a disk (e) against the
// walls (e_wall < e) would bounce with e. This listener gives every wall contact the wall
// restitution when the contact begins; Box2D keeps it for the contact's lifetime.
class WallRestitution : public b2ContactListener {
public:
    WallRestitution(const b2Fixture* wall, float e_wall) : wall_(wall), e_wall_(e_wall) {}
    void BeginContact(b2Contact* contact) override {
        if (contact->GetFixtureA() == wall_ || contact->GetFixtureB() == wall_) contact->SetRestitution(e_wall_);
    }

private:
    const b2Fixture* wall_;
    float e_wall_;
};

double mean_radius(const ParticleState<double>& s) {
    double sum = 0;
    for (double r : s.radius) sum += r;
    return sum / double(s.size());
}

// Box2D computes in float. A value beyond float's range becomes inf, on which Box2D stops
// with an assertion (b2_body.cpp: b2IsValid); a value below float's smallest normal number
// loses digits or becomes 0 (IEEE 754 underflow): a velocity of 0 stops the disk, a density
// of 0 makes Box2D quietly give the body a mass of 1. So every value handed over, in Box2D's
// units, must lie in float's normal range or be exactly 0. Positions are checked for overflow
// only: an offset from the box centre that rounds to 0 is an ordinary rounding of the position.
class FloatInputs {
public:
    explicit FloatInputs(const Box2dUnits& units) : scale_(units.scale) {}
    // The value handed over is the product of `factors` (e.g. {scale, g}); formed in double it
    // could itself overflow, so a problem is described by value_problem, which does not.
    void both(const char* what, std::initializer_list<double> factors, long long disk = -1) {
        if (problem_ || fits(factors)) return;
        const std::string where = std::string(what) + " in Box2D's units (length scale " + round_trip_text(scale_) + ")";
        problem_ = value_problem("box2d computes", Precision::single, where, factors, disk);
    }
    void overflow(const char* what, std::initializer_list<double> factors, long long disk = -1) {
        double product = 1;
        for (double f : factors) product *= f;
        if (!(std::fabs(product) <= 1)) both(what, factors, disk);
    }
    void require(const Scene& scene) const {
        if (problem_) throw std::runtime_error("box2d cannot run scene '" + scene.name + "': " + *problem_ + " (docs/refusals.md)");
    }

private:
    // Exactly 0, or in float's normal range (a product that left double's range is outside).
    static bool fits(std::initializer_list<double> factors) {
        double product = 1;
        for (double f : factors) {
            if (f == 0) return true;
            product *= f;
        }
        return std::fabs(product) >= FLT_MIN && std::fabs(product) <= FLT_MAX;
    }

    double scale_;
    std::optional<std::string> problem_;
};

void check_world_inputs(FloatInputs& in, const Scene& scene, const Box2dUnits& u, int substeps) {
    const World& w = scene.world;
    const double s = u.scale;
    in.both("gravity x", {s, scene.physics.gravity_x});
    in.both("gravity y", {s, scene.physics.gravity_y});
    in.both("damping", {scene.physics.damping});
    in.both("the step dt / substeps", {scene.run.dt / substeps});
    for (double x : {w.xmin, w.xmax}) in.overflow("a wall x", {s, x - u.centre_x});
    for (double y : {w.ymin, w.ymax}) in.overflow("a wall y", {s, y - u.centre_y});
    // Box2D's edge and distance computations square lengths up to the box's size.
    const double side = std::max(w.width(), w.height());
    in.both("the box side", {s, side});
    in.both("the squared box side", {s, side, s, side});
}

void check_disk_inputs(FloatInputs& in, const Scene& scene, const ParticleState<double>& st, const Box2dUnits& u,
                       double h) {
    const double s = u.scale, g = std::hypot(scene.physics.gravity_x, scene.physics.gravity_y);
    for (std::size_t i = 0; i < st.size(); ++i) {
        const auto disk = static_cast<long long>(i);
        const double r = st.radius[i], m = st.mass[i], v = std::hypot(st.vx[i], st.vy[i]);
        in.overflow("x", {s, st.x[i] - u.centre_x}, disk);
        in.overflow("y", {s, st.y[i] - u.centre_y}, disk);
        in.both("radius", {s, r}, disk);
        in.both("squared contact distance (2 r)^2", {4, s, r, s, r}, disk);  // b2CollideCircles
        if (st.is_stone(i)) continue;  // a static body: no velocity, no mass
        in.overflow("vx", {s, st.vx[i]}, disk);
        in.overflow("vy", {s, st.vy[i]}, disk);
        in.both("speed |v|", {s, v}, disk);
        in.both("translation per step |v| h", {s, v, h}, disk);  // b2Island: position += h v,
        in.overflow("squared translation per step (|v| h)^2", {s, v, h, s, v, h}, disk);  // capped by its square
        in.both("mass", {m}, disk);  // b2Body::ResetMassData: m = density * area, then 1/m
        in.both("inverse mass 1/m", {1 / m}, disk);
        in.both("density (mass / area)", {m, 1 / std::numbers::pi, 1 / s, 1 / s, 1 / r, 1 / r}, disk);
        in.both("impulse m |v|", {m, s, v}, disk);  // b2ContactSolver: impulses are mass x velocity
        // b2Island::Solve: v += h (1/m) (m g + F), evaluated as (h (1/m)) (m g + F).
        in.both("step per mass h / m", {h, 1 / m}, disk);
        in.both("weight m |g|", {m, s, g}, disk);
        in.both("velocity change per step |g| h", {s, g, h}, disk);
        in.overflow("displacement per step by gravity |g| h^2", {s, g, h, h}, disk);
    }
}

void require_float_inputs(const Scene& scene, const ParticleState<double>& s, const Box2dUnits& u, int substeps,
                          const Box2dOptions& options) {
    FloatInputs in(u);
    check_world_inputs(in, scene, u, substeps);
    check_disk_inputs(in, scene, s, u, scene.run.dt / substeps);
    if (options.restitution_threshold) in.both("restitution threshold", {u.scale, *options.restitution_threshold});
    in.require(scene);
}

}  // namespace

std::optional<std::string> box2d_supports(const Scene& scene) {
    if (scene.periodic())
        return "Box2D 2.4 has no periodic boundaries (a body cannot wrap around the world), "
               "and a faked wrap would not be Box2D's answer";
    return std::nullopt;
}

// The caller's options: only `iterations` (a suite's sweep of the velocity iterations, which
// replaces the scene's); the scene's [backend.box2d] table is read at load (box2d_options.h).
Box2dSolver::Box2dSolver(const BackendOptions& options) {
    OptionReader given("box2d", nullptr, options.extra);
    if (const auto n = given.find_int("iterations", 1, max_box2d_iterations, "a positive integer")) iterations_ = int(*n);
    given.refuse_unknown();
}
Box2dSolver::~Box2dSolver() = default;

void Box2dSolver::load(const Scene& scene, const ParticleState<double>& initial) {
    if (auto reason = box2d_supports(scene)) throw std::runtime_error("box2d: scene '" + scene.name + "': " + *reason);
    if (initial.size() == 0) throw std::runtime_error("box2d: scene '" + scene.name + "' has no disks");
    scene_ = scene;
    initial_ = initial;
    options_ = parse_box2d_options(scene);
    if (iterations_) options_.velocity_iterations = *iterations_;
    const double mean = mean_radius(initial);
    const double scale = options_.length_scale.value_or(default_box2d_scale(mean));
    if (auto why = box2d_scale_problem(scale, mean, options_.length_scale.has_value()))
        throw std::runtime_error("box2d cannot run scene '" + scene.name + "': " + *why + " (docs/refusals.md)");
    units_ = Box2dUnits(scale, scene.world);
    substeps_ = engine_substeps("box2d", scene, options_.substeps);
    step_count_ = 0;
    stats_ = SolverStats{};
    cap_steps_ = cap_body_steps_ = 0;

    require_representable(scene, initial, Precision::double_, Method::metrics_only, "box2d");
    require_float_inputs(scene, initial, units_, substeps_, options_);
    world_ = std::make_unique<b2World>(b2Vec2(float(units_.to_box2d_length(scene.physics.gravity_x)),
                                              float(units_.to_box2d_length(scene.physics.gravity_y))));
    // Sleeping freezes bodies whose speed stays below a threshold: the tuned preset turns it
    // off, since a frozen body would silently stop being validated; `shipped` keeps Box2D's on.
    world_->SetAllowSleeping(options_.sleeping);
    world_->SetWarmStarting(options_.warm_starting);
    world_->SetContinuousPhysics(options_.continuous);  // time of impact against walls and stones
    wall_fixture_ = nullptr;
    wall_restitution_.reset();
    create_walls();
    create_disks();
}

void Box2dSolver::create_walls() {
    const World& w = scene_.world;
    // Box2D gives chain edges a skin of b2_polygonRadius: a disk touches an edge when its centre
    // is r + b2_polygonRadius from it. Moving the edges out by that skin puts the touching
    // surface on the scene's walls.
    const float skin = b2_polygonRadius;
    const float x0 = float(units_.to_box2d_x(w.xmin)) - skin, x1 = float(units_.to_box2d_x(w.xmax)) + skin;
    const float y0 = float(units_.to_box2d_y(w.ymin)) - skin, y1 = float(units_.to_box2d_y(w.ymax)) + skin;
    // Chain edges are one-sided: they push back only bodies on their right. Going round the
    // box clockwise puts the inside of the box on the right of every edge.
    const b2Vec2 corners[4] = {{x0, y0}, {x0, y1}, {x1, y1}, {x1, y0}};
    b2ChainShape chain;
    chain.CreateLoop(corners, 4);

    b2BodyDef def;  // static by default
    b2Body* walls = world_->CreateBody(&def);
    b2FixtureDef fixture;
    fixture.shape = &chain;
    fixture.restitution = float(scene_.physics.wall_restitution);
    fixture.friction = 0;  // the walls of the exact model are smooth: b2MixFriction(mu, 0) = 0
    fixture.restitutionThreshold = restitution_threshold();
    wall_fixture_ = walls->CreateFixture(&fixture);

    if (scene_.physics.wall_restitution != scene_.physics.restitution) {
        wall_restitution_ = std::make_unique<WallRestitution>(wall_fixture_, float(scene_.physics.wall_restitution));
        world_->SetContactListener(wall_restitution_.get());
    }
}

void Box2dSolver::create_disks() {
    const ParticleState<double>& s = initial_;
    bodies_.assign(s.size(), nullptr);
    b2CircleShape circle;
    b2FixtureDef fixture;
    fixture.shape = &circle;
    fixture.restitution = float(scene_.physics.restitution);
    fixture.friction = float(scene_.physics.friction);
    fixture.restitutionThreshold = restitution_threshold();
    for (std::size_t i = 0; i < s.size(); ++i) {
        const bool stone = s.is_stone(i);
        b2BodyDef def;
        def.type = stone ? b2_staticBody : b2_dynamicBody;
        def.position.Set(float(units_.to_box2d_x(s.x[i])), float(units_.to_box2d_y(s.y[i])));
        if (!stone) def.linearVelocity.Set(float(units_.to_box2d_length(s.vx[i])), float(units_.to_box2d_length(s.vy[i])));
        def.allowSleep = options_.sleeping;
        // The exact model's disks carry no spin; without fixed rotation friction feeds energy
        // into rotation that the model does not have (and that the metrics do not count).
        def.fixedRotation = options_.fixed_rotation;
        // Box2D's damping is v <- v / (1 + h c) per step, the implicit form of dv/dt = -c v.
        def.linearDamping = float(scene_.physics.damping);
        def.bullet = options_.bullet;
        b2Body* body = world_->CreateBody(&def);
        const double r = units_.to_box2d_length(s.radius[i]);
        circle.m_radius = float(r);
        // Box2D's mass is density times area: m = rho pi r^2, so rho = m / (pi r^2).
        fixture.density = float(s.mass[i] / (std::numbers::pi * r * r));
        body->CreateFixture(&fixture);
        bodies_[i] = body;
    }
}

float Box2dSolver::restitution_threshold() const {
    if (options_.restitution_threshold) return float(units_.to_box2d_length(*options_.restitution_threshold));
    return b2FixtureDef().restitutionThreshold;  // Box2D's own, in its metres per second
}

void Box2dSolver::advance_to(double t) {
    if (!world_) throw std::logic_error("box2d: advance_to() before load()");
    const std::int64_t target = target_step(scene_, t, step_count_, "box2d");
    while (step_count_ < target) step();
}

void Box2dSolver::step() {
    const double h = scene_.run.dt / substeps_;
    for (int k = 0; k < substeps_; ++k) {
        const auto start = std::chrono::steady_clock::now();
        world_->Step(float(h), options_.velocity_iterations, options_.position_iterations);
        const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
        stats_.phase_seconds["box2d_step"] += elapsed.count();
        record_box2d_step(h);
    }
    ++step_count_;
    ++stats_.steps;
}

void Box2dSolver::record_box2d_step(double h) {
    for (b2Contact* c = world_->GetContactList(); c; c = c->GetNext())
        if (c->IsTouching() && c->GetFixtureA() != wall_fixture_ && c->GetFixtureB() != wall_fixture_)
            ++stats_.contacts;
    // b2Island::Solve scales a body's velocity down to b2_maxTranslation / h when it would
    // move further in one step; such a body leaves the step with exactly that speed.
    const float cap_speed = b2_maxTranslation / float(h);
    const float near_cap = (1.0f - 1e-4f) * cap_speed;
    std::int64_t capped = 0;
    for (const b2Body* body : bodies_)
        if (body->GetType() == b2_dynamicBody && body->GetLinearVelocity().LengthSquared() >= near_cap * near_cap)
            ++capped;
    cap_body_steps_ += capped;
    if (capped > 0) ++cap_steps_;
}

void Box2dSolver::read_state(ParticleState<double>& out) const {
    out = initial_;  // radii, masses, stones (which never move)
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (initial_.is_stone(i)) continue;
        const b2Vec2 p = bodies_[i]->GetPosition(), v = bodies_[i]->GetLinearVelocity();
        out.x[i] = units_.from_box2d_x(p.x);
        out.y[i] = units_.from_box2d_y(p.y);
        out.vx[i] = units_.from_box2d_length(v.x);
        out.vy[i] = units_.from_box2d_length(v.y);
    }
}

SolverStats Box2dSolver::stats() const {
    SolverStats s = stats_;
    s.counters["translation_cap_steps"] = double(cap_steps_);
    s.counters["translation_cap_body_steps"] = double(cap_body_steps_);
    s.counters["sleeping_allowed"] = (world_ && world_->GetAllowSleeping()) ? 1 : 0;
    std::int64_t asleep = 0;
    for (const b2Body* body : bodies_) asleep += body->GetType() == b2_dynamicBody && !body->IsAwake();
    s.counters["asleep_bodies"] = double(asleep);  // frozen now: not simulated, still in the metrics
    s.counters["length_scale"] = units_.scale;
    s.counters["box2d_substeps"] = substeps_;
    if (stats_.steps > 0) s.counters["seconds_per_step"] = stats_.phase_seconds.at("box2d_step") / double(stats_.steps);
    return s;
}

// The preset and every effective setting, so that a run file says how Box2D was driven. Which
// Box2D is the build's provenance (box2d_version, the installed package's version): the
// library's own b2_version is not recorded, as Box2D 2.4.1 still calls itself 2.4.0.
std::map<std::string, std::string> Box2dSolver::provenance() const {
    auto flag = [](bool b) { return std::string(b ? "true" : "false"); };
    const double threshold = restitution_threshold();
    return {
        {"box2d_preset", options_.preset},
        {"box2d_length_scale", round_trip_text(units_.scale)},
        {"box2d_time_step", round_trip_text(scene_.run.dt / substeps_)},
        {"box2d_substeps", std::to_string(substeps_)},
        {"box2d_velocity_iterations", std::to_string(options_.velocity_iterations)},
        {"box2d_position_iterations", std::to_string(options_.position_iterations)},
        {"box2d_restitution_threshold", round_trip_text(units_.from_box2d_length(threshold))},
        {"box2d_restitution_threshold_box2d_units", round_trip_text(threshold)},
        {"box2d_bullet", flag(options_.bullet)},
        {"box2d_sleeping", flag(options_.sleeping)},
        {"box2d_warm_starting", flag(options_.warm_starting)},
        {"box2d_continuous", flag(options_.continuous)},
        {"box2d_fixed_rotation", flag(options_.fixed_rotation)},
        {"box2d_profiler", box2d_profiler_off() ? "off (b2Timer reads no clock: box2d_profiler.cpp)" : "on"},
    };
}

}  // namespace collide
