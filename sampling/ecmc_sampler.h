// `ecmc`: straight event-chain Monte Carlo for equal hard disks in a periodic box or a box with
// reflecting walls (E. P. Bernard, W. Krauth, D. B. Wilson, Phys. Rev. E 80, 056704 (2009)),
// written to be read in a sitting; docs/monte-carlo.md explains it and derives its pressure.
//
// One chain: pick a disk at random and move it along +x (even chains) or +y (odd chains). When
// it touches another disk, it stops there and the other one goes on ("lift"), until the moves
// of the chain add up to the chain length l. Nothing is ever rejected: the chain's last disk
// always ends somewhere legal, and the moves satisfy global balance with respect to the uniform
// measure of non-overlapping configurations (the equilibrium of hard disks at any temperature).
//
// Walls (docs/monte-carlo.md, "Walls"): a chain starts along +x or -x (+y or -y) with
// probability 1/2 each, and a disk that reaches a wall turns back and goes on with the rest of
// the chain, as if it lifted to its mirror image behind the wall (a disk one diameter further
// on). Starting in one direction only would break the balance: a wall turns chains back, so
// the two directions must be equally likely from the start. A periodic box keeps +x and +y
// (no wall turns a chain, and the chains draw exactly what they drew before walls existed).
//
// The pressure comes from the lifts (M. Michel, S. C. Kapfer, W. Krauth, J. Chem. Phys. 140,
// 054116 (2014)): with x_ij the separation of the two centres along the chain's direction at a
// lift (sqrt(sigma^2 - dy^2) at contact),
//     beta P / rho = 1 + < sum over the chain's lifts of x_ij > / l,     rho = N / A,
// where with walls a turn at a wall counts as a lift with x_ij = sigma (the mirror image), A is
// the whole box, and the x and y chains are weighted by the lengths of the walls they push on,
// so that the mean is the force on the walls per unit wall length, as `event` measures it.
// recorded as beta P d^2 (d = sigma the diameter) per entry of `chains_per_entry` chains and
// turned into beta_pressure +- beta_pressure_error by batch means, with psi6's phase sampled once
// per entry for the mixing check (core/thermo/pressure_record.h, the counters of every backend).
//
// A sampler has no time and no velocities: the scene's duration only divides the run into
// outputs (the fraction t / duration of the chains is done at output time t), and read_state
// gives zero velocities. Seeded: the chains' disks come from one GSL Mersenne Twister seeded
// from the scene's seed, so the same scene and seed give the same bits.
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

namespace collide {

// The default chain length l, in disk diameters (docs/monte-carlo.md, "Event-chain Monte Carlo").
inline constexpr double default_chain_length_diameters = 20;

class EcmcSampler : public Solver {
public:
    explicit EcmcSampler(const BackendOptions& options = {}) : options_(options) {}
    // Why ecmc cannot sample `scene` (gravity, e < 1, wall restitution < 1, ...), or nullopt.
    static std::optional<std::string> supports(const Scene& scene);

    std::string name() const override { return "ecmc"; }
    void load(const Scene& scene, const ParticleState<double>& initial) override;
    void advance_to(double t) override;
    void read_state(ParticleState<double>& out) const override;
    double time() const override { return now_; }
    SolverStats stats() const override;

    std::int64_t chains_total() const { return chains_total_; }
    std::int64_t wall_turns() const { return wall_turns_; }
    double chain_length() const { return chain_length_; }

private:
    // One chain along axis A (0: x, 1: y); Walls: the box has reflecting walls (else periodic).
    template <int A, bool Walls>
    void run_chain();
    void record_chain(int axis, double lift_sum);
    // Moves disk i from its cell to the neighbouring one along axis A, ahead in +A if
    // `forward`, else in -A (wrapping at the edge of a periodic box).
    template <int A>
    void cross_edge(std::uint32_t i, bool forward);
    void place_in_cells();

    BackendOptions options_;
    Scene scene_;
    ParticleState<double> start_;   // radii, masses (the state read_state returns around the positions)
    std::vector<double> pos_[2];    // centre coordinates x, y
    std::vector<int> cell_[2];      // each disk's cell column and row
    std::vector<int> slot_;         // its slot in that cell
    ChainCells cells_;
    std::unique_ptr<gsl_rng, void (*)(gsl_rng*)> rng_{nullptr, gsl_rng_free};

    bool walls_ = false;              // reflecting walls (else a periodic box)
    double wall_contact_[2][2] = {};  // walls: the lowest and highest centre coordinate on each axis
    double axis_weight_[2] = {1, 1};  // walls: the x and y chains' weights (see the header comment)
    double sigma_ = 0, sigma2_ = 0;   // contact distance and its square
    double chain_length_ = 0;         // l, in length units
    double density_d2_ = 0;           // rho sigma^2 = N sigma^2 / A
    std::int64_t chains_total_ = 0, chains_done_ = 0, lifts_ = 0, wall_turns_ = 0;
    std::int64_t chains_per_entry_ = 1;
    double now_ = 0;

    // The pressure series: one beta P d^2 per entry of chains_per_entry_ chains.
    double entry_sum_ = 0;
    std::int64_t entry_chains_ = 0;
    PressureSeries series_;  // beta P d^2 and arg psi6 at the end of each entry (lengths in chains)
    PressureCounterCache counters_;
};

}  // namespace collide
