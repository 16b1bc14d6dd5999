// The plain event-driven solver for hard disks (backend `event-plain`). The method (Alder &
// Wainwright, J. Chem. Phys. 27 (1957) 1208 and 31 (1959) 459; Allen & Tildesley, "Computer
// Simulation of Liquids", 2nd ed., §3.7; Rapaport, "The Art of Molecular Dynamics Simulation",
// 2nd ed., ch. 14): between collisions every disk flies freely, on a straight line (a parabola
// under uniform gravity). So the moment of every possible next event can be computed in
// advance: two disks touching, a disk touching a wall, a disk crossing into the next cell of
// the cell list. The predicted events wait in a priority queue (a binary heap, earliest on
// top). The solver takes the earliest, moves the disks involved to that moment, applies the
// event and predicts the new events of those disks. Nothing is approximated: the only errors
// are rounding errors (which chaos amplifies, so gases are compared by their statistics).
//
// Four plain choices, each the textbook one:
// - Local clocks: disk i keeps its position and velocity at its own time t_i; only the disks of
//   an event are moved to the present (Rapaport ch. 14), so an event costs the same for any N.
// - Lazy invalidation: an event is never removed from the heap. Each disk counts its events;
//   a prediction records the counts of its disks, and an event whose disks have had an event
//   since is stale and dropped when it comes to the top (Sedgewick & Wayne, "Algorithms", 4th
//   ed., §6.1, event-driven simulation).
// - Cell list: the box is cut into cells at least one contact distance (2 r_max) wide, so a
//   disk can only touch disks in its own cell and the 8 around it (Allen & Tildesley §5.3).
//   Entering a new cell is an event like the others; after it the disk is predicted afresh.
// - Every event ends the same way: the counters of its disks go up (their older events are now
//   stale) and the disks are predicted from scratch; a stone, which never moves, keeps its count.
//
// The formulas of a collision are written once, in physics/ (collision_time.h: when, and
// collision_rule.h: what happens), shared with the tuned `event`; core/numerics/target_time.h checks t.
#include "plain_event_solver.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/metrics.h"
#include "core/scene/scene_features.h"
#include "core/numerics/target_time.h"
#include "event_statistics.h"
#include "hard_disk_input.h"
#include "physics/collision_rule.h"
#include "physics/collision_time.h"
#include "physics/stepping_laws.h"

namespace collide {
using event_time::never;

std::optional<std::string> PlainEventSolver::supports(const Scene& scene) {
    const SceneFeatures f = scene_features(scene);
    if (auto reason = outside_event_model(f)) return reason;  // (shared with `event`)
    if (f.restitution != 1 || f.wall_restitution != 1)
        return "restitution below 1: inelastic disks can collapse (infinitely many collisions in a finite time), "
               "and the plain solver leaves out the TC model that prevents it (the `event` backend has it)";
    return std::nullopt;
}

void PlainEventSolver::load(const Scene& scene, const ParticleState<double>& initial) {
    if (auto reason = supports(scene)) throw std::runtime_error("event-plain: scene '" + scene.name + "': " + *reason);
    check_hard_disk_input("event-plain", scene, initial);  // (shared with `event`)
    scene_ = scene;
    gx_ = scene.physics.gravity_x, gy_ = scene.physics.gravity_y;
    ParticleState<double> s = initial;
    const World& w = scene.world;
    CompensatedSum kinetic;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (scene.periodic()) {  // positions inside the box, the cells' coordinates
            s.x[i] = WallLaw<double>::wrap(s.x[i], w.xmin, w.width());
            s.y[i] = WallLaw<double>::wrap(s.y[i], w.ymin, w.height());
        }
        if (s.is_stone(i) && scene.has_gravity())
            throw std::runtime_error("event-plain: particle " + std::to_string(i) + " is a stone, and the scene has gravity");
        if (s.is_stone(i)) s.vx[i] = s.vy[i] = 0;  // a kinematic stone never moves, as in the stepping rules
        kinetic.add(disk_kinetic_energy(s.mass[i], s.vx[i], s.vy[i]));
    }
    reject_overlapping_disks("event-plain", scene, s);  // (shared with `event`)
    disks_.clear();
    for (std::size_t i = 0; i < s.size(); ++i)
        disks_.push_back(Disk{s.x[i], s.y[i], s.vx[i], s.vy[i], 0.0, s.radius[i], s.mass[i], s.inv_mass[i]});
    make_cells();
    queue_ = {}, now_ = progress_mark_ = 0;
    events_since_mark_ = pair_events_ = wall_events_ = cell_events_ = stale_events_ = 0;
    kinetic_ = kinetic.value();
    virial_ = {}, wall_impulse_[0] = wall_impulse_[1] = wall_impulse_[2] = wall_impulse_[3] = {};
    for (std::uint32_t i = 0; i < disks_.size(); ++i)
        if (disks_[i].inv_mass != 0) predict(i);  // stones have no events of their own
}

