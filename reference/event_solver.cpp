#include "event_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "core/target_time.h"
#include "event_statistics.h"
#include "physics/collision_rule.h"
#include "core/disk_overlap.h"
#include "core/scene_features.h"
#include "core/metrics.h"
#include "core/representability.h"
#include "physics/collision_time.h"
#include "hard_disk_input.h"
#include "physics/stepping_laws.h"

namespace collide {
namespace {

using event_time::never;

// The coming events are prefetched (prefetch_upcoming) from this many disks on: 2^16 disks
// have 8 MiB of records and calendar slots, four times what a core's L2 cache holds. Below,
// most of the state stays in the cache and the prefetching mostly costs time: per collision
// +22 % at N = 1e3, +35 % at 1e4, +10 % at 3e4, +2 % at 4.5e4, then -11 % at 6.6e4 and
// -23 % at 1e5 (area fraction 0.5, medians of 4 concurrent runs, docs/event-driven.md).
constexpr std::size_t prefetch_from_disks = std::size_t(1) << 16;

// The disks are renumbered in cell order after about this many events per disk (see renumber).
constexpr std::int64_t renumber_events_per_disk = 4;

std::string describe(double v) {
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
}

// Parses the whole text with parse (std::stod or std::stoll, which alone would accept "7x");
// nothing if it is not a number or has anything after one.
template <typename Parse>
auto parse_whole(const std::string& text, Parse parse) -> std::optional<decltype(parse(text, nullptr))> {
    std::size_t used = 0;
    try {
        const auto value = parse(text, &used);
        if (used == text.size()) return value;
    } catch (const std::exception&) {
    }
    return std::nullopt;
}

}  // namespace

std::optional<std::string> EventSolver::supports(const Scene& scene) {
    const SceneFeatures f = scene_features(scene);
    if (f.friction)
        return "friction: hard disks of the event-driven model are smooth (no tangential impulse)";
    if (f.damping)
        return "damping: a velocity-dependent drag is not free flight between events";
    if (f.gravity && f.stones)
        return "gravity with stones: a falling disk moves on a parabola relative to a fixed stone, "
               "so their collision time is a quartic root, which this solver does not compute";
    return std::nullopt;
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
    pair_events_ = wall_events_ = cell_events_ = stale_events_ = tc_elastic_ = named_events_ = 0;
    forget_names();
    virial_ = kinetic_integral_ = CompensatedSum{};
    for (auto& s : wall_impulse_) s = CompensatedSum{};

    double r_max = 0, r_sum = 0, v2_sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
        r_max = std::max(r_max, disks_[i].radius);
        r_sum += disks_[i].radius;
        v2_sum += disks_[i].vx * disks_[i].vx + disks_[i].vy * disks_[i].vy;
    }
    // Cell size: at least the largest contact distance 2 r_max, so that the 3x3 cells around a
    // disk hold every disk it can touch. In a dilute gas such cells are nearly empty and a disk
    // crosses several of them between two collisions (at area fraction 0.1, 6 of the 7 events
    // per collision are crossings). There cells holding one disk on average (side sqrt(A / N))
    // halve the events per collision and save instructions and cache misses; in a denser gas
    // they only add neighbours (+18 % instructions at area fraction 0.5). So they are used when
    // cells of 2 r_max would hold fewer than 1/4 disk on average (area fraction below ~0.2 for
    // equal disks). docs/event-driven.md, "Performance", has the measurements.
    double cell_size = n > 0 ? 2 * r_max : 1.0;
    const double area_per_disk = n > 0 ? w.width() * w.height() / double(n) : 0.0;
    const double dilute_size = std::sqrt(area_per_disk);
    // (Only in a box at least 4 such cells wide: a periodic box needs 3 cells per axis.)
    if (n > 0 && cell_size < 0.5 * dilute_size && 4 * dilute_size < std::min(w.width(), w.height()))
        cell_size = dilute_size;
    cells_.configure(w, cell_size, n);
    prefetch_second_records_ = double(n) >= double(cells_.cells_x()) * double(cells_.cells_y());
    if (scene.periodic() && (cells_.cells_x() < 3 || cells_.cells_y() < 3))
        throw std::runtime_error("event: periodic box " + describe(w.width()) + " x " + describe(w.height()) +
                                 " is narrower than 3 contact distances (2 r_max = " + describe(2 * r_max) +
                                 "); the minimum-image convention needs at least 3 cells per axis");
    for (std::uint32_t i = 0; i < n; ++i) cells_.insert(disks_, i, cells_.column_of(disks_[i].x), cells_.row_of(disks_[i].y));
    reject_overlaps();

