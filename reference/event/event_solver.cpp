#include "event_solver.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "core/numerics/disk_overlap.h"
#include "core/numerics/number_text.h"
#include "core/scene/scene_features.h"
#include "core/metrics.h"
#include "core/scene/option_reader.h"
#include "core/numerics/representability.h"
#include "core/numerics/target_time.h"
#include "pair_batch.h"
#include "physics/collision_rule.h"
#include "physics/collision_time.h"
#include "physics/stepping_laws.h"
#include "reference/event_statistics.h"
#include "reference/hard_disk_input.h"

namespace collide {
namespace {

using event_time::never;

// The cells of a dilute gas: edge dilute_cell_factor * (a^2 / d)^(1/3) (see load).
constexpr double dilute_cell_factor = 0.45;

}  // namespace

std::optional<std::string> EventSolver::supports(const Scene& scene) {
    return outside_event_model(scene_features(scene));
}

// ---------------------------------------------------------------------------------------
// Loading and input checks
// ---------------------------------------------------------------------------------------

void EventSolver::load(const Scene& scene, const ParticleState<double>& initial) {
    if (auto reason = supports(scene)) throw std::runtime_error("event: scene '" + scene.name + "': " + *reason);
    scene_ = scene;
    validate_input(initial);
    const std::size_t n = initial.size();
    state_ = initial;
    gx_ = scene.physics.gravity_x;
    gy_ = scene.physics.gravity_y;
    gravity_ = gx_ != 0 || gy_ != 0;
    const World& w = scene.world;
    for (std::size_t i = 0; i < n; ++i) {
        if (state_.is_stone(i)) {
            // Kinematic stones never move, as in the stepping rules.
            if (gx_ != 0 || gy_ != 0)
                throw std::runtime_error("event: particle " + std::to_string(i) +
                                         " is a stone and the scene has gravity, which this solver does not "
                                         "support (the collision time would be a quartic root)");
            state_.vx[i] = state_.vy[i] = 0;
        }
        if (scene.periodic()) {
            state_.x[i] = WallLaw<double>::wrap(state_.x[i], w.xmin, w.width());
            state_.y[i] = WallLaw<double>::wrap(state_.y[i], w.ymin, w.height());
        }
    }
    disks_.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        disks_[i] = Disk{state_.x[i], state_.y[i], state_.vx[i], state_.vy[i], 0.0, state_.radius[i], 0, CellLinks{}};
    // The TC clocks are read only when a collision can be inelastic; in an elastic scene they
    // are not written either (a random memory access per disk and collision saved).
    inelastic_ = scene.physics.restitution < 1 || scene.physics.wall_restitution < 1;
    last_collision_.assign(n, -std::numeric_limits<double>::infinity());
    now_ = progress_mark_ = kinetic_mark_ = 0;
    events_since_mark_ = 0;
    pair_events_ = wall_events_ = cell_events_ = shell_events_ = stale_events_ = tc_elastic_ = 0;
    virial_ = kinetic_integral_ = CompensatedSum{};
    for (auto& s : wall_impulse_) s = CompensatedSum{};

    double r_max = 0, r_sum = 0, v2_sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
        r_max = std::max(r_max, disks_[i].radius);
        r_sum += disks_[i].radius;
        v2_sum += disks_[i].vx * disks_[i].vx + disks_[i].vy * disks_[i].vy;
    }
    // Time scale: the time a typical disk needs to travel one diameter (from the rms speed or,
    // for disks starting at rest under gravity, from the fall speed over one diameter).
    const double diameter = n > 0 ? 2 * r_sum / double(n) : 1.0;
    const double speed = std::max(n > 0 ? std::sqrt(v2_sum / double(n)) : 0.0, std::sqrt(std::hypot(gx_, gy_) * diameter));
    time_scale_ = speed > 0 ? diameter / speed : 1.0;
    const std::optional<double> cell_edge = read_options(r_max);

