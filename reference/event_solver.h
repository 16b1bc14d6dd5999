// The `event` backend: exact event-driven dynamics of hard disks (EDMD), double precision,
// serial. The ground truth the other backends are measured against. docs/event-driven.md is
// the walkthrough of this file and event_solver.cpp.
//
// Between events every disk flies freely (a straight line, a parabola under gravity). The
// solver predicts, for every disk, its earliest event: a collision with a neighbour
// (collision_time.h), a wall, or the crossing of a cell border (event_cell_list.h). It jumps to
// the earliest event of all (event_queue.h), applies it, and re-predicts only the disks whose
// course changed. Each disk carries its own clock (the time its position was last written),
// so an event touches only the disks involved, whatever N is.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "event_cell_list.h"
#include "physics/collision_time.h"
#include "core/compensated_sum.h"
#include "core/huge_page_allocator.h"
#include "core/solver.h"
#include "event_queue.h"

namespace collide {

class EventSolver : public Solver {
public:
    // Empty if the event-driven model covers the scene, else the reason it does not.
    static std::optional<std::string> supports(const Scene& scene);

    std::string name() const override { return "event"; }
    void load(const Scene& scene, const ParticleState<double>& initial) override;
    void advance_to(double t) override;
    void read_state(ParticleState<double>& out) const override;
    double time() const override { return now_; }
    SolverStats stats() const override;
    std::map<std::string, std::string> provenance() const override;

    // The collapse-guard duration t_c of the TC model in use (see read_options in the .cpp).
    double tc() const { return tc_; }

private:
    enum class EventKind : std::uint8_t { none, pair, wall, cell };
    // Walls and cell borders are numbered: 0 = x low, 1 = x high, 2 = y low, 3 = y high.
    // A disk's prediction keeps its earliest pair collision apart from its earliest wall or
    // border event: a cell crossing does not change the disk's course, so the pair collision
    // found before stays valid and only the newly entered cells need a look (predict_after_crossing).
    struct Prediction {
        double pair_time = event_time::never;  // the earliest pair collision: its (absolute) time,
        std::uint32_t partner = 0;             // the other disk,
        std::uint32_t partner_count = 0;       // and that disk's event counter when predicted
        EventKind kind = EventKind::none;      // the earlier of the pair collision and the event below
        std::uint8_t border = 0;               // the wall/border number (kind wall or cell)
    };
    // What the calendar slot of a disk carries (event_queue.h): its prediction and its inverse
    // mass, both read at each of its events, on the slot's cache line. A stone has inverse
    // mass 0 (core/particle_state.h).
    struct Slot {
        Prediction prediction;
        double inv_mass = 0;
    };
    Prediction& prediction(std::uint32_t i) { return queue_.payload(i).prediction; }
    const Prediction& prediction(std::uint32_t i) const { return queue_.payload(i).prediction; }

    void validate_input(const ParticleState<double>& initial) const;
    void reject_overlaps() const;
    void process_event();
    // Requests the memory of the coming events ahead of time (see the .cpp).
    void prefetch_upcoming();
    // The cells whose lists the coming event of disk k will read (for prefetching).
    CellList::Block cells_to_visit(std::uint32_t k) const;
    // Renumbers the disks cell by cell (see renumber_interval_ and docs/event-driven.md).
    void renumber();
    void check_progress(std::uint32_t i);

    // Free flight of disk i from its own clock to `now_` (written back: the clock moves).
    void bring_to_now(std::uint32_t i);
    // Position/velocity disk j would have at `now_`, without touching its state.
    void position_now(std::uint32_t j, double& x, double& y, double& vx, double& vy) const {
        // Stones have zero velocity and scenes with stones have no gravity: no special case.
        const Disk& f = disks_[j];
        const double dt = now_ - f.t;
        if (!gravity_) {
            x = f.x + f.vx * dt, y = f.y + f.vy * dt, vx = f.vx, vy = f.vy;
            return;
        }
        x = f.x + (f.vx + 0.5 * gx_ * dt) * dt;
        y = f.y + (f.vy + 0.5 * gy_ * dt) * dt;
        vx = f.vx + gx_ * dt;
        vy = f.vy + gy_ * dt;
    }
    // Re-predicts disk i's earliest event from `now_` and files it in the queue (i is not a stone).
    void predict(std::uint32_t i);
    // The same after disk i crossed `border` into a new cell without changing course.
    void predict_after_crossing(std::uint32_t i, std::uint32_t border);
    // Lowers p's pair collision to the earliest one with a disk j that visit_cells(visit) visits.
    template <typename VisitCells>
    void earliest_pair(std::uint32_t i, Prediction& p, VisitCells&& visit_cells) const;
    // The same, MinimumImage saying whether the neighbours visited may lie across a periodic side.
    template <bool MinimumImage, typename VisitCells>
    void earliest_pair_in(std::uint32_t i, Prediction& p, VisitCells& visit_cells) const;
    // Adds disk i's earliest wall or border event to p and files the earlier event in the queue.
    void file_prediction(std::uint32_t i, Prediction& p);
    double earliest_border_or_wall(std::uint32_t i, std::uint8_t& which, EventKind& kind) const;
    double earliest_border_or_wall_straight(std::uint32_t i, std::uint8_t& which, EventKind& kind) const;

    void collide_pair(std::uint32_t i, std::uint32_t j);
    void collide_wall(std::uint32_t i, std::uint32_t wall);
    void cross_cell(std::uint32_t i, std::uint32_t border);
    // Restitution for a collision now, after the TC model (Luding & McNamara 1998).
    double restitution_now(double e, std::uint32_t i, std::uint32_t j);
    void read_options(std::size_t n);
    double kinetic_energy_now() const;

