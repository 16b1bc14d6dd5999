// The observed convergence order of one work-precision line and its error floor, as the
// comparison records it and the summary writes it. How the range, the order and the floor are
// found: compare/convergence_order.h (docs/validation.md, "Error against run time").
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace collide::validation {

struct ErrorFloor {
    double h = 0, error = 0;               // the last point of the asymptotic range
    double finest_h = 0, finest_error = 0; // the finest point of the line
    std::size_t excluded = 0;              // points below the range
};

struct ConvergenceOrder {
    std::optional<double> order, standard_error;
    std::size_t used = 0, points = 0;  // points in the range, points with a positive error
    double h_coarse = 0, h_fine = 0;   // the range the order was fitted on
    std::optional<ErrorFloor> floor;
    bool bending = false;              // see above: the order mixes two regimes
    std::string note;                  // why no order, when there is none
};

}  // namespace collide::validation
