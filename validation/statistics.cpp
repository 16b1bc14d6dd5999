#include "statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collide::validation {

MeanAndError mean_and_error(const std::vector<double>& samples) {
    MeanAndError r;
    r.count = samples.size();
    if (samples.empty()) return r;
    double sum = 0;
    for (double s : samples) sum += s;
    r.mean = sum / double(r.count);
    if (r.count < 2) return r;
    double squares = 0;
    for (double s : samples) squares += (s - r.mean) * (s - r.mean);
    r.standard_error = std::sqrt(squares / double(r.count - 1) / double(r.count));
    return r;
}

double z_score(const MeanAndError& a, const MeanAndError& b) {
    const double difference = std::fabs(a.mean - b.mean);
    const double error = std::hypot(a.standard_error, b.standard_error);
    if (difference == 0) return 0;
    return error > 0 ? difference / error : std::numeric_limits<double>::infinity();
}

namespace {
// Q_KS(lambda) = 2 sum_{j>=1} (-1)^{j-1} exp(-2 j^2 lambda^2), the Kolmogorov distribution's tail.
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
                                   std::size_t min_points) {
    std::vector<double> lx, ly;
    for (std::size_t k = 0; k < std::min(x.size(), y.size()); ++k)
        if (x[k] > 0 && y[k] > 0 && std::isfinite(x[k]) && std::isfinite(y[k])) {
            lx.push_back(std::log(x[k]));
            ly.push_back(std::log(y[k]));
        }
    if (lx.size() < std::max<std::size_t>(2, min_points)) return std::nullopt;
    const double n = double(lx.size());
    double mx = 0, my = 0;
    for (std::size_t k = 0; k < lx.size(); ++k) mx += lx[k] / n, my += ly[k] / n;
    double sxx = 0, sxy = 0;
    for (std::size_t k = 0; k < lx.size(); ++k) {
        sxx += (lx[k] - mx) * (lx[k] - mx);
        sxy += (lx[k] - mx) * (ly[k] - my);
    }
    if (sxx == 0) return std::nullopt;
    LineFit fit;
    fit.slope = sxy / sxx;
    fit.intercept = my - fit.slope * mx;
    return fit;
}

}  // namespace collide::validation