    // One disk: its free flight (position and velocity valid at the disk's own clock t), its
    // event counter and its place in the cell list, in one 64-byte record. Predicting reads
    // all of these for every neighbour, so a neighbour costs one cache line.
    struct alignas(64) Disk {
        double x, y, vx, vy;
        double t;             // the disk's clock
        double radius;
        std::uint32_t count;  // event counter: bumped whenever the disk changes course
        CellLinks links;      // cell and neighbours in the cell (event_cell_list.h)
    };
    static_assert(sizeof(Disk) == 64);
    // A disk's position and velocity as the vectors of the equations (views, no copies: x, y
    // and vx, vy are adjacent). Eigen::Vector2d arithmetic rounds each component exactly as
    // the scalar lines it replaces (one operation per component, in the same order, no FMA),
    // so the trajectories are the same, bit for bit.
    static_assert(offsetof(Disk, y) == offsetof(Disk, x) + sizeof(double) &&
                  offsetof(Disk, vy) == offsetof(Disk, vx) + sizeof(double));
    using Vector2d = Eigen::Vector2d;
    static Eigen::Map<Vector2d> position_of(Disk& d) { return Eigen::Map<Vector2d>(&d.x); }
    static Eigen::Map<const Vector2d> position_of(const Disk& d) { return Eigen::Map<const Vector2d>(&d.x); }
    static Eigen::Map<Vector2d> velocity_of(Disk& d) { return Eigen::Map<Vector2d>(&d.vx); }
    static Eigen::Map<const Vector2d> velocity_of(const Disk& d) { return Eigen::Map<const Vector2d>(&d.vx); }

    // Disks are numbered internally in cell order, not in the scene's order: every array below
    // indexed by disk uses the internal number. original_[i] is disk i's index in the scene.
    // renumber() restores the order every renumber_interval_ events, after the disks have
    // diffused, so that disks near each other in space stay near each other in memory.
    Scene scene_;
    ParticleState<double> state_;      // masses and stone flags; positions only on load
    std::vector<std::uint32_t> original_;
    std::int64_t renumber_interval_ = 0;
    std::int64_t events_since_renumber_ = 0;
    // Scratch space for renumber(), kept so that no renumbering allocates (and clears) memory.
    HugePageVector<Disk> disks_scratch_;
    std::vector<double> real_scratch_;
    std::vector<std::uint32_t> index_scratch_;
    std::vector<std::uint32_t> order_;   // renumber(): order_[new] = old
    std::vector<std::uint32_t> new_of_;  // and new_of_[old] = new (both kept: no allocation per renumbering)
    HugePageVector<Disk> disks_;  // (huge pages: read at random places, see the allocator)
    std::vector<double> last_collision_;  // TC model: each disk's last collision (kept if inelastic_)
    bool inelastic_ = false;               // pair or wall restitution below 1
    CellList cells_;
    EventQueue<Slot> queue_;
    // prefetch_upcoming(): whether it runs (large N only), and the disks of coming events at
    // stages 1, 2 and 3 of their prefetch chain (EventQueue::none if none).
    bool prefetch_ = false;
    bool prefetch_second_records_ = false;  // stage 3 (where cells hold a disk or more on average)
    struct Upcoming {
        std::uint32_t disk = EventQueue<Slot>::none;
        CellList::Block cells;  // cells_to_visit(disk), from stage 1 on
    };
    Upcoming upcoming_[3];
    // The last K disks put into it, oldest overwritten first (for the two lists below).
    template <unsigned K>
    struct RecentDisks {
        static constexpr unsigned size = K;
        std::uint32_t disk[K];
        unsigned next = 0;  // the slot written next (always below K)
        void remember(std::uint32_t k) {
            disk[next] = k;
            next = next + 1 == K ? 0 : next + 1;
        }
        // Whether it holds a or b. Every slot is compared, without an early exit, so that the
        // compiler makes it a few vector compares (it runs at every event).
        bool holds(std::uint32_t a, std::uint32_t b) const {
            std::uint32_t found = 0;
            for (std::uint32_t d : disk) found |= std::uint32_t(d == a) | std::uint32_t(d == b);
            return found != 0;
        }
        bool holds(std::uint32_t a) const { return holds(a, a); }
        void forget() { std::fill(disk, disk + K, EventQueue<Slot>::none); }
    };
    // The partners of the last few collisions taken into the pipeline, which the look-ahead
    // passes over (see next_to_name).
    RecentDisks<4> partners_;
    // The disks the look-ahead named last, to count the events it named ahead
    // (events_named_ahead, see count_if_named).
    RecentDisks<32> names_;
    std::int64_t named_events_ = 0;
    std::uint32_t next_to_name();
    void forget_names();
    void count_if_named(std::uint32_t i, const Prediction& p);
    static_assert(EventQueue<Slot>::slot_bytes == 64, "a disk's calendar slot should fill one cache line");
    double gx_ = 0, gy_ = 0;
    bool gravity_ = false;             // gx_ or gy_ non-zero
    double now_ = 0;
    double tc_ = 0;
    double time_scale_ = 1;            // typical time between collisions, for the guards

    // Progress guard: events since simulated time last advanced noticeably.
    double progress_mark_ = 0;
    std::int64_t events_since_mark_ = 0;

    // Statistics.
    std::int64_t pair_events_ = 0, wall_events_ = 0, cell_events_ = 0, stale_events_ = 0;
    std::int64_t tc_elastic_ = 0;
    CompensatedSum virial_;            // sum over collisions of |d| J (pair impulse J)
    CompensatedSum wall_impulse_[4];   // momentum transferred to each wall
    CompensatedSum kinetic_integral_;  // integral of K dt up to kinetic_mark_
    double kinetic_ = 0, kinetic_mark_ = 0;
};

}  // namespace collide