    // Time scale: the time a typical disk needs to travel one diameter (from the rms speed or,
    // for disks starting at rest under gravity, from the fall speed over one diameter).
    const double diameter = n > 0 ? 2 * r_sum / double(n) : 1.0;
    const double speed = std::max(n > 0 ? std::sqrt(v2_sum / double(n)) : 0.0, std::sqrt(std::hypot(gx_, gy_) * diameter));
    time_scale_ = speed > 0 ? diameter / speed : 1.0;
    read_options(n);

    queue_.reset(n);
    for (std::uint32_t i = 0; i < n; ++i) queue_.payload(i).inv_mass = state_.inv_mass[i];
    // Stones never move and have no events of their own (the movers find their collisions
    // with them): their queue time stays infinite.
    for (std::uint32_t i = 0; i < n; ++i) {
        if (state_.is_stone(i)) queue_.update(i, never);
        else predict(i);
    }
    kinetic_ = kinetic_energy_now();

    original_.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) original_[i] = i;
    renumber();
}

// Memory locality. A prediction reads the record of every disk in the 3x3 cells around a disk.
// If the disks are numbered in cell order, those records lie in three runs of consecutive
// records (one per row of cells), a few cache lines each; in the scene's order, or after the
// disks have diffused, each is a separate cache miss once the records outgrow the cache (N =
// 1e5: 6.4 MB). So the disks are renumbered cell by cell at load and then every
// renumber_interval_ events. The renumbering is exact: it moves the records and the calendar
// slots with their predictions as they are (no re-prediction, no position is touched, the
// calendar keeps its buckets), keeps each cell's list in its order (so neighbours are visited
// in the same order and equal collision times resolve the same way), and the queue breaks
// ties by the original index. The events are therefore the same, bit for bit, as without
// renumbering.
void EventSolver::renumber() {
    events_since_renumber_ = 0;
    const std::size_t n = disks_.size();
    if (n == 0) return;
    cells_.cell_order(disks_, order_);  // order_[new] = old
    new_of_.resize(n);
    for (std::uint32_t k = 0; k < n; ++k) new_of_[order_[k]] = k;

    disks_scratch_.resize(n);
    for (std::size_t k = 0; k < n; ++k) disks_scratch_[k] = disks_[order_[k]];
    disks_.swap(disks_scratch_);
    cells_.relink_consecutive(disks_, n);

    auto permute = [&](auto& v, auto& scratch) {
        scratch.resize(n);
        for (std::size_t k = 0; k < n; ++k) scratch[k] = v[order_[k]];
        v.swap(scratch);
    };
    for (auto* a : state_.arrays()) permute(*a, real_scratch_);
    permute(last_collision_, real_scratch_);
    permute(original_, index_scratch_);
    queue_.renumber(order_, new_of_);
    forget_names();
    for (std::uint32_t k = 0; k < n; ++k) prediction(k).partner = new_of_[prediction(k).partner];
}

