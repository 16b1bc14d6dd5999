// `metropolis`: the plain local Monte Carlo sampler of hard disks (Metropolis, Rosenbluth,
// Rosenbluth, Teller & Teller, J. Chem. Phys. 21, 1087 (1953)), written for the course.
//
// A trial move picks one disk at random and displaces it by (dx, dy), each uniform in
// [-delta, delta]; the move is rejected if the disk would overlap another one or cross a wall,
// and accepted otherwise (the uniform measure: every legal configuration equally likely, so the
// Metropolis ratio is 1 or 0). A sweep is N trial moves. During the first tenth of the run
// (the tuning sweeps) delta is scaled towards the target acceptance (default 0.5) once per block
// of at least tuning_block_trials = 400 trials, by a factor clamped to [0.5, 2]; then it is
// fixed, so the sampled part obeys detailed balance.
//
// Pressure, after each sampled sweep, from the density of separations at contact, extrapolated
// by a least-squares parabola over a window of 5 % of the diameter (contact_histogram.h):
//  - periodic box: the pair virial, beta P A / N = 1 + sigma h(sigma) / (2 N), h(r) the number
//    of pairs per unit separation at r (Allen & Tildesley §2.4 and §2.6 for hard disks; the same
//    as 1 + (pi/2) rho sigma^2 g(sigma) for large N);
//  - reflecting walls: the wall contact theorem, beta P = (centres per unit distance from the
//    walls, at contact, summed over the walls) / (the box's perimeter), as `event` measures the
//    momentum given to the walls per unit wall length.
// Recorded as beta_pressure (beta P d^2, d the diameter) and its batch-means error.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <gsl/gsl_rng.h>

#include "core/solver.h"
#include "core/thermo/pressure_record.h"
#include "sampling/chain_cells.h"
#include "sampling/contact_histogram.h"

namespace collide {

inline constexpr double default_metropolis_acceptance = 0.5;
inline constexpr double contact_window_diameters = 0.05;  // the fit window, in diameters
inline constexpr int contact_bins = 10;
inline constexpr std::int64_t tuning_block_trials = 400;  // trials per adjustment of delta

class MetropolisSampler : public Solver {
public:
    explicit MetropolisSampler(const BackendOptions& options = {}) : options_(options) {}
    static std::optional<std::string> supports(const Scene& scene);

    std::string name() const override { return "metropolis"; }
    void load(const Scene& scene, const ParticleState<double>& initial) override;
    void advance_to(double t) override;
    void read_state(ParticleState<double>& out) const override;
    double time() const override { return now_; }
    SolverStats stats() const override;

    double step_size() const { return delta_; }

private:
    void sweep();
    bool try_move(std::uint32_t i);
    bool overlaps_any(std::uint32_t i, double x, double y) const;
    double separation2(std::uint32_t i, double x, double y) const;
    // Calls f(j, squared separation) for every disk j in the 3 x 3 cells around (x, y).
    template <typename F>
    void for_each_near(double x, double y, F&& f) const {
        const int cx = cells_.coordinate_of(0, x), cy = cells_.coordinate_of(1, y);
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                int col = cx + dx, row = cy + dy;
                if (!periodic_ && (col < 0 || row < 0 || col >= cells_.count(0) || row >= cells_.count(1))) continue;
                col = (col + cells_.count(0)) % cells_.count(0);
                row = (row + cells_.count(1)) % cells_.count(1);
                const int cell = cells_.index(col, row);
                const std::uint32_t* members = cells_.members(cell);
                for (int k = 0; k < cells_.occupancy(cell); ++k) f(members[k], separation2(members[k], x, y));
            }
    }
    template <typename F>
    void for_each_neighbour(std::uint32_t i, F&& f) const {
        for_each_near(pos_[0][i], pos_[1][i], [&](std::uint32_t j, double r2) { if (j != i) f(j, r2); });
    }
    void tune_step(std::int64_t accepted, std::int64_t trials);
    void record_pressure();
    double wrap(int axis, double p) const;

    BackendOptions options_;
    Scene scene_;
    ParticleState<double> start_;
    std::vector<double> pos_[2];
    std::vector<int> cell_[2];
    std::vector<int> slot_;
    ChainCells cells_;
    std::unique_ptr<gsl_rng, void (*)(gsl_rng*)> rng_{nullptr, gsl_rng_free};
    ContactHistogram histogram_{1, contact_bins};

    bool periodic_ = true;
    double radius_ = 0, sigma_ = 0, sigma2_ = 0;
    double delta_ = 0, target_acceptance_ = default_metropolis_acceptance;
    std::int64_t sweeps_total_ = 0, sweeps_done_ = 0, tuning_sweeps_ = 0;
    std::int64_t trials_ = 0, accepted_ = 0;  // in the sampled (tuned) part
    std::int64_t tuning_trials_ = 0, tuning_accepted_ = 0;  // in the current tuning block
    double now_ = 0;
    PressureSeries series_;  // beta P d^2 and arg psi6, one per sampled sweep (lengths in sweeps)
    PressureCounterCache counters_;
};

}  // namespace collide
