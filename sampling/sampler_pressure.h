// A sampler's pressure series (one beta P d^2 per entry, an entry a fixed number of chains or
// sweeps) turned into the counters every backend records under the same names: beta_pressure,
// beta_pressure_error, beta_pressure_correlation_time and beta_pressure_equilibration (in the
// sampler's own unit: chains or sweeps), beta_pressure_batches. The mean and its error come
// from core's batch means (core/statistics/batch_means.h), as for `event`.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/statistics/batch_means.h"

namespace collide {

inline void record_beta_pressure(const std::vector<double>& series, double steps_per_entry,
                                 std::map<std::string, double>& counters) {
    if (series.size() < 2) return;
    const SeriesEstimate e = estimate_stationary_mean(series);
    counters["beta_pressure"] = e.mean;
    counters["beta_pressure_error"] = e.error;
    counters["beta_pressure_correlation_time"] = e.autocorrelation_time * steps_per_entry;
    counters["beta_pressure_equilibration"] = double(e.equilibration_cut) * steps_per_entry;
    counters["beta_pressure_batches"] = double(e.batches);
}

}  // namespace collide