// Cells of side >= 2 r_max. A huge, nearly empty box gets fewer, larger cells (still correct,
// only slower). A periodic axis needs 3 cells, else a neighbour cell would be visited twice.
void PlainEventSolver::make_cells() {
    const World& w = scene_.world;
    double r_max = 0;
    for (const Disk& d : disks_) r_max = std::max(r_max, d.radius);
    const double size = r_max > 0 ? 2 * r_max : 1.0;
    cells_x_ = std::max<std::int64_t>(1, std::int64_t(w.width() / size));
    cells_y_ = std::max<std::int64_t>(1, std::int64_t(w.height() / size));
    while (cells_x_ * cells_y_ > std::max<std::int64_t>(1024, 4 * std::int64_t(disks_.size())))
        cells_x_ = std::max<std::int64_t>(1, cells_x_ / 2), cells_y_ = std::max<std::int64_t>(1, cells_y_ / 2);
    if (scene_.periodic() && (cells_x_ < 3 || cells_y_ < 3))
        throw std::runtime_error("event-plain: the periodic box is narrower than 3 contact distances (2 r_max); "
                                 "the minimum-image convention needs at least 3 cells per axis");
    cell_w_ = w.width() / double(cells_x_);
    cell_h_ = w.height() / double(cells_y_);
    cells_.assign(std::size_t(cells_x_ * cells_y_), {});
    for (std::uint32_t i = 0; i < disks_.size(); ++i) {
        Disk& d = disks_[i];
        d.cx = std::clamp<std::int64_t>(std::int64_t((d.x - w.xmin) / cell_w_), 0, cells_x_ - 1);
        d.cy = std::clamp<std::int64_t>(std::int64_t((d.y - w.ymin) / cell_h_), 0, cells_y_ - 1);
        cells_[std::size_t(d.cy * cells_x_ + d.cx)].push_back(i);
    }
}

// Calls visit(j) for every disk j != i in the 3x3 cells around disk i's cell.
template <typename Visit>
void PlainEventSolver::for_each_neighbour(std::uint32_t i, Visit&& visit) const {
    for (std::int64_t oy = -1; oy <= 1; ++oy)
        for (std::int64_t ox = -1; ox <= 1; ++ox) {
            std::int64_t cx = disks_[i].cx + ox, cy = disks_[i].cy + oy;
            if (scene_.periodic()) cx = (cx + cells_x_) % cells_x_, cy = (cy + cells_y_) % cells_y_;
            else if (cx < 0 || cx >= cells_x_ || cy < 0 || cy >= cells_y_) continue;
            for (std::uint32_t j : cells_[std::size_t(cy * cells_x_ + cx)])
                if (j != i) visit(j);
        }
}

// Free flight under uniform gravity g from the disk's clock to now (dt = now - t_i):
//   x(now) = x + (v + g dt / 2) dt,   v(now) = v + g dt   (g = 0: a straight line).
void PlainEventSolver::position_now(std::uint32_t i, double& x, double& y, double& vx, double& vy) const {
    const Disk& d = disks_[i];
    const double dt = now_ - d.t;
    x = d.x + (d.vx + 0.5 * gx_ * dt) * dt;
    y = d.y + (d.vy + 0.5 * gy_ * dt) * dt;
    vx = d.vx + gx_ * dt;
    vy = d.vy + gy_ * dt;
}

void PlainEventSolver::bring_to_now(std::uint32_t i) {
    Disk& d = disks_[i];
    position_now(i, d.x, d.y, d.vx, d.vy);
    d.t = now_;
}

// Queues every event of disk i from now on: a collision with each neighbour whose path meets
// i's, and the first wall or cell border i reaches.
void PlainEventSolver::predict(std::uint32_t i) {
    bring_to_now(i);
    const Disk& a = disks_[i];
    const World& w = scene_.world;
    for_each_neighbour(i, [&](std::uint32_t j) {
        double xj, yj, vxj, vyj;
        position_now(j, xj, yj, vxj, vyj);
        double dx = a.x - xj, dy = a.y - yj;
        if (scene_.periodic()) {  // the nearest image of j (minimum-image convention)
            dx = WallLaw<double>::minimum_image(dx, w.width());
            dy = WallLaw<double>::minimum_image(dy, w.height());
        }
        // Both disks feel the same gravity, so their relative motion is a straight line and the
        // contact time is a root of a quadratic (stable form: physics/collision_time.h).
        const double dt = event_time::pair_collision_time(dx, dy, a.vx - vxj, a.vy - vyj, a.radius + disks_[j].radius);
        if (dt != never) queue_.push(Event{now_ + dt, Kind::pair, 0, i, j, a.count, disks_[j].count});
    });
    predict_wall_or_cell(i);
}