// Reads [backend.event]: tc (the TC model's duration), renumber_interval (events between
// renumberings) and prefetch ("auto": from prefetch_from_disks disks on, "on", "off"). The
// defaults of the last two suit every scene; the options are there to test the renumbering
// and the prefetching (neither may change a bit of the result) and to measure their effect.
void EventSolver::read_options(std::size_t n) {
    // TC model (S. Luding and S. McNamara, Granular Matter 1 (1998) 113): a collision that
    // follows another collision of the same disk within t_c is treated as elastic. This stops
    // the inelastic collapse of e < 1 (infinitely many collisions in finite time, McNamara &
    // Young, Phys. Fluids A 4 (1992) 496). The default t_c is 1e-4 of the time a disk needs to
    // cross one diameter: far below the mean free time of a gas (about 0.05 of it even at area
    // fraction 0.7), so mainly collisions inside a collapsing cluster are affected, yet large
    // enough that a column settling on a floor under gravity stays resolvable in double (with
    // 1e-6 the gaps fall below the rounding of the positions and the loop stalls). The counter
    // `tc_elastic` says how many collisions were made elastic.
    tc_ = 1e-4 * time_scale_;
    renumber_interval_ = renumber_events_per_disk * std::int64_t(n) + 1000;
    prefetch_ = n >= prefetch_from_disks;
    auto options = scene_.backend_options.find("event");
    if (options == scene_.backend_options.end()) return;
    const std::string where = "event: scene '" + scene_.name + "' [backend.event]";
    for (const auto& [key, value] : options->second) {
        if (key == "tc") {
            const auto tc = parse_whole(value, [](const std::string& t, std::size_t* used) { return std::stod(t, used); });
            if (!tc || !(*tc >= 0) || !std::isfinite(*tc))
                throw std::runtime_error(where + " tc = '" + value + "': expected a duration >= 0");
            tc_ = *tc;
        } else if (key == "renumber_interval") {
            const auto interval =
                parse_whole(value, [](const std::string& t, std::size_t* used) { return std::stoll(t, used); });
            if (!interval || *interval < 1)
                throw std::runtime_error(where + " renumber_interval = '" + value +
                                         "': expected a whole number of events >= 1");
            renumber_interval_ = *interval;
        } else if (key == "prefetch") {
            if (value != "auto" && value != "on" && value != "off")
                throw std::runtime_error(where + " prefetch = '" + value + "': expected \"auto\", \"on\" or \"off\"");
            if (value != "auto") prefetch_ = value == "on";
        } else {
            throw std::runtime_error(where + ": unknown key '" + key + "' (known: tc, renumber_interval, prefetch)");
        }
    }
}

// The checks are shared with the plain solver (hard_disk_input.h): both refuse the same starts.
void EventSolver::validate_input(const ParticleState<double>& s) const { check_hard_disk_input("event", scene_, s); }

void EventSolver::reject_overlaps() const { reject_overlapping_disks("event", scene_, state_); }

// ---------------------------------------------------------------------------------------
// The event loop
// ---------------------------------------------------------------------------------------

void EventSolver::advance_to(double t) {
    check_target_time("event", t, now_, scene_.run.dt, false);  // NaN would become every disk's time
    while (!queue_.empty() && queue_.top_time() <= t) {
        process_event();
        if (++events_since_renumber_ >= renumber_interval_) renumber();
    }
    now_ = t;
}

// Software pipelining over the coming events. Successive events fall at unrelated places in
// the box, so once the state outgrows the cache every event waits for a chain of cache misses:
// its calendar slot and record, then the list heads of the cells it will look at (which need
// the record's cell), then the records in those cells (which need the heads), then the next
// records in the same cells. The calendar knows the disks of the next few events
// (EventQueue::next_upcoming), so each is taken through this chain one link per event, ahead
// of time (prefetch_line, core/prefetch.h: a request the compiler cannot delete):
//   stage 0: its calendar slot and record are requested;
//   stage 1 (one event later): the list heads of its cells (cells_to_visit), and its
//            predicted partner's record and slot (for a crossing, the kept partner's record,
//            whose event counter the crossing reads);
//   stage 2: the first record of each of those cells, and the list heads around the partner;
//   stage 3: the second record of each of those cells, only where the cells hold a disk or
//            more on average (prefetch_second_records_: dilute gases, very dense or crowded
//            cells); where they hold fewer, few lists have a second record and the stage cost
//            more than it saved.
// The misses of three or four coming events then overlap with the work of the current one,
// instead of following each other. Prefetches are hints: the events, and their order, are the
// same with or without them (docs/event-driven.md, "Performance", has the measurements).
void EventSolver::prefetch_upcoming() {
    constexpr std::uint32_t none = EventQueue<Slot>::none;
    const Upcoming& third = upcoming_[2];
    if (third.disk != none && prefetch_second_records_) cells_.prefetch_records(disks_, third.cells, 1);
    const Upcoming& second = upcoming_[1];
    if (second.disk != none) {
        cells_.prefetch_records(disks_, second.cells, 0);
        const Prediction& p = prediction(second.disk);
        if (p.kind == EventKind::pair) cells_.prefetch_heads(cells_.neighbourhood_block(disks_[p.partner].links));
    }
    Upcoming& first = upcoming_[0];
    if (first.disk != none) {
        first.cells = cells_to_visit(first.disk);  // (its record arrived: its cell is known)
        cells_.prefetch_heads(first.cells);
        // A collision reads and writes its partner's record and slot; a crossing reads the
        // event counter in its kept partner's record (predict_after_crossing).
        const Prediction& p = prediction(first.disk);
        if (p.kind == EventKind::pair || (p.kind == EventKind::cell && p.pair_time != never))
            prefetch_line(&disks_[p.partner]);
        if (p.kind == EventKind::pair) {
            prefetch_line(queue_.slot_address(p.partner));
            partners_.remember(p.partner);
        }
    }
    upcoming_[2] = upcoming_[1];
    upcoming_[1] = upcoming_[0];
    upcoming_[0] = Upcoming{next_to_name(), {}};
    if (upcoming_[0].disk != none) {
        prefetch_line(&disks_[upcoming_[0].disk]);
        prefetch_line(queue_.slot_address(upcoming_[0].disk));
        names_.remember(upcoming_[0].disk);
    }
}

