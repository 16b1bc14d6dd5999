#include "core/thermo/pressure_record.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/statistics/batch_means.h"
#include "core/structure/orientational_order.h"
#include "core/thermo/pressure_estimator.h"

namespace collide {
namespace {

// The psi6 phases after the equilibration cut: the same fraction of the series as the cut
// takes from the pressure entries.
std::vector<double> sampled_phases(const PressureSeries& s, std::size_t cut) {
    const std::size_t n = s.beta_pressure.size(), m = s.psi6_phase.size();
    const std::size_t first = n ? std::min(m, (cut * m + n - 1) / n) : 0;
    return {s.psi6_phase.begin() + std::ptrdiff_t(first), s.psi6_phase.end()};
}

bool equal_moving_disks(const ParticleState<double>& s) {
    for (std::size_t i = 0; i < s.size(); ++i)
        if (s.is_stone(i) || s.radius[i] != s.radius[0] || s.mass[i] != s.mass[0]) return false;
    return s.size() >= 2;
}

}  // namespace

std::map<std::string, double> pressure_counters(const PressureSeries& series) {
    std::map<std::string, double> c;
    if (series.beta_pressure.empty()) return c;
    const SeriesEstimate e = estimate_stationary_mean(series.beta_pressure);
    c["beta_pressure"] = e.mean;
    c["beta_pressure_error"] = e.error;
    c["beta_pressure_correlation_time"] = e.autocorrelation_time * series.entry_length;
    c["beta_pressure_equilibration"] = double(e.equilibration_cut) * series.entry_length;
    c["beta_pressure_batches"] = double(e.batches);
    const std::size_t traversals = phase_traversals(sampled_phases(series, e.equilibration_cut));
    c["psi6_traversals"] = double(traversals);
    c["psi6_mixed"] = series.area_fraction < psi6_mixing_from_area_fraction || phase_mixed(traversals) ? 1 : 0;
    if (!series.collision_rate.empty()) {
        const SeriesEstimate rate = estimate_stationary_mean(series.collision_rate);
        c["collision_rate_mean"] = rate.mean;
        c["collision_rate_error"] = rate.error;
    }
    return c;
}

std::optional<std::string> pressure_record_refusal(const Scene& scene, const ParticleState<double>& initial) {
    if (!scene.periodic()) return "walls: the pressure record is made for a periodic box";
    if (scene.has_gravity()) return "gravity: no stationary bulk pressure";
    if (scene.physics.restitution != 1) return "restitution below 1: a cooling gas has no stationary pressure";
    if (scene.has_friction() || scene.has_damping()) return "friction or damping: energy is not conserved";
    if (!equal_moving_disks(initial)) return "not a system of equal moving disks (one radius, one mass, no stones)";
    if (!(kinetic_temperature(scene, initial).kT() > 0)) return "no thermal motion: beta P is undefined at kT = 0";
    return std::nullopt;
}

std::size_t pressure_windows_per_output(std::size_t output_intervals) {
    if (output_intervals == 0) return 1;
    return std::max<std::size_t>(1, (min_pressure_entries + output_intervals - 1) / output_intervals);
}

PressureRecorder::PressureRecorder(const Scene& scene, const ParticleState<double>& initial, double entry_length)
    : world_(scene.world), temperature_(kinetic_temperature(scene, initial)),
      area_(scene.world.width() * scene.world.height()), diameter_(2 * initial.radius.at(0)), disks_(initial.size()) {
    series_.entry_length = entry_length;
    series_.area_fraction = double(initial.size()) * std::numbers::pi * diameter_ * diameter_ / (4 * area_);
}

void PressureRecorder::sample(const SolverStats& stats, double t) {
    const auto v = stats.counters.find("virial_sum");
    if (v == stats.counters.end()) return;
    if (last_time_ && t > *last_time_) {
        const double virial_rate = (v->second - *last_virial_) / (2 * (t - *last_time_));
        const double z = compressibility_factor(virial_rate, temperature_);
        series_.beta_pressure.push_back(beta_pressure_d2(z, temperature_.moving_disks, area_, diameter_));
        const double collisions = double(stats.contacts) - *last_contacts_;
        series_.collision_rate.push_back(2 * collisions / (double(disks_) * (t - *last_time_)));
    }
    last_time_ = t, last_virial_ = v->second, last_contacts_ = double(stats.contacts);
}

void PressureRecorder::observe(const ParticleState<double>& state) {
    series_.psi6_phase.push_back(std::arg(global_psi6(world_, state)));
}

std::optional<PressureRecorder> pressure_recorder_for(const Scene& scene, const ParticleState<double>& initial,
                                                      const Solver& loaded_solver, double entry_length) {
    if (pressure_record_refusal(scene, initial)) return std::nullopt;
    if (!loaded_solver.stats().counters.count("virial_sum")) return std::nullopt;
    return PressureRecorder(scene, initial, entry_length);
}

}  // namespace collide
