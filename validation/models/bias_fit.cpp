#include "validation/models/bias_fit.h"

#include <cmath>
#include <map>
#include <optional>
#include <utility>

#include "validation/models/statistics_bias_model.h"

namespace collide::validation {
namespace {

struct Sums {
    double dk = 0, kk = 0;
    std::vector<double> d, k, s;
};

void add(Sums& sums, const StatisticalDifference& x, double model) {
    const double combined = std::hypot(x.standard_error, x.reference_standard_error);
    if (std::isnan(x.predicted) || !(combined > 0) || model == 0) return;
    const double d = x.mean - x.reference, k = x.predicted / model;
    sums.dk += d * k / (combined * combined);
    sums.kk += k * k / (combined * combined);
    sums.d.push_back(d);
    sums.k.push_back(k);
    sums.s.push_back(combined);
}

double chi2(const Sums& sums, double c) {
    double out = 0;
    for (std::size_t i = 0; i < sums.d.size(); ++i) out += std::pow((sums.d[i] - c * sums.k[i]) / sums.s[i], 2);
    return out;
}

}  // namespace

std::vector<BiasConstantFit> fit_bias_constants(const std::vector<WorkPrecisionLine>& lines) {
    const StatisticsBiasConstants& model = fitted_statistics_bias();
    std::map<std::pair<std::string, std::string>, Sums> sums;
    std::vector<std::pair<std::string, std::string>> order;
    auto at = [&](const std::string& backend, const std::string& observable) -> Sums& {
        const auto key = std::make_pair(backend, observable);
        if (!sums.count(key)) order.push_back(key);
        return sums[key];
    };
    for (const auto& line : lines)
        for (const auto& p : line.points) {
            if (p.pressure) add(at(line.backend, "pressure"), *p.pressure, model.pressure);
            if (p.collision_rate) add(at(line.backend, "collision_rate"), *p.collision_rate, model.rate);
        }
    std::vector<BiasConstantFit> out;
    for (const auto& key : order) {
        const Sums& s = sums[key];
        if (s.d.size() < 2 || !(s.kk > 0)) continue;
        BiasConstantFit f;
        f.backend = key.first;
        f.observable = key.second;
        const bool pressure = key.second == "pressure";
        f.model = pressure ? model.pressure : model.rate;
        f.model_uncertainty = pressure ? model.pressure_uncertainty : model.rate_uncertainty;
        f.constant = s.dk / s.kk;
        f.standard_error = 1 / std::sqrt(s.kk);
        f.chi2 = chi2(s, f.constant);
        f.chi2_model = chi2(s, f.model);
        f.points = s.d.size();
        out.push_back(f);
    }
    return out;
}

}  // namespace collide::validation