    // Cell size: at least the largest contact distance 2 r_max, so that the 3x3 cells around a
    // disk hold every disk it can touch. In a dilute gas such cells are nearly empty and a disk
    // crosses several of them between two collisions; larger cells mean fewer crossings but
    // more neighbours per prediction. Per collision a disk flies a free path l ~ a / d (a = A / N,
    // the area per disk; d the mean diameter) and crosses ~ l / c cells of edge c, and its
    // predictions test ~ 9 c^2 / a disks: the sum F l / c + G c^2 / a is least at
    // c ~ (a^2 / d)^(1/3). (A crossing also tests the disks of the three cells it enters, a term
    // ~ l c / a that the rule leaves out; the constant absorbs it where it was fitted.) The
    // constant 0.45 (dilute_cell_factor) was fitted at area fractions 0.03 and 0.1: at 0.1 it
    // makes cells of 1.78 d against 2.8 d for one disk per cell (sqrt(a), the earlier choice),
    // 12 % less per collision at N = 1e3 and 4 to 5 % at 1e5 and 1e6; at 0.03 (4.0 d against
    // 5.1 d) the two tie. Used only where cells of 2 r_max would hold fewer than 1/4 disk on
    // average (area fraction below ~0.2 for equal disks); in denser gases larger cells only add
    // neighbours (+18 % instructions at 0.5). bench/journal.md (2026-11-29) has the
    // measurements. The option cell_size overrides the choice, to measure it
    // (docs/course/5-making-it-fast.md, ex. 5.3).
    double cell_size = n > 0 ? 2 * r_max : 1.0;
    const double area_per_disk = n > 0 ? w.width() * w.height() / double(n) : 0.0;
    const double narrowest = std::min(w.width(), w.height());
    const double one_disk_size = std::sqrt(area_per_disk);  // cells of one disk on average
    // (Only in a box at least 4 such cells wide: a periodic box needs 3 cells per axis. Where
    // the balance asks for wider cells than that, as in a small box of very few disks, cells of
    // one disk on average, if they fit. Where the test below passes, both exceed 2 r_max.)
    double dilute_size = dilute_cell_factor * std::cbrt(area_per_disk * area_per_disk / diameter);
    if (!(4 * dilute_size < narrowest)) dilute_size = one_disk_size;
    if (n > 0 && cell_size < 0.5 * one_disk_size && 4 * dilute_size < narrowest) cell_size = dilute_size;
    // In the neighbour-list design the cells hold the shell centres, and a disk's list is
    // gathered from the 3x3 cells around its centre: cells at least one list cutoff wide.
    if (shells_on()) cell_size = 2 * r_max + 2 * shell_ + shell_slack_;
    const double edge = cell_edge.value_or(cell_size);
    cells_.configure(w, shells_on() ? std::max(edge, cell_size) : edge, n);
    if (scene.periodic() && (cells_.cells_x() < 3 || cells_.cells_y() < 3))
        throw std::runtime_error("event: periodic box " + round_trip_text(w.width()) + " x " + round_trip_text(w.height()) +
                                 " is narrower than 3 contact distances (2 r_max = " + round_trip_text(2 * r_max) +
                                 "); the minimum-image convention needs at least 3 cells per axis");
    for (std::uint32_t i = 0; i < n; ++i) cells_.insert(disks_, i, cells_.column_of(disks_[i].x), cells_.row_of(disks_[i].y));
    reject_overlaps();
    if (shells_on()) {
        // Room for 1.5 times the disks a list holds on average, plus 8 (it grows when full).
        const double cutoff = 2 * r_max + 2 * shell_;
        const double expected = n > 0 ? double(n) * std::numbers::pi * cutoff * cutoff / (w.width() * w.height()) : 0;
        shells_.reset(n, std::uint32_t(std::min(1.5 * expected + 8, double(n) + 4)));
        for (std::uint32_t i = 0; i < n; ++i) shells_.shell(i).cx = disks_[i].x, shells_.shell(i).cy = disks_[i].y;
        for (std::uint32_t i = 0; i < n; ++i) build_shell(i, false);
    }

    // Stage 3 of the prefetch pipeline where the cells hold a disk or more on average.
    const bool second_records = double(n) >= double(cells_.cells_x()) * double(cells_.cells_y());
    prefetch_.configure(prefetch_choice_ == "auto" ? n >= prefetch_from_disks : prefetch_choice_ == "on", second_records);

    queue_.reset(n);
    for (std::uint32_t i = 0; i < n; ++i) queue_.payload(i).inv_mass = state_.inv_mass[i];
    // Stones never move and have no events of their own (the movers find their collisions
    // with them): their queue time stays infinite.
    for (std::uint32_t i = 0; i < n; ++i) {
        if (state_.is_stone(i)) queue_.update(i, never);
        else predict_any(i);
    }
    kinetic_ = kinetic_energy_now();

    original_.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) original_[i] = i;
    renumber();
}

// The speed layer's renumbering (cell_order_renumbering.h): exact, so the events are the same
// with or without it.
void EventSolver::renumber() {
    std::vector<std::vector<double>*> per_disk = state_.arrays();
    per_disk.push_back(&last_collision_);
    renumbering_.apply(disks_, cells_, queue_, per_disk, original_);
    if (shells_on()) shells_.renumber(renumbering_.order(), renumbering_.new_of());
    prefetch_.forget();  // (it holds disks by their old numbers)
}

void EventSolver::renumber_if_due() {
    if (renumbering_.count_event()) renumber();
}