// The next disk for the pipeline: the look-ahead's next one that is not the partner of a
// collision already in it. About half the collisions were predicted by both disks, so each
// has a calendar entry for it; the entry served second vanishes (serving the first
// re-predicts both disks), and the pipeline already requested both
// disks' records and slots for the first. Naming the second would waste a stage and, worse,
// let the front gain on the look-ahead: the front serves more entries than there are events,
// the walk names one per event, and where the front reaches the bucket the walk is in, the
// walk leaves that bucket's remaining entries unnamed (docs/event-driven.md, "Prefetching the
// coming events", has the shares of events named with and without). A partner whose own entry
// is another, later event is passed over only if the walk reaches it while it is among the
// last few partners, which is rare (its entry lies far ahead).
std::uint32_t EventSolver::next_to_name() {
    constexpr std::uint32_t none = EventQueue<Slot>::none;
    std::uint32_t next = queue_.next_upcoming();
    for (unsigned passed = 0; next != none && passed < partners_.size && partners_.holds(next); ++passed)
        next = queue_.next_upcoming();
    return next;
}

// Forgets every disk the pipeline holds (on load and after renumbering, which renames them).
void EventSolver::forget_names() {
    for (Upcoming& u : upcoming_) u = Upcoming{};
    partners_.forget();
    names_.forget();
}

// The statistic events_named_ahead: events (of all four kinds, stale ones included) whose
// disk, or for a collision either disk, was among the last 32 disks the look-ahead named.
// Such an event found its memory requested ahead, at least partly (a disk named one event
// before has only its record in the cache); the others wait for each of their cache misses
// in turn.
void EventSolver::count_if_named(std::uint32_t i, const Prediction& p) {
    if (names_.holds(i, p.kind == EventKind::pair ? p.partner : i)) ++named_events_;
}

// The cells whose lists the coming event of disk k will read: for a cell crossing the cell it
// enters and the three beyond (crossing_block), else the 3x3 block around its cell.
CellList::Block EventSolver::cells_to_visit(std::uint32_t k) const {
    const Prediction& p = prediction(k);
    if (p.kind == EventKind::cell) return cells_.crossing_block(disks_[k].links, p.border);
    return cells_.neighbourhood_block(disks_[k].links);
}

void EventSolver::process_event() {
    if (prefetch_) prefetch_upcoming();
    const std::uint32_t i = queue_.top();
    // Event times are never earlier than the time they were predicted at (collision_time.h
    // clamps to "now"), so simulated time never runs backwards.
    now_ = std::max(now_, queue_.top_time());
    check_progress(i);
    const Prediction p = prediction(i);
    if (prefetch_) count_if_named(i, p);
    switch (p.kind) {
    case EventKind::pair:
        if (disks_[p.partner].count != p.partner_count) {
            // The partner changed course after this was predicted: the event is stale.
            ++stale_events_;
            predict(i);
            return;
        }
        collide_pair(i, p.partner);
        cells_.prefetch_neighbourhood(disks_, p.partner);  // (overlaps with predicting i)
        predict(i);  // (the disk of an event is never a stone: stones have no events)
        if (queue_.payload(p.partner).inv_mass != 0) predict(p.partner);  // (a stone does not move)
        return;
    case EventKind::wall:
        collide_wall(i, p.border);
        predict(i);
        return;
    case EventKind::cell:
        cross_cell(i, p.border);
        predict_after_crossing(i, p.border);
        return;
    case EventKind::none:
        return;  // unreachable: such a disk's time is infinite
    }
}

