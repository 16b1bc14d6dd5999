// The small statistics toolbox of the validation suite: replicate means with standard errors,
// the two-sample z-score and Kolmogorov-Smirnov test, and least-squares slopes on log-log data.
#pragma once

#include <optional>
#include <vector>

namespace collide::validation {

struct MeanAndError {
    double mean = 0;
    double standard_error = 0;  // s / sqrt(n), s the sample standard deviation (n - 1)
    std::size_t count = 0;
};
MeanAndError mean_and_error(const std::vector<double>& samples);

// |a - b| / sqrt(se_a^2 + se_b^2): how many combined standard errors apart two means are.
// Infinity when they differ with zero error bars, 0 when equal.
double z_score(const MeanAndError& a, const MeanAndError& b);

// Two-sample Kolmogorov-Smirnov statistic D = sup |F_a - F_b| and its asymptotic p-value
// (Numerical Recipes 3rd ed., sec. 14.3.3, with the effective sample size n_a n_b/(n_a + n_b)).
struct KolmogorovSmirnov {
    double statistic = 0;
    double p_value = 1;
};
KolmogorovSmirnov ks_two_sample(std::vector<double> a, std::vector<double> b);

// Least-squares line y = intercept + slope x.
struct LineFit {
    double slope = 0, intercept = 0;
};
// Fits log(y) against log(x) over the points with x > 0 and y > 0: the observed order of
// convergence when x is the time step and y the error. Empty with fewer than `min_points`
// usable points or when all x are equal.
std::optional<LineFit> log_log_fit(const std::vector<double>& x, const std::vector<double>& y,
                                   std::size_t min_points = 3);

}  // namespace collide::validation