// The first border of disk i's cell it crosses, or wall it touches (centre at wall + r). Along
// each axis q(t) = q + v t + a t^2 / 2 crosses a level upwards or downwards
// (physics/collision_time.h). The outer cells of a box with walls have no border beyond.
void PlainEventSolver::predict_wall_or_cell(std::uint32_t i) {
    const Disk& d = disks_[i];
    const World& w = scene_.world;
    const bool periodic = scene_.periodic();
    Event best{never, Kind::cell, 0, i, i, d.count, d.count};
    auto consider = [&](double dt, Kind kind, int side) {
        if (now_ + dt < best.time) best.time = now_ + dt, best.kind = kind, best.side = std::uint8_t(side);
    };
    // One axis: position q, velocity v, acceleration a, cell c of n, borders lo + c * width.
    auto axis = [&](double q, double v, double a, std::int64_t c, std::int64_t n, double lo, double width,
                    double wall_lo, double wall_hi, int side) {
        if (periodic || c > 0) consider(event_time::downward_crossing_time(lo + double(c) * width - q, v, a), Kind::cell, side);
        if (periodic || c < n - 1)
            consider(event_time::upward_crossing_time(lo + double(c + 1) * width - q, v, a), Kind::cell, side + 1);
        if (periodic) return;
        consider(event_time::downward_crossing_time(wall_lo + d.radius - q, v, a), Kind::wall, side);
        consider(event_time::upward_crossing_time(wall_hi - d.radius - q, v, a), Kind::wall, side + 1);
    };
    axis(d.x, d.vx, gx_, d.cx, cells_x_, w.xmin, cell_w_, w.xmin, w.xmax, 0);
    axis(d.y, d.vy, gy_, d.cy, cells_y_, w.ymin, cell_h_, w.ymin, w.ymax, 2);
    if (best.time != never) queue_.push(best);
}

bool PlainEventSolver::stale(const Event& e) const {
    return disks_[e.i].count != e.count_i || (e.kind == Kind::pair && disks_[e.j].count != e.count_j);
}

void PlainEventSolver::advance_to(double t) {
    check_target_time("event-plain", t, now_, scene_.run.dt, false);  // NaN, infinity, the past: refused
    while (!queue_.empty() && queue_.top().time <= t) {
        const Event e = queue_.top();
        queue_.pop();
        if (stale(e)) {
            ++stale_events_;
            continue;
        }
        // A prediction is never earlier than the moment it was made at (collision_time.h
        // returns 0 for "now" rather than a time in the past), so time never runs backwards.
        now_ = std::max(now_, e.time);
        check_progress(e);
        process(e);
    }
    now_ = t;
}

void PlainEventSolver::process(const Event& e) {
    switch (e.kind) {
    case Kind::pair: collide_pair(e.i, e.j); break;
    case Kind::wall: collide_wall(e.i, e.side); break;
    case Kind::cell: cross_cell(e.i, e.side); break;
    }
    // Every older event of these disks is now stale; predict them afresh.
    ++disks_[e.i].count;
    predict(e.i);
    // A stone's course never changes: its count stays, so its other collisions stay valid.
    if (e.kind != Kind::pair || disks_[e.j].inv_mass == 0) return;
    ++disks_[e.j].count;
    predict(e.j);
}

// An elastic collision of smooth disks (physics/collision_rule.h): an impulse along the line
// of centres d = x_i - x_j reverses the normal relative velocity; momentum and kinetic energy
// are conserved.
void PlainEventSolver::collide_pair(std::uint32_t i, std::uint32_t j) {
    bring_to_now(i);
    bring_to_now(j);
    Disk &a = disks_[i], &b = disks_[j];
    double dx = a.x - b.x, dy = a.y - b.y;
    if (scene_.periodic()) {
        dx = WallLaw<double>::minimum_image(dx, scene_.world.width());
        dy = WallLaw<double>::minimum_image(dy, scene_.world.height());
    }
    const double d_dot_u = dx * (a.vx - b.vx) + dy * (a.vy - b.vy);
    if (!(d_dot_u < 0)) return;  // a grazing contact that rounding turned into a miss
    const double d2 = dx * dx + dy * dy;
    const double g = event_rule::impulse_factor(d_dot_u, d2, a.inv_mass + b.inv_mass, 1.0);
    a.vx += a.inv_mass * g * dx, a.vy += a.inv_mass * g * dy;
    b.vx -= b.inv_mass * g * dx, b.vy -= b.inv_mass * g * dy;
    virial_.add(g * d2);  // d.(J n) = g |d|^2, for the pressure (stats)
    ++pair_events_;
}

