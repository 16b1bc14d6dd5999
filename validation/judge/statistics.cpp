#include "validation/judge/statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_statistics_double.h>

namespace collide::validation {

PooledEstimate pool_inverse_variance(const std::vector<Estimate>& replicates) {
    PooledEstimate p;
    double weights = 0, weighted = 0;
    for (const Estimate& e : replicates) {
        const double w = 1 / (e.standard_error * e.standard_error);
        weights += w, weighted += w * e.value;
    }
    p.count = replicates.size();
    if (p.count == 0 || !(weights > 0) || !std::isfinite(weights)) {
        p.mean = p.standard_error = std::nan("");
        return p;
    }
    p.mean = weighted / weights;
    p.standard_error = 1 / std::sqrt(weights);
    for (const Estimate& e : replicates) p.chi2 += std::pow((e.value - p.mean) / e.standard_error, 2);
    return p;
}


MeanAndError mean_and_error(const std::vector<double>& samples) {
    MeanAndError r;
    r.count = samples.size();
    if (samples.empty()) return r;
    r.mean = gsl_stats_mean(samples.data(), 1, samples.size());
    if (r.count < 2) return r;
    // gsl_stats_sd_m: the sample standard deviation s (divisor n - 1) about the mean just found.
    r.standard_error = gsl_stats_sd_m(samples.data(), 1, samples.size(), r.mean) / std::sqrt(double(r.count));
    return r;
}

double normal_equivalent_of_t(double t, double dof) {
    if (!std::isfinite(t) || !(dof > 0)) return std::fabs(t);
    // The upper tail Q_t, kept above the smallest double so that Phi^-1 stays finite (|z| ~ 37).
    const double q = std::max(gsl_cdf_tdist_Q(std::fabs(t), dof), std::numeric_limits<double>::min());
    return gsl_cdf_ugaussian_Qinv(q);
}

double student_t_95(double dof) {
    if (!(dof > 0) || !std::isfinite(dof)) return gsl_cdf_ugaussian_Qinv(0.025);
    return gsl_cdf_tdist_Qinv(0.025, dof);
}

double z_score(const MeanAndError& a, const MeanAndError& b) {
    const double difference = std::fabs(a.mean - b.mean);
    const double error = std::hypot(a.standard_error, b.standard_error);
    if (difference == 0) return 0;
    return error > 0 ? difference / error : std::numeric_limits<double>::infinity();
}

namespace {
// Q_KS(lambda) = 2 sum_{j>=1} (-1)^{j-1} exp(-2 j^2 lambda^2), the Kolmogorov distribution's tail.
// (Hand-written: neither GSL nor Eigen offers the Kolmogorov distribution.)
double kolmogorov_tail(double lambda) {
    if (lambda < 0.3) return 1.0;  // the series converges slowly here and the tail is ~1
    double sum = 0, sign = 1;
    for (int j = 1; j <= 100; ++j) {
        const double term = sign * std::exp(-2.0 * j * j * lambda * lambda);
        sum += term;
        if (std::fabs(term) < 1e-12 * std::fabs(sum)) break;
        sign = -sign;
    }
    return std::clamp(2 * sum, 0.0, 1.0);
}
}  // namespace

KolmogorovSmirnov ks_two_sample(std::vector<double> a, std::vector<double> b) {
    KolmogorovSmirnov r;
    if (a.empty() || b.empty()) return r;
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    std::size_t i = 0, j = 0;
    const double na = double(a.size()), nb = double(b.size());
    while (i < a.size() && j < b.size()) {
        const double x = std::min(a[i], b[j]);
        while (i < a.size() && a[i] <= x) ++i;
        while (j < b.size() && b[j] <= x) ++j;
        r.statistic = std::max(r.statistic, std::fabs(double(i) / na - double(j) / nb));
    }
    const double n = std::sqrt(na * nb / (na + nb));
    r.p_value = kolmogorov_tail((n + 0.12 + 0.11 / n) * r.statistic);
    return r;
}

std::optional<LineFit> log_log_fit(const std::vector<double>& x, const std::vector<double>& y,
                                   std::size_t min_points, const std::vector<double>& y_error, FitWeights weights) {
    std::vector<double> lx, ly, sigma;  // sigma: the standard error of log(y), where known
    bool have_errors = y_error.size() == y.size();
    for (std::size_t k = 0; k < std::min(x.size(), y.size()); ++k)
        if (x[k] > 0 && y[k] > 0 && std::isfinite(x[k]) && std::isfinite(y[k])) {
            lx.push_back(std::log(x[k]));
            ly.push_back(std::log(y[k]));
            if (have_errors) {
                const double s = y_error[k] / y[k];
                if (s > 0 && std::isfinite(s)) sigma.push_back(s);
                else have_errors = false;  // one point without an error bar: none are used
            }
        }
    const std::size_t n = lx.size();
    if (n < std::max<std::size_t>(2, min_points)) return std::nullopt;
    if (std::all_of(lx.begin(), lx.end(), [&](double v) { return v == lx[0]; })) return std::nullopt;
    const bool weighted = have_errors && weights == FitWeights::error_bars;

    // Least squares for log y = intercept + slope log x: minimise |W (A c - b)|^2 with
    // A = [1, log x], b = log y, W = diag(1 / sigma) when weighted, else the identity.
    Eigen::MatrixXd a(n, 2);
    Eigen::VectorXd b(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double w = weighted ? 1 / sigma[k] : 1.0;
        a(Eigen::Index(k), 0) = w;
        a(Eigen::Index(k), 1) = w * lx[k];
        b(Eigen::Index(k)) = w * ly[k];
    }
    // Householder QR with column pivoting, not the normal equations, which square the
    // condition number of A (the log x of close steps make nearly parallel columns).
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
    if (qr.rank() < 2) return std::nullopt;
    const Eigen::Vector2d c = qr.solve(b);
    const Eigen::Matrix2d inverse = (a.transpose() * a).inverse();
    const double chi2 = (a * c - b).squaredNorm(), dof = double(n) - 2;
    Eigen::Matrix2d covariance;  // of (intercept, slope)
    if (weighted) {
        covariance = inverse * (dof > 0 ? std::max(1.0, chi2 / dof) : 1.0);
    } else if (have_errors) {
        const Eigen::MatrixXd m = inverse * a.transpose();  // c = M b
        const Eigen::VectorXd variance = Eigen::Map<const Eigen::VectorXd>(sigma.data(), Eigen::Index(n)).array().square();
        covariance = m * variance.asDiagonal() * m.transpose();
    } else {
        covariance = inverse * (dof > 0 ? chi2 / dof : 0.0);
    }
    LineFit fit;
    fit.intercept = c(0);
    fit.slope = c(1);
    fit.intercept_standard_error = std::sqrt(covariance(0, 0));
    fit.slope_standard_error = std::sqrt(covariance(1, 1));
    fit.weighted = weighted;
    return fit;
}

}  // namespace collide::validation
