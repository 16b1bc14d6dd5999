// The pressure a run records in its statistics (`collide run`'s /stats, a validation case's
// counters): beta P d^2 with its batch-means error, correlation time, equilibration cut, and the
// psi6 mixing check. docs/validation.md, "Error bars and mixing", explains every counter.
//
// Two parts:
//  - pressure_counters: any series of beta P d^2 (one entry per window of a run: time for the
//    event-driven solvers, chains or sweeps for samplers) and psi6 phases -> the counters
//    beta_pressure, beta_pressure_error, beta_pressure_correlation_time,
//    beta_pressure_equilibration, beta_pressure_batches, psi6_traversals, psi6_mixed.
//  - PressureRecorder: the series of an event-driven run (a solver that reports the collision
//    virial `virial_sum`), fed by run_scene.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/particle_state.h"
#include "core/scene/scene.h"
#include "core/solver.h"
#include "core/thermo/kinetic_temperature.h"

namespace collide {

// The density from which the psi6 mixing check applies (below it the fluid's orientation
// decorrelates within a few collisions per disk; Li et al. 2022 check the dense points).
constexpr double psi6_mixing_from_area_fraction = 0.69;

struct PressureSeries {
    std::vector<double> beta_pressure;  // beta P d^2 per window, in run order
    double entry_length = 1;            // a window's length: time, or chains / sweeps
    // arg psi6 (-pi, pi], sampled evenly over the same run as beta_pressure (any count).
    std::vector<double> psi6_phase;
    double area_fraction = 0;           // eta of the scene: the mixing check applies from 0.69
    // Collisions per disk per unit time in the same windows (event-driven runs only; empty for
    // samplers): 2 Delta C / (N Delta t), each collision involving two disks.
    std::vector<double> collision_rate;
};

// The counters of the series (see above). Lengths (correlation time, equilibration) are in
// the unit of entry_length. psi6_traversals counts over the sampled part (after the cut);
// psi6_mixed is 1 when traversals >= 3, and 1 below eta 0.69 where the check does not apply.
// With a collision-rate series, also collision_rate_mean and collision_rate_error (batch means,
// the same estimator and its own equilibration cut).
std::map<std::string, double> pressure_counters(const PressureSeries& series);

// pressure_counters of a series that only grows, computed again only when it has grown: a
// sampler's stats() is asked for them at every output, and by the viewer at every frame.
class PressureCounterCache {
public:
    const std::map<std::string, double>& counters(const PressureSeries& series) const {
        if (series.beta_pressure.size() != entries_) {
            counters_ = pressure_counters(series);
            entries_ = series.beta_pressure.size();
        }
        return counters_;
    }

private:
    mutable std::size_t entries_ = 0;
    mutable std::map<std::string, double> counters_;
};

// Why a scene gets no pressure record, or nullopt when it gets one: a periodic box (walls
// make the pressure depend on the wall, and the virial has wall terms), no gravity, e = 1 (a
// cooling gas has no stationary pressure), no friction or damping, equal moving disks (the
// finite-N estimator and beta P d^2 with one d are stated for them), no stones, and a
// temperature above 0 (a gas at rest in its centre-of-mass frame has no beta P).
std::optional<std::string> pressure_record_refusal(const Scene& scene, const ParticleState<double>& initial);

// Windows of one entry each into which an event-driven run cuts every output interval: enough
// that the run has at least min_pressure_entries entries (20 batches of 50), one where the
// output interval already gives them.
constexpr std::size_t min_pressure_entries = 1000;
std::size_t pressure_windows_per_output(std::size_t output_intervals);

// Collects the series of an event-driven run. beta P d^2 per window from the increment of the
// collision virial V (SolverStats counter virial_sum, sum over collisions of d.(J n)):
// W = Delta V / (2 Delta t), Z by pressure_estimator.h with the temperature of the initial
// state (e = 1: conserved), the collision rate per disk per window from the increment of the
// collision count (SolverStats contacts), and psi6's phase at every output.
class PressureRecorder {
public:
    PressureRecorder(const Scene& scene, const ParticleState<double>& initial, double entry_length);
    // The solver's statistics at time t (t increasing; the first call starts the series).
    void sample(const SolverStats& stats, double t);
    // The configuration at an output time.
    void observe(const ParticleState<double>& state);
    std::map<std::string, double> counters() const { return pressure_counters(series_); }
    const PressureSeries& series() const { return series_; }

private:
    World world_;
    KineticTemperature temperature_;
    double area_ = 0, diameter_ = 0;
    std::size_t disks_ = 0;
    std::optional<double> last_time_, last_virial_, last_contacts_;
    PressureSeries series_;
};

// A recorder for this run, or nullopt when the scene does not qualify
// (pressure_record_refusal) or the solver reports no collision virial after loading.
std::optional<PressureRecorder> pressure_recorder_for(const Scene& scene, const ParticleState<double>& initial,
                                                      const Solver& loaded_solver, double entry_length);

}  // namespace collide