// An event loop that keeps finding events without simulated time moving on (inelastic
// collapse with t_c = 0, a disk at rest on a floor) must be reported, not spun forever.
void EventSolver::check_progress(std::uint32_t i) {
    const double resolution = 1e-12 * time_scale_ + 4 * std::numeric_limits<double>::epsilon() * std::fabs(now_);
    if (now_ > progress_mark_ + resolution) {
        progress_mark_ = now_;
        events_since_mark_ = 0;
        return;
    }
    // A Newton's cradle of N touching disks legitimately has N events at one instant.
    const std::int64_t limit = 10 * std::int64_t(state_.size()) + 100000;
    if (++events_since_mark_ <= limit) return;
    const Prediction& p = prediction(i);
    const std::string with = p.kind == EventKind::pair ? "particle " + std::to_string(original_[p.partner])
                             : p.kind == EventKind::wall ? "wall " + std::to_string(p.border)
                                                         : "a cell border";
    throw std::runtime_error("event: no progress in simulated time: " + std::to_string(events_since_mark_) +
                             " events at t = " + describe(now_) + " within " + describe(resolution) +
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

void EventSolver::predict(std::uint32_t i) {
    bring_to_now(i);
    Prediction p;
    earliest_pair(i, p, [&](auto&& visit) { cells_.for_each_neighbour(disks_, i, visit); });
    file_prediction(i, p);
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
        predict(i);
        return;
    }
    earliest_pair(i, p, [&](auto&& visit) { cells_.for_each_entered(disks_, i, border, visit); });
    file_prediction(i, p);
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
// counts.
template <bool MinimumImage, typename VisitCells>
void EventSolver::earliest_pair_in(std::uint32_t i, Prediction& p, VisitCells& visit_cells) const {
    const double xi = disks_[i].x, yi = disks_[i].y, vxi = disks_[i].vx, vyi = disks_[i].vy, ri = disks_[i].radius;
    const double width = scene_.world.width(), height = scene_.world.height();
    double best_dt = p.pair_time - now_;
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
        const double dt = event_time::pair_collision_time(dx, dy, vxi - vxj, vyi - vyj, ri + disks_[j].radius);
        if (dt < best_dt) {
            best_dt = dt;
            p.partner = j;
            p.partner_count = disks_[j].count;
            p.pair_time = now_ + dt;
        }
    });
}

void EventSolver::file_prediction(std::uint32_t i, Prediction& p) {
    const double border_time = now_ + earliest_border_or_wall(i, p.border, p.kind);
    double t = border_time;
    if (p.pair_time < border_time) p.kind = EventKind::pair, t = p.pair_time;
    prediction(i) = p;
    queue_.update(i, t);
}

// The earliest crossing of one of the four borders of disk i's cell, or of a wall (its time
// from now; `which` and `kind` say which one, kind none if there is none).
double EventSolver::earliest_border_or_wall(std::uint32_t i, std::uint8_t& which, EventKind& kind) const {
    if (!gravity_) return earliest_border_or_wall_straight(i, which, kind);
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
    const EventCounts counts{pair_events_, wall_events_, cell_events_, stale_events_, virial_.value(), wall_impulse_};
    const double kinetic_integral = kinetic_integral_.value() + kinetic_ * (now_ - kinetic_mark_);
    SolverStats s = event_statistics(scene_, state_.size(), now_, counts, kinetic_integral);
    s.counters["tc_elastic"] = double(tc_elastic_);
    if (prefetch_) s.counters["events_named_ahead"] = double(named_events_);
    return s;
}

std::map<std::string, std::string> EventSolver::provenance() const {
    return {{"event.tc", describe(tc_)},
            {"event.cells", std::to_string(cells_.cells_x()) + "x" + std::to_string(cells_.cells_y())},
            {"event.prefetch", prefetch_ ? (prefetch_second_records_ ? "on, second records" : "on") : "off"}};
}

}  // namespace collide