// Reads [backend.event]: tc (the TC model's duration), renumber_interval (events between
// renumberings), prefetch ("auto": from prefetch_from_disks disks on, "on", "off") and
// cell_size (the cell edge, at least the largest contact distance 2 r_max; returned, nullopt
// when not set) and shell (the neighbour-list design, off by default: see choose_shell). The
// defaults of the last four suit every scene; the options are there to test the renumbering,
// the prefetching, the cells and the shells (none may change the physics) and to measure
// their effect.
std::optional<double> EventSolver::read_options(double r_max) {
    // TC model (S. Luding and S. McNamara, Granular Matter 1 (1998) 113): a collision that
    // follows another collision of the same disk within t_c is treated as elastic. This stops
    // the inelastic collapse of e < 1 (infinitely many collisions in finite time, McNamara &
    // Young, Phys. Fluids A 4 (1992) 496). The default t_c is 1e-4 of the time a disk needs to
    // cross one diameter: far below the mean free time of a gas (about 0.05 of it even at area
    // fraction 0.7), so mainly collisions inside a collapsing cluster are affected, yet large
    // enough that a column settling on a floor under gravity stays resolvable in double (with
    // 1e-6 the gaps fall below the rounding of the positions and the loop stalls). The counter
    // `tc_elastic` says how many collisions were made elastic.
    OptionReader options("event", &scene_);
    tc_ = options.get_double("tc", 1e-4 * time_scale_, 0, "a duration >= 0");
    const std::int64_t renumber_interval = options.get_int("renumber_interval", CellOrderRenumbering::default_interval(state_.size()),
                                                           1, INT64_MAX, "a whole number of events >= 1");
    prefetch_choice_ = options.get_choice("prefetch", {"auto", "on", "off"}, "auto");
    const std::optional<double> cell_edge = options.find_double(
        "cell_size", 2 * r_max, "a cell edge >= the largest contact distance 2 r_max = " + round_trip_text(2 * r_max));
    // shell: the shell width delta of the neighbour-list design (neighbour_shells.h) as a
    // fraction of the largest contact distance 2 r_max; 0, the default, keeps the cell-list
    // design. The lists were measured slower than the cells in two dimensions (per collision
    // 1.5x at area fraction 0.5 with the best shell, 0.3; 2.3x at 0.1 with 1.0; N = 1e5;
    // docs/event-driven.md, "Neighbour lists with shells"), so they are an experiment, not
    // the default.
    const double shell_fraction = options.get_double("shell", 0.0, 0, "a fraction of 2 r_max >= 0");
    options.refuse_unknown();
    // (Positions are exact to a few ulps of the box size; the slack covers that many times over.)
    shell_slack_ = 1e-9 * 2 * r_max + 64 * std::numeric_limits<double>::epsilon() *
                                          std::max(std::fabs(scene_.world.xmin) + scene_.world.width(),
                                                   std::fabs(scene_.world.ymin) + scene_.world.height());
    shell_ = choose_shell(shell_fraction, r_max);
    renumbering_.set_interval(renumber_interval);
    return cell_edge;
}

// The checks are shared with the plain solver (hard_disk_input.h): both refuse the same starts.
void EventSolver::validate_input(const ParticleState<double>& s) const { check_hard_disk_input("event", scene_, s); }

void EventSolver::reject_overlaps() const { reject_overlapping_disks("event", scene_, state_); }

// The neighbour-list design needs straight free flights (under gravity a disk's path is a
// parabola and the exit a quartic: such scenes keep the cell lists) and, in a periodic box, a
// box at least 4 cells of the list cutoff 2 r_max + 2 delta wide: more than twice the largest
// separation a list can hold (2 r_max + 4 delta: two centres within the cutoff, each disk
// within delta of its centre), so that one shift by the box makes the minimum image in the
// innermost loop, no disk meets two images of another, and interior cells exist.
double EventSolver::choose_shell(double fraction, double r_max) const {
    const double delta = fraction * 2 * r_max;
    if (!(delta > 0) || gravity_) return 0;
    const World& w = scene_.world;
    if (scene_.periodic() && std::min(w.width(), w.height()) < 4 * (2 * r_max + 2 * delta + shell_slack_)) return 0;
    return delta;
}

// ---------------------------------------------------------------------------------------
// The event loop
// ---------------------------------------------------------------------------------------

void EventSolver::advance_to(double t) {
    check_target_time("event", t, now_, scene_.run.dt, false);  // NaN would become every disk's time
    if (shells_on()) run_events<true>(t);
    else run_events<false>(t);
    now_ = t;
}

template <bool Shells>
void EventSolver::run_events(double t) {
    while (!queue_.empty() && queue_.top_time() <= t) {
        process_event<Shells>();
        renumber_if_due();
    }
}

// The speed layer's prefetch pipeline (prefetch_pipeline.h), from 2^16 disks on: it only
// requests memory, so the events are the same with or without it.
template <bool Shells>
void EventSolver::prefetch_coming_events() {
    if (!prefetch_.on()) return;
    if constexpr (Shells) prefetch_.advance(disks_, cells_, shells_, queue_);
    else prefetch_.advance(disks_, cells_, queue_);
}

