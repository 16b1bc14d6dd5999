// Metrics: the physical invariants and error indicators computed from any backend's state,
// always in double with compensated sums (docs/validation.md defines each one).
#pragma once

#include <cstdint>
#include <vector>

#include "core/numerics/compensated_sum.h"
#include "core/particle_state.h"
#include "core/scene/scene.h"

namespace collide {

// m |v|^2 / 2 of one disk: the kinetic energy every sum of collide is made of (compute_metrics,
// the event solver's running energy, `collide explain`'s energy budget).
inline double disk_kinetic_energy(double mass, double vx, double vy) { return 0.5 * mass * (vx * vx + vy * vy); }

// One row of the run schema (core/io/run_schema.h names, units and describes every field).
struct Metrics {
    double time = 0;
    double momentum_x = 0, momentum_y = 0;  // sum m v over non-stone disks
    double kinetic_energy = 0;              // sum m |v|^2 / 2
    double potential_energy = 0;            // gravitational, - sum m g.x (0 without gravity)
    std::int64_t overlapping_pairs = 0;     // pairs with |x_i - x_j| < r_i + r_j
    double max_overlap = 0;                 // max over pairs of (r_i + r_j - d) / (r_i + r_j)
    double mean_overlap = 0;                // mean of the same over overlapping pairs
    // max over overlapping pairs of (r_i + r_j - d - |v_i - v_j| h)/(r_i + r_j), h = dt/substeps
    // of the scene, 0 where none is positive: the depth a pair has beyond what one step of its
    // relative motion can press it in (see compute_metrics)
    double max_overlap_beyond_step = 0;
    double max_wall_penetration = 0;        // max over disks of depth beyond a wall / radius
    std::int64_t nonfinite = 0;             // disks with a NaN or Inf coordinate or velocity

    double total_energy() const { return kinetic_energy + potential_energy; }
};

Metrics compute_metrics(const Scene& scene, const ParticleState<double>& state, double time);

// The per-disk part of compute_metrics alone, O(N) and without a pair search: time, momentum,
// energies, wall penetration, non-finite disks; the overlap fields stay 0. For callers
// that search the pairs themselves (the viewer lists them for its marks).
Metrics compute_disk_metrics(const Scene& scene, const ParticleState<double>& state, double time);

// The overlap fields of Metrics (overlapping_pairs, max_overlap, mean_overlap,
// max_overlap_beyond_step) from the overlapping pairs of one state, added one at a time: the one
// place they are computed, for compute_metrics' pair search and the viewer's (view/overlap_pairs.h).
class OverlapTally {
public:
    // `scene` gives the step h = dt / substeps; `state` the pairs' radii and velocities and must
    // outlive the tally.
    OverlapTally(const Scene& scene, const ParticleState<double>& state);
    // Disks i and j overlap by the relative depth (r_i + r_j - d)/(r_i + r_j).
    void add(std::size_t i, std::size_t j, double depth);
    void write_into(Metrics& m) const;

private:
    const ParticleState<double>& state_;
    double step_;
    std::int64_t pairs_ = 0;
    double max_depth_ = 0, max_beyond_step_ = 0;
    CompensatedSum depth_sum_;
};

// Relative overlap depth (r_i + r_j - d)/(r_i + r_j) of every overlapping pair, for histograms.
std::vector<double> overlap_depths(const Scene& scene, const ParticleState<double>& state);

}  // namespace collide
