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
//
// This file and event_solver.cpp are the algorithm. The speed layer is in files of its own,
// each saying what it buys: the compact records (event_records.h), the event calendar
// (event_queue.h), the allocation on huge pages (event_memory.h), the prefetch pipeline
// (prefetch_pipeline.h) and the renumbering in cell order (cell_order_renumbering.h). The
// same method without any of them is `event-plain` (reference/plain_event_solver.cpp).
//
// An experimental second design replaces the cell crossings by neighbour lists with shells
// (neighbour_shells.h; Smallenburg, Eur. Phys. J. E 45, 22 (2022)): [backend.event] shell > 0.
// Its events are collisions, walls and shell exits. It is off by default: in two dimensions
// it was measured slower than the cells (docs/event-driven.md, "Neighbour lists with shells").
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cell_order_renumbering.h"
#include "core/numerics/compensated_sum.h"
#include "core/solver.h"
#include "event_cell_list.h"
#include "event_memory.h"
#include "event_queue.h"
#include "event_records.h"
#include "neighbour_shells.h"
#include "physics/collision_time.h"
#include "prefetch_pipeline.h"

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
    // The records (event_records.h): one 64-byte record per disk, and in each disk's calendar
    // slot its prediction and inverse mass.
    using Disk = EventDisk;
    using Prediction = EventPrediction;
    using Slot = EventSlot;
    using Vector2d = Eigen::Vector2d;
    Prediction& prediction(std::uint32_t i) { return queue_.payload(i).prediction; }
    const Prediction& prediction(std::uint32_t i) const { return queue_.payload(i).prediction; }

    void validate_input(const ParticleState<double>& initial) const;
    void reject_overlaps() const;
    // The event loop and what it calls on every event are compiled once per neighbour design
    // (Shells: neighbour_shells.h; otherwise the cells), chosen once per advance: the cells'
    // loop carries no trace of the shells (measured: with runtime tests it cost 5 to 10 % per
    // collision, bench/journal.md).
    template <bool Shells>
    void run_events(double t);
    template <bool Shells>
    void process_event();
    // The speed layer, called from the event loop (each in a file of its own).
    // Requests the memory of the coming events ahead of time (prefetch_pipeline.h).
    template <bool Shells>
    void prefetch_coming_events();
    // Renumbers the disks in cell order when due (cell_order_renumbering.h).
    void renumber_if_due();
    void renumber();
    void check_progress(std::uint32_t i);
    void count_event_without_progress(std::uint32_t i, double resolution);

    // Free flight of disk i from its own clock to `now_` (written back: the clock moves).
    void bring_to_now(std::uint32_t i);
    // Position/velocity disk j would have at `now_`, without touching its state. (Always
    // inlined: it runs for every neighbour of every prediction, and with the shells' loop
    // compiled beside the cells' GCC stopped inlining it, which cost the cells' loop 4 to 8 %.)
    [[gnu::always_inline]] void position_now(std::uint32_t j, double& x, double& y, double& vx, double& vy) const {
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
    template <bool Shells>
    void predict(std::uint32_t i);
    void predict_any(std::uint32_t i) { shells_on() ? predict<true>(i) : predict<false>(i); }
    // The same after disk i crossed `border` into a new cell without changing course.
    void predict_after_crossing(std::uint32_t i, std::uint32_t border);
    // Lowers p's pair collision to the earliest one with a disk j that visit_cells(visit) visits.
    template <typename VisitCells>
    void earliest_pair(std::uint32_t i, Prediction& p, VisitCells&& visit_cells) const;
    // The same, MinimumImage saying whether the neighbours visited may lie across a periodic side.
    template <bool MinimumImage, typename VisitCells>
    void earliest_pair_in(std::uint32_t i, Prediction& p, VisitCells& visit_cells) const;
    // Adds disk i's earliest wall or border event to p and files the earlier event in the queue.
    template <bool Shells>
    void file_prediction(std::uint32_t i, Prediction& p);
    // (earliest_border_or_wall under gravity, _straight without.)
    double earliest_border_or_wall(std::uint32_t i, std::uint8_t& which, EventKind& kind) const;
    double earliest_border_or_wall_straight(std::uint32_t i, std::uint8_t& which, EventKind& kind) const;
    // The neighbour-list design (neighbour_shells.h): on when shell_ > 0.
    bool shells_on() const { return shell_ > 0; }
    // The shell width to use (0: the cell-list design) for the option's fraction of 2 r_max.
    double choose_shell(double fraction, double r_max) const;
    // Disk i's earliest wall collision or shell exit (time from now; kind none if neither).
    double earliest_wall_or_exit(std::uint32_t i, std::uint8_t& which, EventKind& kind) const;
    // Makes disk i's current position its shell centre and lists the disks whose centres lie
    // within the contact distance plus 2 shell_ (adding i to their lists too if both_ways).
    void build_shell(std::uint32_t i, bool both_ways);
    void exit_shell(std::uint32_t i);

    void collide_pair(std::uint32_t i, std::uint32_t j);
    void collide_wall(std::uint32_t i, std::uint32_t wall);
    void cross_cell(std::uint32_t i, std::uint32_t border);
    // Restitution for a collision now, after the TC model (Luding & McNamara 1998).
    double restitution_now(double e, std::uint32_t i, std::uint32_t j);
    std::optional<double> read_options(double r_max);
    double kinetic_energy_now() const;

    // Disks are numbered internally in cell order, not in the scene's order: every array below
    // indexed by disk uses the internal number. original_[i] is disk i's index in the scene.
    // renumbering_ restores the order now and then, after the disks have diffused, so that
    // disks near each other in space stay near each other in memory.
    Scene scene_;
    ParticleState<double> state_;      // masses and stone flags; positions only on load
    std::vector<std::uint32_t> original_;
    EventArray<Disk> disks_;  // (huge pages: read at random places, event_memory.h)
    std::vector<double> last_collision_;  // TC model: each disk's last collision (kept if inelastic_)
    bool inelastic_ = false;               // pair or wall restitution below 1
    CellList cells_;  // (in the neighbour-list design, a grid of the shell centres)
    EventQueue<Slot> queue_;
    CellOrderRenumbering renumbering_;
    PrefetchPipeline prefetch_;
    static_assert(EventQueue<Slot>::slot_bytes == 64, "a disk's calendar slot should fill one cache line");
    double gx_ = 0, gy_ = 0;
    bool gravity_ = false;             // gx_ or gy_ non-zero
    double now_ = 0;
    double tc_ = 0;
    std::string prefetch_choice_ = "auto";  // [backend.event] prefetch: "auto", "on" or "off"
    double time_scale_ = 1;            // typical time between collisions, for the guards

    // Progress guard: events since simulated time last advanced noticeably.
    double progress_mark_ = 0;
    std::int64_t events_since_mark_ = 0;

    // Statistics.
    std::int64_t pair_events_ = 0, wall_events_ = 0, cell_events_ = 0, shell_events_ = 0, stale_events_ = 0;
    std::int64_t tc_elastic_ = 0;
    CompensatedSum virial_;            // sum over collisions of |d| J (pair impulse J)
    CompensatedSum wall_impulse_[4];   // momentum transferred to each wall
    CompensatedSum kinetic_integral_;  // integral of K dt up to kinetic_mark_
    double kinetic_ = 0, kinetic_mark_ = 0;

    // The neighbour-list design, last: the members the cells' event loop reads every event stay
    // together above (placed between the cells and the queue these cost the cells' loop 5 to
    // 10 % per collision, bench/journal.md).
    NeighbourShells shells_;
    double shell_ = 0;        // shell width delta (0: the cell-list design)
    double shell_slack_ = 0;  // added to the list cutoff against round-off (build_shell)
    std::vector<std::uint32_t> old_neighbours_;  // (exit_shell's scratch space)
};

}  // namespace collide