template <bool Shells>
void EventSolver::process_event() {
    prefetch_coming_events<Shells>();
    const std::uint32_t i = queue_.top();
    // Event times are never earlier than the time they were predicted at (collision_time.h
    // clamps to "now"), so simulated time never runs backwards.
    now_ = std::max(now_, queue_.top_time());
    check_progress(i);
    const Prediction p = prediction(i);
    prefetch_.count_if_named(i, p);  // (the pipeline's statistic events_named_ahead)
    switch (p.kind) {
    case EventKind::pair:
        if (disks_[p.partner].count != p.partner_count) {
            // The partner changed course after this was predicted: the event is stale.
            ++stale_events_;
            predict<Shells>(i);
            return;
        }
        collide_pair(i, p.partner);
        // (overlaps with predicting i)
        if constexpr (Shells) shells_.prefetch_neighbours(disks_, p.partner);
        else cells_.prefetch_neighbourhood(disks_, p.partner);
        predict<Shells>(i);  // (the disk of an event is never a stone: stones have no events)
        if (queue_.payload(p.partner).inv_mass != 0) predict<Shells>(p.partner);  // (a stone does not move)
        return;
    case EventKind::wall:
        collide_wall(i, p.border);
        predict<Shells>(i);
        return;
    case EventKind::cell:
        if constexpr (Shells) throw std::logic_error("event: a cell crossing in the shells' design");
        cross_cell(i, p.border);
        predict_after_crossing(i, p.border);
        return;
    case EventKind::shell:
        if constexpr (!Shells) throw std::logic_error("event: a shell exit in the cells' design");
        exit_shell(i);
        predict<Shells>(i);
        return;
    case EventKind::none:
        return;  // unreachable: such a disk's time is infinite
    }
}

// An event loop that keeps finding events without simulated time moving on (inelastic
// collapse with t_c = 0, a disk at rest on a floor) must be reported, not spun forever.
// (The test is inline, the counting and the report out of line: it runs at every event.)
inline void EventSolver::check_progress(std::uint32_t i) {
    const double resolution = 1e-12 * time_scale_ + 4 * std::numeric_limits<double>::epsilon() * std::fabs(now_);
    if (now_ > progress_mark_ + resolution) {
        progress_mark_ = now_;
        events_since_mark_ = 0;
        return;
    }
    count_event_without_progress(i, resolution);
}

void EventSolver::count_event_without_progress(std::uint32_t i, double resolution) {
    // A Newton's cradle of N touching disks legitimately has N events at one instant.
    const std::int64_t limit = 10 * std::int64_t(state_.size()) + 100000;
    if (++events_since_mark_ <= limit) return;
    const Prediction& p = prediction(i);
    const std::string with = p.kind == EventKind::pair ? "particle " + std::to_string(original_[p.partner])
                             : p.kind == EventKind::wall ? "wall " + std::to_string(p.border)
                             : p.kind == EventKind::shell ? "its shell"
                                                         : "a cell border";
    throw std::runtime_error("event: no progress in simulated time: " + std::to_string(events_since_mark_) +
                             " events at t = " + round_trip_text(now_) + " within " + round_trip_text(resolution) +
                             "; the last one between particle " + std::to_string(original_[i]) + " and " + with +
                             ". Likely an inelastic collapse (set [backend.event] tc > 0) or a disk "
                             "resting on a wall under gravity");
}

// ---------------------------------------------------------------------------------------
// Free flight and prediction
// ---------------------------------------------------------------------------------------

void EventSolver::bring_to_now(std::uint32_t i) {
    const double dt = now_ - disks_[i].t;
    disks_[i].t = now_;
    // (A stone needs no exception: it has zero velocity and scenes with stones have no gravity,
    // so the lines below leave it where it is.)
    if (dt == 0) return;
    // Free flight under uniform gravity: x(t) = x + (v + g dt / 2) dt, v(t) = v + g dt.
    // (Each component is rounded as the scalar lines x += (vx + 0.5 gx dt) dt would be.)
    const Vector2d g(gx_, gy_);
    position_of(disks_[i]) += (velocity_of(disks_[i]) + 0.5 * g * dt) * dt;
    velocity_of(disks_[i]) += g * dt;
}

template <bool Shells>
void EventSolver::predict(std::uint32_t i) {
    bring_to_now(i);
    Prediction p;
    if constexpr (Shells) {
        // (The minimum-image choice of earliest_pair holds here too: a neighbour's centre lies
        // in the 3x3 cells around i's centre, and each disk within delta of its centre.)
        earliest_pair(i, p, [&](auto&& visit) {
            for (const std::uint32_t* j = shells_.begin(i); j != shells_.end(i); ++j) visit(*j);
        });
    } else {
        earliest_pair(i, p, [&](auto&& visit) { cells_.for_each_neighbour(disks_, i, visit); });
    }
    file_prediction<Shells>(i, p);
}

