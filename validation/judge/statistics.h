// The small statistics toolbox of the validation suite: replicate means with standard errors,
// replicates pooled by inverse variance,
// the two-sample z-score and Kolmogorov-Smirnov test, and least-squares slopes on log-log data.
// Means and standard deviations come from GSL (gsl_stats_*), the fits from Eigen.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace collide::validation {

struct MeanAndError {
    double mean = 0;
    double standard_error = 0;  // s / sqrt(n), s the sample standard deviation (n - 1)
    std::size_t count = 0;
};
MeanAndError mean_and_error(const std::vector<double>& samples);

// The weighted mean of replicates that each carry their own standard error (each run's batch
// means): weights 1 / se_k^2, mean = sum w_k P_k / sum w_k, se = 1 / sqrt(sum w_k); chi2 of the
// replicates about the mean (k - 1 degrees of freedom; near k - 1 when the error bars are right).
struct PooledEstimate {
    double mean = 0, standard_error = 0, chi2 = 0;
    std::size_t count = 0;
};
struct Estimate {
    double value = 0, standard_error = 0;
};
PooledEstimate pool_inverse_variance(const std::vector<Estimate>& replicates);

// The normal score with the same two-sided tail probability as Student's t with `dof` degrees
// of freedom: z = Phi^-1(1 - Q_t(|t|; dof)). A mean of n replicates over its own standard error
// is t-distributed with n - 1 dof (Student 1908), so |t| > 3 happens 5.8 % of the time at n = 4
// against 0.27 % for a normal score; judging the converted z at 3 keeps the 0.27 %.
double normal_equivalent_of_t(double t, double dof);

// The two-sided 95 % point of Student's t with `dof` degrees of freedom: the factor of the
// standard error in a 95 % bound on a mean of dof + 1 replicates that estimates its own error
// (12.71 at dof 1, 3.18 at 3, 2.36 at 7, 1.96 as dof grows). The normal 1.96 for dof <= 0 or
// infinite (an error known from elsewhere).
double student_t_95(double dof);

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

// Least-squares line y = intercept + slope x, with the standard errors of its two coefficients.
struct LineFit {
    double slope = 0, intercept = 0;
    double slope_standard_error = 0, intercept_standard_error = 0;
    bool weighted = false;  // whether the points' error bars weighted the fit
};
// Fits log(y) against log(x) over the points with x > 0 and y > 0: the observed order of
// convergence when x is the time step and y the error. Empty with fewer than `min_points`
// usable points or when all x are equal.
//
// y_error, if given (one per point), holds the points' standard errors; log(y) then has the
// standard error y_error / y. They are used only if every usable point has one above zero:
//  - FitWeights::none (the default): the ordinary least-squares line, every point alike (the
//    observed orders in docs/validation.md are these), and its standard errors propagated
//    from the error bars: c = M b with M = (A^T A)^-1 A^T, so cov(c) = M diag(sigma^2) M^T.
//  - FitWeights::error_bars: weighted least squares (weight (y / y_error)^2), with the
//    covariance (A^T W A)^-1 the error bars imply, scaled up by chi^2 / (n - 2) where the
//    points scatter about the line more than their error bars say (the Birge ratio).
// Without usable error bars the line is unweighted and its standard errors come from the
// scatter alone (residual variance chi^2 / (n - 2)); with two points they are 0 (nothing
// measures the scatter).
enum class FitWeights { none, error_bars };
std::optional<LineFit> log_log_fit(const std::vector<double>& x, const std::vector<double>& y,
                                   std::size_t min_points = 3, const std::vector<double>& y_error = {},
                                   FitWeights weights = FitWeights::none);

}  // namespace collide::validation
