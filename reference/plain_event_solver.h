// The `event-plain` backend: the event-driven method for hard disks in its plainest form, one
// file (plain_event_solver.cpp) a student reads in one sitting. The `event` backend
// (event/event_solver.h) is the same method tuned for speed; the conformance tests hold the two
// against each other. docs/event-driven.md, "The plain solver", walks through it.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <queue>
#include <string>
#include <vector>

#include "core/numerics/compensated_sum.h"
#include "core/solver.h"

namespace collide {

class PlainEventSolver : public Solver {
public:
    // Empty if the plain solver covers the scene, else the reason it does not.
    static std::optional<std::string> supports(const Scene& scene);

    std::string name() const override { return "event-plain"; }
    void load(const Scene& scene, const ParticleState<double>& initial) override;
    void advance_to(double t) override;
    void read_state(ParticleState<double>& out) const override;
    double time() const override { return now_; }
    SolverStats stats() const override;
    std::map<std::string, std::string> provenance() const override;

private:
    enum class Kind : std::uint8_t { pair, wall, cell };
    // A predicted event. `side` numbers walls and cell borders: 0 x low, 1 x high, 2 y low,
    // 3 y high. The counters say which course of the disks the prediction was made for.
    struct Event {
        double time;
        Kind kind;
        std::uint8_t side;
        std::uint32_t i, j;              // the disk, and its partner (pair events)
        std::uint32_t count_i, count_j;  // their event counters when predicted
        // Earliest first; ties in a fixed order, so that every run is the same.
        bool operator>(const Event& o) const {
            return time != o.time ? time > o.time : i != o.i ? i > o.i : j > o.j;
        }
    };
    // A disk: position and velocity at its own clock t, and its cell.
    struct Disk {
        double x, y, vx, vy, t;
        double radius, mass, inv_mass;  // inverse mass 0: a stone, which never moves
        std::uint32_t count = 0;  // events of this disk so far
        std::int64_t cx = 0, cy = 0;
    };

    void make_cells();
    template <typename Visit>
    void for_each_neighbour(std::uint32_t i, Visit&& visit) const;
    void position_now(std::uint32_t i, double& x, double& y, double& vx, double& vy) const;
    void bring_to_now(std::uint32_t i);
    void predict(std::uint32_t i);
    void predict_wall_or_cell(std::uint32_t i);
    bool stale(const Event& e) const;
    void process(const Event& e);
    void collide_pair(std::uint32_t i, std::uint32_t j);
    void collide_wall(std::uint32_t i, std::uint8_t side);
    void cross_cell(std::uint32_t i, std::uint8_t side);
    void check_progress(const Event& e);

    Scene scene_;
    double gx_ = 0, gy_ = 0;
    std::vector<Disk> disks_;
    std::int64_t cells_x_ = 1, cells_y_ = 1;
    double cell_w_ = 1, cell_h_ = 1;
    std::vector<std::vector<std::uint32_t>> cells_;  // the disks in each cell, row by row
    std::priority_queue<Event, std::vector<Event>, std::greater<Event>> queue_;
    double now_ = 0;
    double progress_mark_ = 0;
    std::int64_t events_since_mark_ = 0;

    std::int64_t pair_events_ = 0, wall_events_ = 0, cell_events_ = 0, stale_events_ = 0;
    double kinetic_ = 0;               // kinetic energy: constant (e = 1) without gravity
    CompensatedSum virial_;            // sum over collisions of d.(J n)
    CompensatedSum wall_impulse_[4];   // momentum given to each wall
};

}  // namespace collide