// After a cell crossing (cross_cell has brought disk i to now) the disk's course is the same,
// so its earliest pair collision with the disks of its old neighbourhood is still the one found
// before: of the 3x3 cells around the new cell, six were neighbours already, and only the
// three entered ones need a look. A neighbour that changed course since then was re-predicted
// itself, against i among others, so the pair (i, j) is covered by j's prediction. If the kept
// collision's partner has changed course, the kept time is no longer a collision: predict
// afresh against the whole neighbourhood.
void EventSolver::predict_after_crossing(std::uint32_t i, std::uint32_t border) {
    Prediction p = prediction(i);
    if (p.pair_time != never && disks_[p.partner].count != p.partner_count) {
        predict<false>(i);
        return;
    }
    earliest_pair(i, p, [&](auto&& visit) { cells_.for_each_entered(disks_, i, border, visit); });
    file_prediction<false>(i, p);
}

// Only disks in the cells along the edges of a periodic box can have neighbours across a side;
// elsewhere the minimum-image test is left out of the innermost loop.
template <typename VisitCells>
void EventSolver::earliest_pair(std::uint32_t i, Prediction& p, VisitCells&& visit_cells) const {
    if (cells_.needs_minimum_image(disks_[i].links)) earliest_pair_in<true>(i, p, visit_cells);
    else earliest_pair_in<false>(i, p, visit_cells);
}

// The innermost loop of the solver stays in scalars (no Eigen::Vector2d): its minimum image
// is per component and the collision time (physics/collision_time.h) takes the components, so
// vectors here would read no closer to the equations, in the loop where every instruction
// counts. The walk gathers the neighbours; their collision times are computed in batches
// (pair_batch.h), which spares the processor the branches it cannot predict and gives the
// same times, so the same events.
template <bool MinimumImage, typename VisitCells>
void EventSolver::earliest_pair_in(std::uint32_t i, Prediction& p, VisitCells& visit_cells) const {
    const double xi = disks_[i].x, yi = disks_[i].y, vxi = disks_[i].vx, vyi = disks_[i].vy, ri = disks_[i].radius;
    const double width = scene_.world.width(), height = scene_.world.height();
    double best_dt = p.pair_time - now_;
    PairBatch batch;
    auto take_earliest = [&](std::uint32_t j, double dt) {
        if (dt < best_dt) {
            best_dt = dt;
            p.partner = j;
            p.partner_count = disks_[j].count;
            p.pair_time = now_ + dt;
        }
    };
    visit_cells([&](std::uint32_t j) {
        if (j == i) return;
        double xj, yj, vxj, vyj;
        position_now(j, xj, yj, vxj, vyj);
        double dx = xi - xj, dy = yi - yj;
        if constexpr (MinimumImage) {
            // Minimum image; both centres lie in [lo, lo + L), so one shift is enough
            // (cheaper than WallLaw::minimum_image's division in this innermost loop).
            if (dx > 0.5 * width) dx -= width;
            else if (dx < -0.5 * width) dx += width;
            if (dy > 0.5 * height) dy -= height;
            else if (dy < -0.5 * height) dy += height;
        }
        // Both disks feel the same gravity, so their relative motion is a straight line.
        batch.add(j, dx, dy, vxi - vxj, vyi - vyj, ri + disks_[j].radius);
        if (batch.full()) batch.flush(take_earliest);
    });
    batch.flush(take_earliest);
}

template <bool Shells>
void EventSolver::file_prediction(std::uint32_t i, Prediction& p) {
    // (Chosen here, not inside: one call instead of two on every prediction.)
    const double border_time = now_ + (Shells     ? earliest_wall_or_exit(i, p.border, p.kind)
                                       : gravity_ ? earliest_border_or_wall(i, p.border, p.kind)
                                                  : earliest_border_or_wall_straight(i, p.border, p.kind));
    double t = border_time;
    if (p.pair_time < border_time) p.kind = EventKind::pair, t = p.pair_time;
    prediction(i) = p;
    queue_.update(i, t);
}

// The earliest crossing of one of the four borders of disk i's cell, or of a wall (its time
// from now; `which` and `kind` say which one, kind none if there is none), under gravity.
double EventSolver::earliest_border_or_wall(std::uint32_t i, std::uint8_t& which, EventKind& kind) const {
    const World& w = scene_.world;
    const bool periodic = scene_.periodic();
    const double r = disks_[i].radius;
    const std::int64_t cx = cells_.column(disks_[i].links), cy = cells_.row(disks_[i].links);
    double best = never;
    kind = EventKind::none;
    auto consider = [&](double t, EventKind k, std::uint8_t id) {
        if (t < best) best = t, kind = k, which = id;
    };
    // One axis: position q, velocity v, acceleration a, cell index c of n cells.
    auto axis = [&](double q, double v, double a, std::int64_t c, std::int64_t n, double border_lo, double border_hi,
                    double wall_lo, double wall_hi, std::uint8_t lo_id) {
        if (periodic || c > 0) consider(event_time::downward_crossing_time(border_lo - q, v, a), EventKind::cell, lo_id);
        if (periodic || c < n - 1) consider(event_time::upward_crossing_time(border_hi - q, v, a), EventKind::cell, std::uint8_t(lo_id + 1));
        if (periodic) return;
        consider(event_time::downward_crossing_time(wall_lo + r - q, v, a), EventKind::wall, lo_id);
        consider(event_time::upward_crossing_time(wall_hi - r - q, v, a), EventKind::wall, std::uint8_t(lo_id + 1));
    };
    axis(disks_[i].x, disks_[i].vx, gx_, cx, cells_.cells_x(), cells_.border_x(cx), cells_.border_x(cx + 1), w.xmin,
         w.xmax, 0);
    axis(disks_[i].y, disks_[i].vy, gy_, cy, cells_.cells_y(), cells_.border_y(cy), cells_.border_y(cy + 1), w.ymin,
         w.ymax, 2);
    return best;
}