// A smooth, elastic wall reverses the velocity component normal to it. Rounding never puts
// the centre beyond the contact line: it is put back on it.
void PlainEventSolver::collide_wall(std::uint32_t i, std::uint8_t side) {
    bring_to_now(i);
    Disk& d = disks_[i];
    const World& w = scene_.world;
    const bool x_axis = side < 2, low = side % 2 == 0;
    double& q = x_axis ? d.x : d.y;
    double& v = x_axis ? d.vx : d.vy;
    const double contact = x_axis ? (low ? w.xmin + d.radius : w.xmax - d.radius)
                                  : (low ? w.ymin + d.radius : w.ymax - d.radius);
    q = low ? std::max(q, contact) : std::min(q, contact);
    ++wall_events_;
    if (low ? !(v < 0) : !(v > 0)) return;  // at rest on the contact line: nothing to reflect
    wall_impulse_[side].add(2 * d.mass * std::fabs(v));  // momentum given to the wall
    v = -v;
}

// Disk i enters the neighbouring cell across `side`. In a periodic box, leaving through one
// side of the box is entering through the other: the centre moves by one box length.
void PlainEventSolver::cross_cell(std::uint32_t i, std::uint8_t side) {
    bring_to_now(i);
    Disk& d = disks_[i];
    auto& old_cell = cells_[std::size_t(d.cy * cells_x_ + d.cx)];
    old_cell.erase(std::find(old_cell.begin(), old_cell.end(), i));
    if (side < 2) d.cx += side == 0 ? -1 : 1;
    else d.cy += side == 2 ? -1 : 1;
    const World& w = scene_.world;
    if (d.cx < 0) d.cx += cells_x_, d.x += w.width();
    if (d.cx >= cells_x_) d.cx -= cells_x_, d.x -= w.width();
    if (d.cy < 0) d.cy += cells_y_, d.y += w.height();
    if (d.cy >= cells_y_) d.cy -= cells_y_, d.y -= w.height();
    cells_[std::size_t(d.cy * cells_x_ + d.cx)].push_back(i);
    ++cell_events_;
}

// Events that keep coming without simulated time moving on (a disk at rest on the floor under
// gravity meets it again at the same instant) are reported, not spun forever. A Newton's
// cradle of N touching disks legitimately has N events at one instant.
void PlainEventSolver::check_progress(const Event& e) {
    if (now_ > progress_mark_) {
        progress_mark_ = now_, events_since_mark_ = 0;
        return;
    }
    if (++events_since_mark_ > 10 * std::int64_t(disks_.size()) + 100000)
        throw std::runtime_error("event-plain: no progress in simulated time at t = " + std::to_string(now_) +
                                 " (the last event of particle " + std::to_string(e.i) +
                                 "); a disk resting on a wall under gravity?");
}

void PlainEventSolver::read_state(ParticleState<double>& out) const {
    out.resize(disks_.size());
    const World& w = scene_.world;
    for (std::uint32_t i = 0; i < disks_.size(); ++i) {
        const Disk& d = disks_[i];
        position_now(i, out.x[i], out.y[i], out.vx[i], out.vy[i]);  // wrapped into the box below
        if (scene_.periodic()) {
            out.x[i] = WallLaw<double>::wrap(out.x[i], w.xmin, w.width());
            out.y[i] = WallLaw<double>::wrap(out.y[i], w.ymin, w.height());
        }
        out.radius[i] = d.radius, out.mass[i] = d.mass, out.inv_mass[i] = d.inv_mass;
    }
}

// The same counters, under the same names, as the `event` backend (event_statistics.h).
SolverStats PlainEventSolver::stats() const {
    const EventCounts counts{pair_events_, wall_events_, cell_events_, stale_events_, virial_.value(), wall_impulse_};
    return event_statistics(scene_, disks_.size(), now_, counts, kinetic_ * now_);  // K constant: e = 1
}

std::map<std::string, std::string> PlainEventSolver::provenance() const {
    return {{"event-plain.cells", std::to_string(cells_x_) + "x" + std::to_string(cells_y_)}};
}

}  // namespace collide
