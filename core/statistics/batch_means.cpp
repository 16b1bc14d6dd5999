#include "core/statistics/batch_means.h"

#include <algorithm>
#include <cmath>

namespace collide {
namespace {

double mean_of(const double* x, std::size_t n) {
    double s = 0;
    for (std::size_t i = 0; i < n; ++i) s += x[i];
    return n ? s / double(n) : 0;
}

double tau_int(const double* x, std::size_t n) {
    if (n < 2) return 0;
    const double m = mean_of(x, n);
    double c0 = 0;
    for (std::size_t i = 0; i < n; ++i) c0 += (x[i] - m) * (x[i] - m);
    if (c0 <= 0) return 0.5;
    double tau = 0.5;
    for (std::size_t k = 1; k < n / 2; ++k) {
        double ck = 0;
        for (std::size_t i = 0; i + k < n; ++i) ck += (x[i] - m) * (x[i + k] - m);
        tau += ck / c0;
        if (double(k) >= 5 * tau) break;  // Sokal's window: M >= 5 tau_int
    }
    return std::max(tau, 0.5);
}

// The first candidate with the most effective samples (Chodera 2016).
std::size_t chosen_cut(const std::vector<CutCandidate>& candidates) {
    std::size_t best = 0;
    double best_effective = -1;
    for (const CutCandidate& c : candidates)
        if (c.effective_samples > best_effective) best_effective = c.effective_samples, best = c.cut;
    return best;
}

}  // namespace

std::vector<CutCandidate> equilibration_candidates(const std::vector<double>& x) {
    const std::size_t n = x.size(), step = std::max<std::size_t>(1, n / 20);
    std::vector<CutCandidate> candidates;
    for (std::size_t t0 = 0; t0 <= n / 2 && t0 < n; t0 += step) {
        const double g = 2 * tau_int(x.data() + t0, n - t0);
        candidates.push_back({t0, double(n - t0) / std::max(g, 1.0)});
    }
    return candidates;
}

double integrated_autocorrelation_time(const std::vector<double>& x) { return tau_int(x.data(), x.size()); }

SeriesEstimate estimate_stationary_mean(const std::vector<double>& x, bool cut_from_data, std::size_t batches) {
    SeriesEstimate e;
    if (x.empty()) return e;
    if (cut_from_data) e.candidates = equilibration_candidates(x);
    e.equilibration_cut = chosen_cut(e.candidates);
    const double* y = x.data() + e.equilibration_cut;
    e.used = x.size() - e.equilibration_cut;
    e.mean = mean_of(y, e.used);
    e.autocorrelation_time = tau_int(y, e.used);
    e.batches = std::min(batches, e.used);
    if (e.batches < 2) return e.error = std::nan(""), e;
    const std::size_t length = e.used / e.batches;  // a remainder at the end is left out of the batches
    double s = 0, s2 = 0;
    for (std::size_t b = 0; b < e.batches; ++b) {
        const double m = mean_of(y + b * length, length);
        s += m, s2 += m * m;
    }
    const double bm = s / double(e.batches);
    const double variance = std::max(0.0, (s2 - double(e.batches) * bm * bm) / double(e.batches - 1));
    e.error = std::sqrt(variance / double(e.batches));
    return e;
}

}  // namespace collide
