// The `cpu` backend: the stepping rules of docs/stepping-rules.md (both orders, the same as
// `step`) in float, on a structure of arrays, with every per-particle phase run in parallel
// on OpenMP's persistent thread pool. docs/cpu-backend.md walks through it.
//
// Guarantees:
//   * bitwise identical states for any thread count and across reruns (each particle's
//     update reads a fixed snapshot and sums its neighbours in a fixed order);
//   * agreement with `step` to float rounding over short horizons;
//   * read_state returns particles in the scene's order, whatever the internal order is.
#pragma once

#include <cstdint>
#include <vector>

#include "cpu_cell_list.h"
#include "core/solver.h"
#include "feature_set.h"
#include "pair_list.h"
#include "phase_kernels.h"

namespace collide::cpu {

class CpuSolver : public Solver {
public:
    // options.threads (0: OpenMP's default); options.extra keys (also accepted from the
    // scene's [backend.cpu] table, which options override):
    //   "specialise" = "on" (default) | "off": loops specialised to the scene's features, or
    //                  the generic loop with every feature compiled in (for the benchmark);
    //   "sort_interval" = K >= 0: move particles into cell order at every K-th grid build
    //                  (one build per sub-step; 0: never, the contact pass then reads
    //                  through the cell list's index);
    //   "skin" = s >= 0: the contact search on a Verlet list of pairs within reach
    //                  r_i + r_j + s * 2 r_max, each pair once, rebuilt (with the grid) when
    //                  a disk has moved far enough (pair_list.h); 0: the cell path, a grid
    //                  rebuilt and every disk's 3x3 neighbourhood searched at every step.
    explicit CpuSolver(const BackendOptions& options);

    std::string name() const override { return "cpu"; }
    void load(const Scene& scene, const ParticleState<double>& initial) override;
    void advance_to(double t) override;
    void read_state(ParticleState<double>& out) const override;
    double time() const override { return double(step_count_) * scene_.run.dt; }
    SolverStats stats() const override { return stats_; }
    std::map<std::string, std::string> provenance() const override;

    int threads() const { return threads_; }
    // One full time step dt of the scene's rule.
    void step();

    // Default of "sort_interval": chosen by the `features` benchmark (docs/cpu-backend.md).
    static constexpr int kDefaultSortInterval = 1;
    // Default of "skin", in units of the largest diameter: chosen by `collide bench features`
    // (docs/cpu-backend.md).
    static constexpr double kDefaultSkin = 0.5;

private:
    void read_settings(const Scene* scene);
    void step_collide_first(float dt);
    void substep_integrate_first(float h);

    void integrate(float h);          // phases 1-3 of integrate-first
    void build_grid();                // phase 4, with the reorder by cell
    void collide();                   // phase 5: one-sided Jacobi contact pass
    void rebuild_pairs();             // the grid and the pair list, rebuilt
    void collide_pairs();             // phase 5 on the pair list, rebuilt first when stale
    void contact_phase();             // phases 4 and 5, on the pair list or the cell path
    template <typename Update>
    void update_with_corrections(Update&& update);  // the update, with the pair list's shares
    void correct();                   // phase 6 of integrate-first
    void correct_and_integrate(float dt);  // collide-first after its contact pass
    Corrections corrections() { return {dx_.data(), dy_.data(), dvx_.data(), dvy_.data()}; }

    BackendOptions options_;
    int threads_ = 1;
    bool specialise_ = true;
    int sort_interval_ = kDefaultSortInterval;
    double skin_ = kDefaultSkin;      // in units of 2 r_max

    Scene scene_;
    FeatureSet features_;
    PhaseParams params_;
    ParticleState<float> state_;              // in the current internal order
    std::vector<std::uint32_t> original_index_;  // scene index of the particle in each slot
    ParticleState<float> reordered_;          // the reorder's destination, swapped with state_
    std::vector<std::uint32_t> reordered_index_;
    bool in_cell_order_ = false;              // state_ is in the cell order of grid_
    bool equal_radii_ = false, equal_masses_ = false;  // arrays the reorder need not move
    std::vector<float> dx_, dy_, dvx_, dvy_;
    CellList grid_;
    PairList pairs_;
    std::vector<std::vector<PairShares>> shares_;  // per chunk of the list: its contacts' shares
    std::vector<std::int64_t> contacts_per_chunk_;     // per chunk: its contacts, counted
    std::int64_t step_count_ = 0;
    std::int64_t grid_builds_ = 0;
    SolverStats stats_;
};

}  // namespace collide::cpu