// The same on a straight line (no gravity), the common case. A disk moving up an axis can
// only cross the upper border of its cell or, in the last cell of a reflecting box, reach the
// upper wall; the lower border and wall need no look, and neither does a wall behind a cell
// border (the border, nearer by at least a cell width minus a radius, comes first). The
// events found are the same as the general code's, tie-breaking included.
double EventSolver::earliest_border_or_wall_straight(std::uint32_t i, std::uint8_t& which, EventKind& kind) const {
    const World& w = scene_.world;
    const bool periodic = scene_.periodic();
    const Disk& d = disks_[i];
    const std::int64_t cx = cells_.column(d.links), cy = cells_.row(d.links);
    double best = never;
    kind = EventKind::none;
    // One axis: position q, velocity v, cell index c of n cells; lo_id numbers the lower side.
    auto axis = [&](double q, double v, std::int64_t c, std::int64_t n, double border_lo, double border_hi,
                    double wall_lo, double wall_hi, std::uint8_t lo_id) {
        double t = never;
        bool border = periodic;
        std::uint8_t id = lo_id;
        if (v > 0) {
            border = border || c < n - 1;
            t = event_time::upward_crossing_time((border ? border_hi : wall_hi - d.radius) - q, v, 0);
            id = std::uint8_t(lo_id + 1);
        } else if (v < 0) {
            border = border || c > 0;
            t = event_time::downward_crossing_time((border ? border_lo : wall_lo + d.radius) - q, v, 0);
        }
        if (t < best) best = t, kind = border ? EventKind::cell : EventKind::wall, which = id;
    };
    axis(d.x, d.vx, cx, cells_.cells_x(), cells_.border_x(cx), cells_.border_x(cx + 1), w.xmin, w.xmax, 0);
    axis(d.y, d.vy, cy, cells_.cells_y(), cells_.border_y(cy), cells_.border_y(cy + 1), w.ymin, w.ymax, 2);
    return best;
}

// The neighbour-list design: a disk's shell exit (event_time::shell_exit_time) or, in a box
// with walls, the wall it is moving towards, whichever comes first.
double EventSolver::earliest_wall_or_exit(std::uint32_t i, std::uint8_t& which, EventKind& kind) const {
    const Disk& d = disks_[i];
    const NeighbourShells::Shell& s = shells_.shell(i);
    double best = event_time::shell_exit_time(d.x - s.cx, d.y - s.cy, d.vx, d.vy, shell_);
    kind = best == never ? EventKind::none : EventKind::shell;
    if (scene_.periodic()) return best;
    const World& w = scene_.world;
    auto axis = [&](double q, double v, double wall_lo, double wall_hi, std::uint8_t lo_id) {
        const double t = v > 0   ? event_time::upward_crossing_time(wall_hi - d.radius - q, v, 0)
                         : v < 0 ? event_time::downward_crossing_time(wall_lo + d.radius - q, v, 0)
                                 : never;
        if (t < best) best = t, kind = EventKind::wall, which = std::uint8_t(lo_id + (v > 0));
    };
    axis(d.x, d.vx, w.xmin, w.xmax, 0);
    axis(d.y, d.vy, w.ymin, w.ymax, 2);
    return best;
}

void EventSolver::build_shell(std::uint32_t i, bool both_ways) {
    NeighbourShells::Shell& s = shells_.shell(i);
    s.cx = disks_[i].x;
    s.cy = disks_[i].y;
    const bool minimum_image = cells_.needs_minimum_image(disks_[i].links);
    const double width = scene_.world.width(), height = scene_.world.height();
    auto separation_squared = [&](double dx, double dy) {
        if (minimum_image) {
            // (One shift is enough, as in earliest_pair_in: the points lie within delta of the box.)
            if (dx > 0.5 * width) dx -= width;
            else if (dx < -0.5 * width) dx += width;
            if (dy > 0.5 * height) dy -= height;
            else if (dy < -0.5 * height) dy += height;
        }
        return dx * dx + dy * dy;
    };
    cells_.for_each_neighbour(disks_, i, [&](std::uint32_t j) {
        if (j == i) return;
        const double cutoff = disks_[i].radius + disks_[j].radius + 2 * shell_ + shell_slack_;
        // A cheap first test on the record already read: j is within delta of its centre, so
        // a centre within the cutoff puts j's position within cutoff + delta. Only the disks
        // that pass have their centre (another cache line) read.
        double xj, yj, vxj, vyj;
        position_now(j, xj, yj, vxj, vyj);
        const double reach = cutoff + shell_;
        if (separation_squared(s.cx - xj, s.cy - yj) >= reach * reach) return;
        const NeighbourShells::Shell& sj = shells_.shell(j);
        if (separation_squared(s.cx - sj.cx, s.cy - sj.cy) >= cutoff * cutoff) return;
        shells_.add(i, j);
        if (both_ways) shells_.add(j, i);
    });
}

