// The observed convergence order of one work-precision line, on its asymptotic range: the
// definition the summary (summary.json) records and the report only draws (docs/validation.md,
// "Error against run time").
//
// Sorted from coarse to fine, the asymptotic range ends where the error stops falling: the first
// point after which every local slope log(e_i-1 / e_i) / log(h_i-1 / h_i) is below
// flat_local_order (0.3). For points with error bars (statistical observables) a step counts as
// flat only where the finer point lies floor_standard_errors (2) combined standard errors above
// the order-0.3 descent from the coarser one: noise the descent explains is no floor. The points
// below the range are the floor. The order is the ordinary least-squares slope of log e against
// log h on the range, with its standard error propagated from the points' error bars
// (statistics.h, log_log_fit).
//
// A floor can also hide inside the range: a step whose local order is below flat_local_order,
// followed by a fall that keeps it in the range (a float rule's rounding stalling the error at
// one step, phase noise at another). `bending` says so: the order then mixes the method with
// what stalled it, and the report flags it as floor-contaminated.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "validation/record/observed_order.h"

namespace collide::validation {

struct ErrorPoint {
    double h = 0;               // the rule's effective step, dt / substeps
    double error = 0;
    double standard_error = 0;  // 0 where unknown
};

constexpr double flat_local_order = 0.3;
constexpr double floor_standard_errors = 2.0;
constexpr std::size_t order_min_points = 3;

ConvergenceOrder asymptotic_order(std::vector<ErrorPoint> points);

}  // namespace collide::validation
