// The run schema: the one table of the metric columns of a run. Every writer and reader of
// metrics goes through it: RunWriter (one /metrics/<name> dataset per column, with the units and
// description as attributes), RunFile (which reads and checks exactly these), the case records
// of a validation suite (their [series] table), Python's Simulation.metrics() and
// collide.read_run(), and docs/output-format.md, whose "Metrics" table a test holds to this one
// (tests/core/test_run_schema.cpp). A column added here appears in all of them.
//
// Units are in the scene's own units (the scene file states what "length", "mass" and "time"
// are); "1" marks a pure number (a count or a ratio).
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string_view>

#include "core/metrics.h"

namespace collide {

struct MetricColumn {
    const char* name;         // the dataset /metrics/<name>, the key everywhere else
    const char* units;
    const char* description;
    double Metrics::*real;          // the field, for a float64 column; nullptr for a count
    std::int64_t Metrics::*count;   // the field, for an int64 column; nullptr for a float
    bool non_negative;              // by definition: a reader refuses a negative value

    bool integer() const { return count != nullptr; }
    // The column's value in one row, as a double (a count converts exactly below 2^53).
    double value(const Metrics& m) const { return real ? m.*real : double(m.*count); }
    // Sets the column's field of `m` from a double (a count is rounded to its integer).
    void assign(Metrics& m, double v) const {
        if (real) m.*real = v;
        else m.*count = std::int64_t(v);
    }
};

inline constexpr MetricColumn metric_columns[] = {
    {"time", "time", "simulation time of the output", &Metrics::time, nullptr, false},
    {"momentum_x", "mass*length/time",
     "sum of m*vx over non-stone disks (a stone has infinite mass and carries no momentum of its own)",
     &Metrics::momentum_x, nullptr, false},
    {"momentum_y", "mass*length/time", "sum of m*vy over non-stone disks", &Metrics::momentum_y, nullptr, false},
    {"kinetic_energy", "mass*length^2/time^2", "sum of m*|v|^2/2 over non-stone disks",
     &Metrics::kinetic_energy, nullptr, true},
    {"potential_energy", "mass*length^2/time^2",
     "gravitational, -sum of m*(g.x) over non-stone disks, 0 without gravity; the total energy is "
     "kinetic_energy + potential_energy",
     &Metrics::potential_energy, nullptr, false},
    {"overlapping_pairs", "1", "number of pairs with |x_i - x_j| < r_i + r_j", nullptr,
     &Metrics::overlapping_pairs, true},
    {"max_overlap", "1", "max over pairs of (r_i + r_j - d)/(r_i + r_j), 0 without overlap",
     &Metrics::max_overlap, nullptr, true},
    {"mean_overlap", "1", "mean of (r_i + r_j - d)/(r_i + r_j) over the overlapping pairs, 0 without overlap",
     &Metrics::mean_overlap, nullptr, true},
    {"max_overlap_beyond_step", "1",
     "max over overlapping pairs of (r_i + r_j - d - |v_i - v_j| h)/(r_i + r_j), h = dt/substeps, 0 where none is "
     "positive: depth that one step of the pair's relative motion cannot explain",
     &Metrics::max_overlap_beyond_step, nullptr, true},
    {"max_wall_penetration", "1",
     "max over disks of the depth beyond a reflecting wall divided by the disk's radius, 0 in a periodic box",
     &Metrics::max_wall_penetration, nullptr, true},
    {"nonfinite", "1",
     "disks with a NaN or Inf coordinate or velocity (a run stops with an error when this is not 0)", nullptr,
     &Metrics::nonfinite, true},
};

inline constexpr std::size_t metric_column_count = std::size(metric_columns);

// The column named `name`, or nullptr.
inline const MetricColumn* find_metric_column(std::string_view name) {
    for (const MetricColumn& c : metric_columns)
        if (name == c.name) return &c;
    return nullptr;
}

}  // namespace collide