// Disk i reached distance shell_ from its centre: its list is rebuilt around where it is now
// (its course does not change, so neither does its event counter: predictions that name it
// stay valid). In a periodic box its position is first put back into the box, so that every
// centre lies in the box (the minimum image of build_shell and earliest_pair_in).
void EventSolver::exit_shell(std::uint32_t i) {
    bring_to_now(i);
    if (scene_.periodic()) {
        const World& w = scene_.world;
        disks_[i].x = WallLaw<double>::wrap(disks_[i].x, w.xmin, w.width());
        disks_[i].y = WallLaw<double>::wrap(disks_[i].y, w.ymin, w.height());
    }
    old_neighbours_.assign(shells_.begin(i), shells_.end(i));
    shells_.clear(i);
    cells_.remove(disks_, i);
    cells_.insert(disks_, i, cells_.column_of(disks_[i].x), cells_.row_of(disks_[i].y));
    build_shell(i, false);
    // Symmetry: only the lists i leaves or joins are written (most neighbours stay, and each
    // list written is a cache miss once the lists outgrow the cache).
    auto holds = [](const std::uint32_t* b, const std::uint32_t* e, std::uint32_t j) { return std::find(b, e, j) != e; };
    for (std::uint32_t j : old_neighbours_)
        if (!holds(shells_.begin(i), shells_.end(i), j)) shells_.remove(j, i);
    for (std::uint32_t k = 0; k < shells_.shell(i).count; ++k) {
        const std::uint32_t j = shells_.begin(i)[k];  // (re-read: add may move the lists)
        if (!holds(old_neighbours_.data(), old_neighbours_.data() + old_neighbours_.size(), j)) shells_.add(j, i);
    }
    ++shell_events_;
}

// ---------------------------------------------------------------------------------------
// Applying events
// ---------------------------------------------------------------------------------------

double EventSolver::restitution_now(double e, std::uint32_t i, std::uint32_t j) {
    if (e == 1) return 1;
    if (now_ - last_collision_[i] < tc_ || now_ - last_collision_[j] < tc_) {
        ++tc_elastic_;
        return 1;
    }
    return e;
}

void EventSolver::collide_pair(std::uint32_t i, std::uint32_t j) {
    bring_to_now(i);
    bring_to_now(j);
    Vector2d d = position_of(disks_[i]) - position_of(disks_[j]);  // line of centres, d = x_i - x_j
    if (scene_.periodic()) {
        d.x() = WallLaw<double>::minimum_image(d.x(), scene_.world.width());
        d.y() = WallLaw<double>::minimum_image(d.y(), scene_.world.height());
    }
    const Vector2d u = velocity_of(disks_[i]) - velocity_of(disks_[j]);  // relative velocity
    const double b = d.dot(u);  // d.u < 0: approaching
    if (!(b < 0)) return;       // a grazing contact that round-off turned into a miss
    const double d2 = d.squaredNorm();
    const double wi = queue_.payload(i).inv_mass, wj = queue_.payload(j).inv_mass;
    const double e = restitution_now(scene_.physics.restitution, i, j);
    // Normal impulse of a smooth collision with restitution e (contact_law.cl.h, without the
    // overlap correction and friction): J = -(1 + e) (u.n) / (w_i + w_j), n = d / |d|.
    // Written as J n = g d with g = -(1 + e) (d.u) / (|d|^2 (w_i + w_j)):
    //   v_i' = v_i + w_i g d,   v_j' = v_j - w_j g d.
    const double g = event_rule::impulse_factor(b, d2, wi + wj, e);  // (physics/collision_rule.h)
    velocity_of(disks_[i]) += wi * g * d;
    velocity_of(disks_[j]) -= wj * g * d;
    // Collision virial d.(J n) = g |d|^2 (the pressure, see stats()).
    virial_.add(g * d2);
    // Energy lost: (1 - e^2)/2 * mu (u.n)^2 with the reduced mass mu = 1/(w_i + w_j).
    if (e != 1) {
        kinetic_integral_.add(kinetic_ * (now_ - kinetic_mark_));
        kinetic_mark_ = now_;
        kinetic_ -= 0.5 * (1 - e * e) * b * b / (d2 * (wi + wj));
    }
    ++disks_[i].count;
    ++disks_[j].count;
    if (inelastic_) last_collision_[i] = last_collision_[j] = now_;
    ++pair_events_;
}

void EventSolver::collide_wall(std::uint32_t i, std::uint32_t wall) {
    bring_to_now(i);
    const World& w = scene_.world;
    const double r = disks_[i].radius;
    const bool x_axis = wall < 2, low = wall % 2 == 0;
    double& q = x_axis ? disks_[i].x : disks_[i].y;
    double& v = x_axis ? disks_[i].vx : disks_[i].vy;
    // Round-off rule: the centre is put back exactly on the contact line, never beyond it.
    const double contact = x_axis ? (low ? w.xmin + r : w.xmax - r) : (low ? w.ymin + r : w.ymax - r);
    q = low ? std::max(q, contact) : std::min(q, contact);
    ++wall_events_;
    if (low ? !(v < 0) : !(v > 0)) return;  // at rest on the contact line: nothing to reflect
    const double e = restitution_now(scene_.physics.wall_restitution, i, i);
    const double m = state_.mass[i];
    wall_impulse_[wall].add(m * (1 + e) * std::fabs(v));
    if (e != 1) {
        kinetic_integral_.add(kinetic_ * (now_ - kinetic_mark_));
        kinetic_mark_ = now_;
        kinetic_ -= 0.5 * m * (1 - e * e) * v * v;
    }
    v = -e * v;
    ++disks_[i].count;
    if (inelastic_) last_collision_[i] = now_;
}

void EventSolver::cross_cell(std::uint32_t i, std::uint32_t border) {
    bring_to_now(i);
    std::int64_t cx = cells_.column(disks_[i].links), cy = cells_.row(disks_[i].links);
    switch (border) {
    case 0: --cx; break;
    case 1: ++cx; break;
    case 2: --cy; break;
    default: ++cy; break;
    }
    // Periodic box: leaving through one side is entering through the other.
    const World& w = scene_.world;
    if (cx < 0) cx += cells_.cells_x(), disks_[i].x += w.width();
    if (cx >= cells_.cells_x()) cx -= cells_.cells_x(), disks_[i].x -= w.width();
    if (cy < 0) cy += cells_.cells_y(), disks_[i].y += w.height();
    if (cy >= cells_.cells_y()) cy -= cells_.cells_y(), disks_[i].y -= w.height();
    cells_.remove(disks_, i);
    cells_.insert(disks_, i, cx, cy);
    ++cell_events_;
}

// ---------------------------------------------------------------------------------------
// Output
// ---------------------------------------------------------------------------------------

void EventSolver::read_state(ParticleState<double>& out) const {
    // In the scene's order: internal disk i is the scene's particle original_[i].
    out.resize(state_.size());
    const World& w = scene_.world;
    for (std::uint32_t i = 0; i < state_.size(); ++i) {
        const std::uint32_t k = original_[i];
        out.radius[k] = state_.radius[i];
        out.mass[k] = state_.mass[i];
        out.inv_mass[k] = state_.inv_mass[i];
        position_now(i, out.x[k], out.y[k], out.vx[k], out.vy[k]);
        if (scene_.periodic()) {
            out.x[k] = WallLaw<double>::wrap(out.x[k], w.xmin, w.width());
            out.y[k] = WallLaw<double>::wrap(out.y[k], w.ymin, w.height());
        }
    }
}

double EventSolver::kinetic_energy_now() const {
    CompensatedSum k;
    for (std::size_t i = 0; i < state_.size(); ++i)
        if (!state_.is_stone(i)) k.add(disk_kinetic_energy(state_.mass[i], disks_[i].vx, disks_[i].vy));
    return k.value();
}

SolverStats EventSolver::stats() const {
    const EventCounts counts{pair_events_, wall_events_, cell_events_, stale_events_, virial_.value(), wall_impulse_,
                             shell_events_};
    const double kinetic_integral = kinetic_integral_.value() + kinetic_ * (now_ - kinetic_mark_);
    SolverStats s = event_statistics(scene_, state_.size(), now_, counts, kinetic_integral);
    s.counters["tc_elastic"] = double(tc_elastic_);
    if (prefetch_.on()) s.counters["events_named_ahead"] = double(prefetch_.events_named_ahead());
    if (shells_on()) s.counters["shell_lists_grown"] = double(shells_.times_grown());
    return s;
}

std::map<std::string, std::string> EventSolver::provenance() const {
    return {{"event.tc", round_trip_text(tc_)},
            {"event.cells", std::to_string(cells_.cells_x()) + "x" + std::to_string(cells_.cells_y())},
            {"event.prefetch", prefetch_.describe()},
            {"event.neighbours", shells_on() ? "shells of width " + round_trip_text(shell_) : "cells"}};
}

}  // namespace collide
